#include "support/adjoint_check.hpp"
#include <vector>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include "a30_vector_adjoint.hpp"
#include "a30_vector_tangent.hpp"
DPGEN_KERNEL void a30_vector(DPGEN_IN const std::vector<double>& u, DPGEN_OUT std::vector<double>& o);
TEST_CASE("adversary: a30_vector") {
  for (int n : {0, 1, 2, 3, 4, 7}) {
    CAPTURE(n);
    auto V = [&](const double* p) { return std::vector<double>(p, p + n); };
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { auto u = V(in[0]); auto o = V(out[0]); a30_vector(u, o); std::copy(o.begin(), o.end(), out[0]); };
    p.adjoint = [&](auto in, auto adj, auto seed) { auto u = V(in[0]); auto ua = V(adj[0]); auto s = V(seed[0]);
      a30_vector_adjoint(u, ua, s); std::copy(ua.begin(), ua.end(), adj[0]); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { auto u = V(in[0]); auto d = V(dir[0]); auto o = V(out[0]); auto od = V(outd[0]);
      a30_vector_tangent(u, d, o, od); std::copy(o.begin(), o.end(), out[0]); std::copy(od.begin(), od.end(), outd[0]); };
    dpgen_test::check_adjoint(p);
  }
  std::vector<double> u(5, 1.0), ua(4, 0.0), s(5, 1.0);
  CHECK_THROWS_AS(a30_vector_adjoint(u, ua, s), std::invalid_argument);
}
