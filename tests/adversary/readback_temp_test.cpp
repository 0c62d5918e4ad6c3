// readback_temp (tests/adversary/): see readback_temp.cpp; sizes n in {0, 1, 2, 3, 8}.
#include "adv.hpp"
#include "readback_temp_adjoint.hpp"
#include "readback_temp_tangent.hpp"
void readback_temp(const double*, double*, int n);
TEST_CASE("adversary: readback_temp") {
  for (int n : {0, 1, 2, 3, 8}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { readback_temp(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { readback_temp_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { readback_temp_tangent(in[0], dir[0], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      readback_temp_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
