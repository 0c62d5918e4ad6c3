// r3_vector_inout (tests/adversary/): DPGEN_INOUT vector u as (old u in, new u out); sizes n in {0,1,2,3,6}.
// Assumed signatures: _adjoint(u, u_adj, c, c_adj), _tangent(u, u_dot, c, c_dot), as for pointers.
#include "adv.hpp"
#include "r3_vector_inout_adjoint.hpp"
#include "r3_vector_inout_tangent.hpp"
#include <algorithm>
void r3_vector_inout(std::vector<double>& u, const std::vector<double>& c);
TEST_CASE("adversary: r3_vector_inout") {
  for (int n : {0, 1, 2, 3, 6}) {
    CAPTURE(n);
    auto V = [&](const double* p) { return std::vector<double>(p, p + n); };
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n), size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { auto u = V(in[0]); r3_vector_inout(u, V(in[1])); std::copy(u.begin(), u.end(), out[0]); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      auto t = V(seed[0]); auto ca = V(adj[1]);
      r3_vector_inout_adjoint(V(in[0]), t, V(in[1]), ca);
      for (int i = 0; i < n; ++i) adj[0][i] += t[i];
      std::copy(ca.begin(), ca.end(), adj[1]);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto od) {
      auto u = V(in[0]); auto d = V(dir[0]);
      r3_vector_inout_tangent(u, d, V(in[1]), V(dir[1]));
      std::copy(u.begin(), u.end(), out[0]); std::copy(d.begin(), d.end(), od[0]);
    };
    dpgen_test::check_adjoint(p);
  }
}
