#include "support/adjoint_check.hpp"
#include "styles/styles_support.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include "r4_acc_one_arm_only_adjoint.hpp"
#include "r4_acc_one_arm_only_tangent.hpp"

DPGEN_KERNEL void r4_acc_one_arm_only(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, int flag);
TEST_CASE("adversary: r4_acc_one_arm_only") {
  for (int flag : {0, 1, 2, -1}) for (int n : {0, 1, 2, 3, 7}) {
    CAPTURE(flag);
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(1)};
    p.forward = [&](auto in, auto out) { r4_acc_one_arm_only(in[0], out[0], n, flag); };
    p.adjoint = [&](auto in, auto adj, auto seed) { r4_acc_one_arm_only_adjoint(in[0], adj[0], seed[0], n, flag); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { r4_acc_one_arm_only_tangent(in[0], dir[0], out[0], outd[0], n, flag); };
    dpgen_test::check_adjoint(p);
  }
}
