// acc_then_init (tests/adversary/): `+=` into an output in one nest, then `=`
// to every other element in a later nest (m <= (n+1)/2): the `=` replaces the
// accumulated value.
#include "adv.hpp"
#include "acc_then_init_adjoint.hpp"
#include "acc_then_init_tangent.hpp"
void acc_then_init(const double* a, double* out, int n, int m);
TEST_CASE("adversary: acc_then_init") {
  for (auto [n, m] : {std::pair{0, 0}, {1, 0}, {1, 1}, {2, 1}, {3, 2}, {6, 3}, {7, 2}}) {
    CAPTURE(n); CAPTURE(m);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { acc_then_init(in[0], out[0], n, m); };
    p.adjoint = [&](auto in, auto adj, auto seed) { acc_then_init_adjoint(in[0], adj[0], seed[0], n, m); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { acc_then_init_tangent(in[0], dir[0], out[0], od[0], n, m); };
    dpgen_test::check_adjoint(p);
  }
}
