// read_before_store (tests/adversary/): see read_before_store.cpp; sizes n in {0, 1, 2, 5}.
#include "adv.hpp"
#include "read_before_store_adjoint.hpp"
#include "read_before_store_tangent.hpp"
void read_before_store(const double*, double*, double*, int n);
TEST_CASE("adversary: read_before_store") {
  for (int n : {0, 1, 2, 5}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n),ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { read_before_store(in[0], out[0], out[1], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { read_before_store_adjoint(in[0], adj[0], seed[0], seed[1], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { read_before_store_tangent(in[0], dir[0], out[0], od[0], out[1], od[1], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      read_before_store_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], seed[1], out_n[1], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
