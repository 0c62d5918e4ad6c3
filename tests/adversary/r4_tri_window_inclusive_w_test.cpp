#include "support/adjoint_check.hpp"
#include "styles/styles_support.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#include "r4_tri_window_inclusive_w_adjoint.hpp"
#include "r4_tri_window_inclusive_w_tangent.hpp"

DPGEN_KERNEL void r4_tri_window_inclusive_w(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, int w);
TEST_CASE("adversary: r4_tri_window_inclusive_w") {
  for (int w : {0, 1, 2, 5}) for (int n : {0, 1, 2, 3, 7}) {
    CAPTURE(w);
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { r4_tri_window_inclusive_w(in[0], out[0], n, w); };
    p.adjoint = [&](auto in, auto adj, auto seed) { r4_tri_window_inclusive_w_adjoint(in[0], adj[0], seed[0], n, w); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { r4_tri_window_inclusive_w_tangent(in[0], dir[0], out[0], outd[0], n, w); };
    dpgen_test::check_adjoint(p);
  }
}
