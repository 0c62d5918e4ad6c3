// Row pointers as C89 codes write them: declared with no value before the loops (or `= NULL`)
// and pointed at the rows of each iteration at the top of its loop body, before they are used.
// dpgen binds each assignment as it would a declaration made there; a pointer that would carry
// a row from one iteration into the next, or one assigned in an arm, is refused
// (tests/diagnostics/c89_row_pointers.cpp).
#include "dpgen/annotate.hpp"

#include <cstddef>

// 5-point Laplacian of the interior, rows above and below named per row.
DPGEN_KERNEL void laplace2d_c89_rows(DPGEN_IN const double* u, DPGEN_OUT double* lap, int nx,
                                     int ny, double inv_h2) {
  int i, j;
  const double *up, *mid, *dn;
  double* out = NULL;
  for (j = 1; j < ny - 1; j++) {
    dn = u + (j - 1) * nx;
    mid = u + j * nx;
    up = u + (j + 1) * nx;
    out = lap + j * nx;
    for (i = 1; i < nx - 1; i++)
      out[i] = (mid[i - 1] + mid[i + 1] + dn[i] + up[i] - 4.0 * mid[i]) * inv_h2;
  }
}

// A 3D product stencil: a plane pointer per k, row pointers per j taken from it.
DPGEN_KERNEL void advect3d_c89_planes(DPGEN_IN const double* q, DPGEN_IN const double* w,
                                      DPGEN_OUT double* flux, int nx, int ny, int nz) {
  int i, j, k;
  const double* plane;
  const double* row;
  const double* wrow;
  double* frow;
  for (k = 1; k < nz; k++) {
    plane = q + k * nx * ny;
    for (j = 0; j < ny; j++) {
      row = plane + j * nx;
      wrow = &w[(k * ny + j) * nx];
      frow = flux + (k * ny + j) * nx;
      for (i = 0; i < nx; i++)
        frow[i] = wrow[i] * (wrow[i] > 0.0 ? row[i - nx * ny] : row[i]);
    }
  }
}

// A helper with a C89 row pointer of its own, called from two loops.
static double row_triple(const double* a, int j, int nx, int i) {
  const double* r;
  r = a + j * nx;
  return r[i - 1] * r[i] + r[i + 1];
}

DPGEN_KERNEL void two_rows_helper(DPGEN_IN const double* a, DPGEN_OUT double* top,
                                  DPGEN_OUT double* bottom, int nx, int ny) {
  for (int i = 1; i < nx - 1; i++)
    top[i] = row_triple(a, ny - 1, nx, i);
  for (int i = 1; i < nx - 1; i++)
    bottom[i] = row_triple(a, 0, nx, i);
}

// One pointer pointed at two arrays in turn within a row.
DPGEN_KERNEL void mix_rows_repointed(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                     DPGEN_OUT double* out, DPGEN_OUT double* out2, int nx,
                                     int ny) {
  const double* src;
  for (int j = 0; j < ny; j++) {
    src = a + j * nx;
    for (int i = 0; i < nx; i++)
      out[j * nx + i] = 2.0 * src[i];
    src = b + j * nx;
    for (int i = 0; i < nx; i++)
      out2[j * nx + i] = src[i] * src[i] - src[i];
  }
}
