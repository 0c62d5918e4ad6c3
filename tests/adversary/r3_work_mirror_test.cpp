// r3_work_mirror (tests/adversary/): see r3_work_mirror.cpp; sizes n in {0,1,2,3,6}.
#include "adv.hpp"
#include "r3_work_mirror_adjoint.hpp"
#include "r3_work_mirror_tangent.hpp"
void r3_work_mirror(const double*, double*, double*, unsigned n);
TEST_CASE("adversary: r3_work_mirror") {
  for (unsigned n : {0,1,2,3,6}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n),ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { r3_work_mirror(in[0], out[0], out[1], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { r3_work_mirror_adjoint(in[0], adj[0], seed[0], seed[1], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { r3_work_mirror_tangent(in[0], dir[0], out[0], od[0], out[1], od[1], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      r3_work_mirror_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], seed[1], out_n[1], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
