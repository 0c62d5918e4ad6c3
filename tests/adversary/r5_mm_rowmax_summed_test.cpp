#include "support/adjoint_check.hpp"
#include "styles/styles_support.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#include "r5_mm_rowmax_summed_adjoint.hpp"
#include "r5_mm_rowmax_summed_tangent.hpp"

DPGEN_KERNEL void r5_mm_rowmax_summed(DPGEN_IN const double* a, DPGEN_OUT double* out, int nx, int ny);
TEST_CASE("adversary: r5_mm_rowmax_summed") {
  for (auto [n, m] : {std::pair{0, 0}, {1, 1}, {1, 3}, {3, 1}, {2, 2}, {4, 3}, {5, 6}}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n*m)};
    p.out_sizes = {size_t(1)};
    p.forward = [&](auto in, auto out) { r5_mm_rowmax_summed(in[0], out[0], n, m); };
    p.adjoint = [&](auto in, auto adj, auto seed) { r5_mm_rowmax_summed_adjoint(in[0], adj[0], seed[0], n, m); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { r5_mm_rowmax_summed_tangent(in[0], dir[0], out[0], outd[0], n, m); };
    dpgen_test::check_adjoint(p);
  }
}
