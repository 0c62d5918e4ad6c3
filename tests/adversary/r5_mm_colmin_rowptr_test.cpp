#include "support/adjoint_check.hpp"
#include "styles/styles_support.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#include "r5_mm_colmin_rowptr_adjoint.hpp"
#include "r5_mm_colmin_rowptr_tangent.hpp"

DPGEN_KERNEL void r5_mm_colmin_rowptr(DPGEN_IN double** a, DPGEN_OUT double* colmin, int nx, int ny);
TEST_CASE("adversary: r5_mm_colmin_rowptr") {
  for (auto [n, m] : {std::pair{1, 1}, {1, 3}, {3, 1}, {2, 2}, {4, 3}, {5, 6}}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(m) * size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { auto ri0 = styles::rows(in[0], size_t(m), size_t(n)); r5_mm_colmin_rowptr(ri0.data(), out[0], n, m); };
    p.adjoint = [&](auto in, auto adj, auto seed) { auto ri0 = styles::rows(in[0], size_t(m), size_t(n)); auto ai0 = styles::rows(adj[0], size_t(m), size_t(n)); r5_mm_colmin_rowptr_adjoint(ri0.data(), ai0.data(), seed[0], n, m); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { auto ri0 = styles::rows(in[0], size_t(m), size_t(n)); auto di0 = styles::rows(dir[0], size_t(m), size_t(n)); r5_mm_colmin_rowptr_tangent(ri0.data(), di0.data(), out[0], outd[0], n, m); };
    dpgen_test::check_adjoint(p);
  }
}
