#include "support/adjoint_check.hpp"
#include "styles/styles_support.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include "r4_acc_float_pure_adjoint.hpp"
#include "r4_acc_float_pure_tangent.hpp"

DPGEN_KERNEL void r4_acc_float_pure(DPGEN_IN const float* a, DPGEN_IN const float* b, DPGEN_OUT float* out, int n);
TEST_CASE("adversary: r4_acc_float_pure") {
  for (int n : {0, 1, 2, 3, 4, 7, 16}) {
    CAPTURE(n);
    dpgen_test::Problem<float> p;
    p.in_sizes = {size_t(n), size_t(n)};
    p.out_sizes = {size_t(1)};
    p.forward = [&](auto in, auto out) { r4_acc_float_pure(in[0], in[1], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { r4_acc_float_pure_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { r4_acc_float_pure_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], n); };
    dpgen_test::check_adjoint(p);
  }
}
