// half_local (tests/adversary/): see half_local.cpp; sizes n in {0, 1, 2, 3, 7}.
#include "adv.hpp"
#include "half_local_adjoint.hpp"
#include "half_local_tangent.hpp"
void half_local(const double*, double*, int n);
TEST_CASE("adversary: half_local") {
  for (int n : {0, 1, 2, 3, 7}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { half_local(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { half_local_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { half_local_tangent(in[0], dir[0], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      half_local_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
