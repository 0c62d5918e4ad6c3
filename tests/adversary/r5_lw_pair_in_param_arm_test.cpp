#include "support/adjoint_check.hpp"
#include "styles/styles_support.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#include "r5_lw_pair_in_param_arm_adjoint.hpp"
#include "r5_lw_pair_in_param_arm_tangent.hpp"

DPGEN_KERNEL void r5_lw_pair_in_param_arm(DPGEN_IN const double* a, DPGEN_OUT double* K, int n, int flag);
TEST_CASE("adversary: r5_lw_pair_in_param_arm") {
  for (int flag : {0, 1}) for (int n : {0, 1, 2, 3, 7}) {
    CAPTURE(flag);
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n + 1)};
    p.forward = [&](auto in, auto out) { r5_lw_pair_in_param_arm(in[0], out[0], n, flag); };
    p.adjoint = [&](auto in, auto adj, auto seed) { r5_lw_pair_in_param_arm_adjoint(in[0], adj[0], seed[0], n, flag); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { r5_lw_pair_in_param_arm_tangent(in[0], dir[0], out[0], outd[0], n, flag); };
    dpgen_test::check_adjoint(p);
  }
}
