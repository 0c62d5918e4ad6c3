#include "support/adjoint_check.hpp"
#include "styles/styles_support.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#include "r5_pin_strided_last_maybe_missing_adjoint.hpp"
#include "r5_pin_strided_last_maybe_missing_tangent.hpp"

DPGEN_KERNEL void r5_pin_strided_last_maybe_missing(DPGEN_IN const double* a, DPGEN_OUT double* u, DPGEN_OUT double* last, int n);
TEST_CASE("adversary: r5_pin_strided_last_maybe_missing") {
  for (int n : {0, 1, 2, 3, 4, 5, 8, 9}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n), size_t(1)};
    p.forward = [&](auto in, auto out) { r5_pin_strided_last_maybe_missing(in[0], out[0], out[1], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { r5_pin_strided_last_maybe_missing_adjoint(in[0], adj[0], seed[0], seed[1], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { r5_pin_strided_last_maybe_missing_tangent(in[0], dir[0], out[0], outd[0], out[1], outd[1], n); };
    dpgen_test::check_adjoint(p);
  }
}
