// r3_vector_rev (tests/adversary/): std::vector parameters; sizes n in {0,1,2,3,6}.
#include "adv.hpp"
#include "r3_vector_rev_adjoint.hpp"
#include "r3_vector_rev_tangent.hpp"
#include <algorithm>
void r3_vector_rev(const std::vector<double>& u, std::vector<double>& o);
TEST_CASE("adversary: r3_vector_rev") {
  for (int n : {0,1,2,3,6}) {
    CAPTURE(n);
    auto V = [&](const double* p) { return std::vector<double>(p, p + n); };
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { auto u = V(in[0]); auto o = V(out[0]); r3_vector_rev(u, o); std::copy(o.begin(), o.end(), out[0]); };
    p.adjoint = [&](auto in, auto adj, auto seed) { auto u = V(in[0]); auto ua = V(adj[0]); auto s = V(seed[0]); r3_vector_rev_adjoint(u, ua, s); std::copy(ua.begin(), ua.end(), adj[0]); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { auto u = V(in[0]); auto d = V(dir[0]); auto o = V(out[0]); auto od = V(outd[0]); r3_vector_rev_tangent(u, d, o, od); std::copy(o.begin(), o.end(), out[0]); std::copy(od.begin(), od.end(), outd[0]); };
    dpgen_test::check_adjoint(p);
  }
}
