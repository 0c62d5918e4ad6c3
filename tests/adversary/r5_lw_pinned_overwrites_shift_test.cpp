#include "support/adjoint_check.hpp"
#include "styles/styles_support.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#include "r5_lw_pinned_overwrites_shift_adjoint.hpp"
#include "r5_lw_pinned_overwrites_shift_tangent.hpp"

DPGEN_KERNEL void r5_lw_pinned_overwrites_shift(DPGEN_IN const double* a, DPGEN_OUT double* K, int n);
TEST_CASE("adversary: r5_lw_pinned_overwrites_shift") {
  for (int n : {0, 1, 2, 3, 4, 7, 16}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n + 1)};
    p.forward = [&](auto in, auto out) { r5_lw_pinned_overwrites_shift(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { r5_lw_pinned_overwrites_shift_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { r5_lw_pinned_overwrites_shift_tangent(in[0], dir[0], out[0], outd[0], n); };
    dpgen_test::check_adjoint(p);
  }
}
