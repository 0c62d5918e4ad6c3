// loop_local_bounds (tests/styles/): an inner loop whose bound is an integer local made
// inside an outer loop, in the ways users write one: a `const int` row width in the row
// loop, a C89 local assigned in the loop body, a library-style ParallelFor called in a loop
// (its `int n` parameter bound to the caller's width) or inside another ParallelFor, a
// helper with its own row loop, a lambda that owns the row loop, and a 3D nest with a plane
// and a row width per level. The generated adjoints compiled before, but the parallel
// forwards and tangents evaluate bounds before the nest (the parallel loop's size test, the
// loop headers), where the local was not defined: they did not compile ("'m' was not
// declared in this scope").
#include "dpgen/annotate.hpp"

#include <cmath>
#include <cstddef>

// A library's parallel-for, the way AMReX- or Kokkos-like codes call one.
template <class F> void ParallelFor(int n, F&& f) {
  for (int i = 0; i < n; ++i)
    f(i);
}

// The row width as a const local of the row loop.
DPGEN_KERNEL void row_width_local(DPGEN_IN const double* a, DPGEN_OUT double* b, int nx, int ny) {
  for (int j = 0; j < ny; ++j) {
    const int m = nx;
    for (int i = 0; i < m; ++i)
      b[j * nx + i] = std::sin(a[j * nx + i]) * a[j * nx + i];
  }
}

// C89: every local declared first, the interior's last index assigned in the row loop.
DPGEN_KERNEL void c89_interior(DPGEN_IN const double* a, DPGEN_OUT double* b, int nx, int ny) {
  int i, j, last;
  for (j = 0; j < ny; j++) {
    last = nx - 1;
    b[j * nx] = a[j * nx];
    for (i = 1; i < last; i++)
      b[j * nx + i] =
          0.25 * a[j * nx + i - 1] + 0.5 * a[j * nx + i] * a[j * nx + i] + 0.25 * a[j * nx + i + 1];
    b[j * nx + last] = a[j * nx + last];
  }
}

// A ParallelFor over a row, called in the row loop.
DPGEN_KERNEL void pfor_in_loop(DPGEN_IN const double* a, DPGEN_OUT double* b, int nx, int ny) {
  for (int j = 0; j < ny; ++j)
    ParallelFor(nx, [&](int i) { b[j * nx + i] = std::exp(-a[j * nx + i] * a[j * nx + i]); });
}

// ParallelFor inside ParallelFor, the inner one reading the transposed element too.
DPGEN_KERNEL void pfor_nested(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  ParallelFor(n, [&](int j) {
    ParallelFor(n, [&](int i) { b[j * n + i] = std::sin(a[j * n + i]) * a[i * n + j]; });
  });
}

namespace {
// A helper with its own loop over one row of width n (boundary cells copied).
void smooth_row(const double* a, double* b, int j, int n) {
  b[j * n] = a[j * n];
  for (int i = 1; i < n - 1; ++i)
    b[j * n + i] =
        (a[j * n + i - 1] + 2.0 * a[j * n + i] + a[j * n + i + 1]) * 0.25 * std::cos(a[j * n + i]);
  b[j * n + n - 1] = a[j * n + n - 1];
}
} // namespace

DPGEN_KERNEL void helper_row_loop(DPGEN_IN const double* a, DPGEN_OUT double* b, int nx, int ny) {
  for (int j = 0; j < ny; ++j)
    smooth_row(a, b, j, nx);
}

// A lambda that owns the row loop, its interior bounds locals of the lambda.
DPGEN_KERNEL void lambda_row_loop(DPGEN_IN const double* a, DPGEN_OUT double* b, int nx, int ny) {
  auto row = [&](int j) {
    const int first = 1, last = nx - 1;
    for (int i = 0; i < first; ++i)
      b[j * nx + i] = a[j * nx + i];
    for (int i = first; i < last; ++i)
      b[j * nx + i] = a[j * nx + i] * (a[j * nx + i + 1] - a[j * nx + i - 1]);
    for (int i = last; i < nx; ++i)
      b[j * nx + i] = a[j * nx + i];
  };
  for (int j = 0; j < ny; ++j)
    row(j);
}

// 3D: the plane size and the row width named at their levels.
DPGEN_KERNEL void planes_3d(DPGEN_IN const double* a, DPGEN_OUT double* b, int nx, int ny, int nz) {
  for (int k = 0; k < nz; ++k) {
    const std::ptrdiff_t plane = std::ptrdiff_t(nx) * ny;
    const int rows = ny;
    for (int j = 0; j < rows; ++j) {
      const int width = nx;
      for (int i = 0; i < width; ++i) {
        const std::ptrdiff_t c = k * plane + std::ptrdiff_t(j) * width + i;
        b[c] = a[c] * std::tanh(a[c]);
      }
    }
  }
}

// The row width read once from the data (a count stored beside the grid, clamped to the
// grid), named again in the row loop: the bound is the kernel-level local.
DPGEN_KERNEL void width_from_data(DPGEN_IN const double* a, DPGEN_OUT double* b, const int* width,
                                  int nx, int ny) {
  const int w = width[0] < nx ? width[0] : nx;
  for (int j = 0; j < ny; ++j) {
    const int m = w;
    for (int i = 0; i < m; ++i)
      b[j * nx + i] = a[j * nx + i] * std::cos(a[j * nx + i]);
  }
}
