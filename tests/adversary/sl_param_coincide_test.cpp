// sl_param_coincide (tests/adversary/): two straight-line stores, out[0] and
// out[m]; m == 0 makes the second replace the first.
#include "adv.hpp"
#include "sl_param_coincide_adjoint.hpp"
#include "sl_param_coincide_tangent.hpp"
void sl_param_coincide(const double* a, double* out, int n, int m);
TEST_CASE("adversary: sl_param_coincide") {
  for (int m : {0, 1, 3}) {
    CAPTURE(m);
    dpgen_test::Problem<double> p;
    p.in_sizes = {2};
    p.out_sizes = {ADV_SZ(m + 1)};
    p.forward = [&](auto in, auto out) { sl_param_coincide(in[0], out[0], 5, m); };
    p.adjoint = [&](auto in, auto adj, auto seed) { sl_param_coincide_adjoint(in[0], adj[0], seed[0], 5, m); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { sl_param_coincide_tangent(in[0], dir[0], out[0], od[0], 5, m); };
    dpgen_test::check_adjoint(p);
  }
}
