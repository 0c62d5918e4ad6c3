#include "support/adjoint_check.hpp"
#include "styles/styles_support.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#define IDX(i, j) ((j) * nx + (i))
#include "r5_ip_rowmax_per_row_adjoint.hpp"
#include "r5_ip_rowmax_per_row_tangent.hpp"

DPGEN_KERNEL void r5_ip_rowmax_per_row(DPGEN_INOUT double* u, int nx, int ny);
TEST_CASE("adversary: r5_ip_rowmax_per_row") {
  for (auto [n, m] : {std::pair{0, 0}, {1, 1}, {1, 3}, {3, 1}, {2, 2}, {4, 3}, {5, 6}}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n*m)};
    p.out_sizes = {size_t(n*m)};
    p.forward = [&](auto in, auto out) { std::copy(in[0], in[0] + size_t(n*m), out[0]); r5_ip_rowmax_per_row(out[0], n, m); };
    p.adjoint = [&](auto in, auto adj, auto seed) { std::vector<double> t0(seed[0], seed[0] + size_t(n*m)); r5_ip_rowmax_per_row_adjoint(in[0], t0.data(), n, m); for (size_t z = 0; z < t0.size(); ++z) adj[0][z] += t0[z]; };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { std::copy(in[0], in[0] + size_t(n*m), out[0]); std::copy(dir[0], dir[0] + size_t(n*m), outd[0]); r5_ip_rowmax_per_row_tangent(out[0], outd[0], n, m); };
    dpgen_test::check_adjoint(p);
  }
}
