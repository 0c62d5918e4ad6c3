// modify_size_param (tests/adversary/): the kernel assigns its size and
// coefficient parameters before the loop.
#include "adv.hpp"
#include "modify_size_param_adjoint.hpp"
#include "modify_size_param_tangent.hpp"
void modify_size_param(const double* a, double* out, int n, double dt);
TEST_CASE("adversary: modify_size_param") {
  for (int n : {1, 2, 5}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { modify_size_param(in[0], out[0], n, 0.3); };
    p.adjoint = [&](auto in, auto adj, auto seed) { modify_size_param_adjoint(in[0], adj[0], seed[0], n, 0.3); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { modify_size_param_tangent(in[0], dir[0], out[0], od[0], n, 0.3); };
    dpgen_test::check_adjoint(p);
  }
}
