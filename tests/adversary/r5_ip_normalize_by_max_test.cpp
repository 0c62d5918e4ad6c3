#include "support/adjoint_check.hpp"
#include "styles/styles_support.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#include "r5_ip_normalize_by_max_adjoint.hpp"
#include "r5_ip_normalize_by_max_tangent.hpp"

DPGEN_KERNEL void r5_ip_normalize_by_max(DPGEN_INOUT double* v, int n);
TEST_CASE("adversary: r5_ip_normalize_by_max") {
  for (int n : {0, 1, 2, 3, 4, 7, 16}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { std::copy(in[0], in[0] + size_t(n), out[0]); r5_ip_normalize_by_max(out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { std::vector<double> t0(seed[0], seed[0] + size_t(n)); r5_ip_normalize_by_max_adjoint(in[0], t0.data(), n); for (size_t z = 0; z < t0.size(); ++z) adj[0][z] += t0[z]; };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { std::copy(in[0], in[0] + size_t(n), out[0]); std::copy(dir[0], dir[0] + size_t(n), outd[0]); r5_ip_normalize_by_max_tangent(out[0], outd[0], n); };
    dpgen_test::check_adjoint(p);
  }
}
