// r3_inout_mirror (tests/adversary/): DPGEN_INOUT u as (old u in, new u out); sizes n in {0,1,2,3,6}.
#include "adv.hpp"
#include "r3_inout_mirror_adjoint.hpp"
#include "r3_inout_mirror_tangent.hpp"
#include <algorithm>
void r3_inout_mirror(double* u, const double* c, size_t n, double dt);
TEST_CASE("adversary: r3_inout_mirror") {
  for (size_t n : {0,1,2,3,6}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n), ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { std::copy(in[0], in[0] + n, out[0]); r3_inout_mirror(out[0], in[1], n, 0.7); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      std::vector<double> t(seed[0], seed[0] + n);
      r3_inout_mirror_adjoint(in[0], t.data(), in[1], adj[1], n, 0.7);
      for (size_t i = 0; i < size_t(n); ++i) adj[0][i] += t[i];
    };
    p.tangent = [&](auto in, auto dir, auto out, auto od) {
      std::copy(in[0], in[0] + n, out[0]); std::copy(dir[0], dir[0] + n, od[0]);
      r3_inout_mirror_tangent(out[0], od[0], in[1], dir[1], n, 0.7);
    };
    dpgen_test::check_adjoint(p);
  }
}
