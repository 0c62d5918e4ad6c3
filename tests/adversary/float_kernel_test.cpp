// float_kernel (tests/adversary/): float arrays, double literals.
#include "adv.hpp"
#include "float_kernel_adjoint.hpp"
#include "float_kernel_tangent.hpp"
void float_kernel(const float* a, float* out, int n);
TEST_CASE("adversary: float_kernel") {
  for (int n : {0, 1, 2, 3, 9}) {
    CAPTURE(n);
    dpgen_test::Problem<float> p;
    p.in_sizes = {ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { float_kernel(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { float_kernel_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { float_kernel_tangent(in[0], dir[0], out[0], od[0], n); };
    dpgen_test::check_adjoint(p);
  }
}
