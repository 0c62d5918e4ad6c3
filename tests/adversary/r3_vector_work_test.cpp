// r3_vector_work (tests/adversary/): std::vector parameters; sizes n in {0,1,2,3,6}.
#include "adv.hpp"
#include "r3_vector_work_adjoint.hpp"
#include "r3_vector_work_tangent.hpp"
#include <algorithm>
void r3_vector_work(const std::vector<double>& u, std::vector<double>& w, std::vector<double>& o);
TEST_CASE("adversary: r3_vector_work") {
  for (int n : {0,1,2,3,6}) {
    CAPTURE(n);
    auto V = [&](const double* p) { return std::vector<double>(p, p + n); };
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n), size_t(n)};
    p.forward = [&](auto in, auto out) { auto u = V(in[0]); auto w = V(out[0]); auto o = V(out[1]); r3_vector_work(u, w, o); std::copy(w.begin(), w.end(), out[0]); std::copy(o.begin(), o.end(), out[1]); };
    p.adjoint = [&](auto in, auto adj, auto seed) { auto u = V(in[0]); auto ua = V(adj[0]); auto s0 = V(seed[0]); auto s1 = V(seed[1]); r3_vector_work_adjoint(u, ua, s0, s1); std::copy(ua.begin(), ua.end(), adj[0]); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { auto u = V(in[0]); auto d = V(dir[0]); auto w = V(out[0]); auto wd = V(outd[0]); auto o = V(out[1]); auto od = V(outd[1]); r3_vector_work_tangent(u, d, w, wd, o, od); std::copy(w.begin(), w.end(), out[0]); std::copy(wd.begin(), wd.end(), outd[0]); std::copy(o.begin(), o.end(), out[1]); std::copy(od.begin(), od.end(), outd[1]); };
    dpgen_test::check_adjoint(p);
  }
}
