#include "support/adjoint_check.hpp"
#include "styles/styles_support.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#include "r5_ip_max_ties_adjoint.hpp"
#include "r5_ip_max_ties_tangent.hpp"

DPGEN_KERNEL void r5_ip_max_ties(DPGEN_INOUT double* v, int n);
TEST_CASE("adversary: r5_ip_max_ties") {
  for (int n : {0, 1, 2, 3, 4, 7, 16}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { std::copy(in[0], in[0] + size_t(n), out[0]); r5_ip_max_ties(out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { std::vector<double> t0(seed[0], seed[0] + size_t(n)); r5_ip_max_ties_adjoint(in[0], t0.data(), n); for (size_t z = 0; z < t0.size(); ++z) adj[0][z] += t0[z]; };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { std::copy(in[0], in[0] + size_t(n), out[0]); std::copy(dir[0], dir[0] + size_t(n), outd[0]); r5_ip_max_ties_tangent(out[0], outd[0], n); };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("adversary: r5_ip_max_ties ties") {
  // v = {2, -2, 1}: m = 2 at v0 and v1 (half each, with the sign); seed e_0 on the new v:
  // d v0'/d v0 = 1/3 - 2/9 * 1/2 = 2/9, d v0'/d v1 = -2/9 * (-1/2) = 1/9, d v0'/d v2 = 0
  std::vector<double> v = {2.0, -2.0, 1.0}, va = {1.0, 0.0, 0.0};
  r5_ip_max_ties_adjoint(v.data(), va.data(), 3);
  CHECK(va[0] == doctest::Approx(2.0 / 9));
  CHECK(va[1] == doctest::Approx(1.0 / 9));
  CHECK(va[2] == doctest::Approx(0.0));
  std::vector<double> vt = v, vd = {0.0, 1.0, 0.0};
  r5_ip_max_ties_tangent(vt.data(), vd.data(), 3);
  CHECK(vt[0] == doctest::Approx(2.0 / 3));
  CHECK(vd[0] == doctest::Approx(1.0 / 9));
}
