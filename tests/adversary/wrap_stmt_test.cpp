// wrap_stmt (tests/adversary/): see wrap_stmt.cpp; sizes n in {1, 2, 3, 6}.
#include "adv.hpp"
#include "wrap_stmt_adjoint.hpp"
#include "wrap_stmt_tangent.hpp"
void wrap_stmt(const double*, double*, int n);
TEST_CASE("adversary: wrap_stmt") {
  for (int n : {1, 2, 3, 6}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { wrap_stmt(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { wrap_stmt_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { wrap_stmt_tangent(in[0], dir[0], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      wrap_stmt_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
