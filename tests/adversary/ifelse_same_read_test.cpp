// ifelse_same_read (tests/adversary/): see ifelse_same_read.cpp; sizes n in {1, 2, 3, 8}.
#include "adv.hpp"
#include "ifelse_same_read_adjoint.hpp"
#include "ifelse_same_read_tangent.hpp"
void ifelse_same_read(const double*, const double*, double*, int n);
TEST_CASE("adversary: ifelse_same_read") {
  for (int n : {1, 2, 3, 8}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n),ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { ifelse_same_read(in[0], in[1], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { ifelse_same_read_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { ifelse_same_read_tangent(in[0], dir[0], in[1], dir[1], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      ifelse_same_read_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
