#include "adv.hpp"
#include "readback_square_adjoint.hpp"
#include "readback_square_tangent.hpp"
void readback_square(const double* a, const double* b, double* out, int n);
TEST_CASE("adversary: readback_square") {
  for (int n : {0, 1, 2, 3, 4, 9}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n), ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { readback_square(in[0], in[1], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { readback_square_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { readback_square_tangent(in[0], dir[0], in[1], dir[1], out[0], od[0], n); };
    dpgen_test::check_adjoint(p);
  }
}
