#include "adv.hpp"
#include "size_t_plus1_adjoint.hpp"
#include "size_t_plus1_tangent.hpp"
void size_t_plus1(const double* a, double* out, std::size_t n);
TEST_CASE("adversary: size_t_plus1") {
  for (std::size_t n : {0, 1, 2, 3, 4, 9}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {n};
    p.out_sizes = {n};
    p.forward = [&](auto in, auto out) { size_t_plus1(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { size_t_plus1_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { size_t_plus1_tangent(in[0], dir[0], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      size_t_plus1_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
