#include "support/adjoint_check.hpp"
#include "styles/styles_support.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#define IDX3(i, j, k) (((k) * ny + (j)) * nx + (i))
#include "r5_mm_3d_idx_omp_adjoint.hpp"
#include "r5_mm_3d_idx_omp_tangent.hpp"

DPGEN_KERNEL void r5_mm_3d_idx_omp(DPGEN_IN const double* u, DPGEN_OUT double* out, int nx, int ny, int nz);
TEST_CASE("adversary: r5_mm_3d_idx_omp") {
  for (auto [nx, ny, nz] : {std::tuple{1, 1, 1}, {3, 3, 3}, {4, 3, 5}}) {
    const int n = nx * ny * nz; CAPTURE(nx); CAPTURE(ny); CAPTURE(nz);
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(1)};
    p.forward = [&](auto in, auto out) { r5_mm_3d_idx_omp(in[0], out[0], nx, ny, nz); };
    p.adjoint = [&](auto in, auto adj, auto seed) { r5_mm_3d_idx_omp_adjoint(in[0], adj[0], seed[0], nx, ny, nz); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { r5_mm_3d_idx_omp_tangent(in[0], dir[0], out[0], outd[0], nx, ny, nz); };
    dpgen_test::check_adjoint(p);
  }
}
