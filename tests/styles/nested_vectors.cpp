// Rows as `std::vector<std::vector<double>>`, the way prototype and teaching
// codes hold a grid: a nonlinear 5-point stencil between two such grids, a
// sweep whose row count is `u.size()` and whose columns come as a parameter
// into a flat output, a nested input beside a flat one, and rows taken by
// reference (`const auto& up = u[j - 1];`, `auto& out = v[j];`), read and
// written through.
#include "dpgen/annotate.hpp"

#include <cstddef>
#include <vector>

DPGEN_KERNEL void vv_stencil(DPGEN_IN const std::vector<std::vector<double>>& u,
                             DPGEN_OUT std::vector<std::vector<double>>& v, int nx, int ny,
                             double c) {
  for (int j = 1; j < ny - 1; ++j)
    for (int i = 1; i < nx - 1; ++i)
      v[j][i] =
          u[j][i] +
          c * (u[j][i + 1] + u[j][i - 1] + u[j + 1][i] + u[j - 1][i] - 4.0 * u[j][i]) * u[j][i];
}

DPGEN_KERNEL void vv_rows_to_flat(DPGEN_IN const std::vector<std::vector<double>>& u,
                                  DPGEN_OUT double* g, int nx) {
  for (std::size_t j = 0; j < u.size(); ++j)
    for (int i = 1; i < nx; ++i)
      g[j * nx + i] = (u[j][i] - u[j][i - 1]) * (u[j][i] + u[j][i - 1]);
}

DPGEN_KERNEL void vv_weighted(DPGEN_IN const std::vector<std::vector<double>>& u,
                              DPGEN_IN const double* w,
                              DPGEN_OUT std::vector<std::vector<double>>& v, int nx, int ny) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      v[j][i] = w[j * nx + i] * u[j][i] * u[j][i];
}

// The rows around j by const reference, the output's row by reference, written through; a C89
// counter moved after the references are bound does not move them.
DPGEN_KERNEL void vv_row_refs(DPGEN_IN const std::vector<std::vector<double>>& u,
                              DPGEN_OUT std::vector<std::vector<double>>& v, int nx, int ny) {
  int j;
  for (j = 1; j < ny - 1; ++j) {
    const auto& up = u[j - 1];
    const std::vector<double>& here = u[j];
    const auto& down = u[j + 1];
    auto& out = v[j];
    for (int i = 1; i < nx - 1; ++i)
      out[i] = here[i] * (up[i] + down[i] + here[i - 1] + here[i + 1] - 4.0 * here[i]);
  }
}
