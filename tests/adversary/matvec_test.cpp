#include "adv.hpp"
#include "matvec_adjoint.hpp"
#include "matvec_tangent.hpp"
void matvec(const double* A, const double* x, double* y, int n, int m);
TEST_CASE("adversary: matvec") {
  for (auto [n, m] : {std::pair{0, 0}, {1, 1}, {1, 0}, {0, 2}, {2, 1}, {2, 3}, {5, 4}}) {
    CAPTURE(n); CAPTURE(m);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n * m), ADV_SZ(m)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { matvec(in[0], in[1], out[0], n, m); };
    p.adjoint = [&](auto in, auto adj, auto seed) { matvec_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n, m); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { matvec_tangent(in[0], dir[0], in[1], dir[1], out[0], od[0], n, m); };
    dpgen_test::check_adjoint(p);
  }
}
