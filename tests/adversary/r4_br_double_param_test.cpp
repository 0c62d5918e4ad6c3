#include "support/adjoint_check.hpp"
#include "styles/styles_support.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include "r4_br_double_param_adjoint.hpp"
#include "r4_br_double_param_tangent.hpp"

DPGEN_KERNEL void r4_br_double_param(DPGEN_IN const double* a, DPGEN_OUT double* u, int n, double dt);
TEST_CASE("adversary: r4_br_double_param") {
  for (double dt : {0.1, 0.9}) for (int n : {0, 1, 2, 5}) {
    CAPTURE(dt);
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { r4_br_double_param(in[0], out[0], n, dt); };
    p.adjoint = [&](auto in, auto adj, auto seed) { r4_br_double_param_adjoint(in[0], adj[0], seed[0], n, dt); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { r4_br_double_param_tangent(in[0], dir[0], out[0], outd[0], n, dt); };
    dpgen_test::check_adjoint(p);
  }
}
