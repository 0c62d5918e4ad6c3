/* Line buffers as C99 codes write them (issue 20): VLA locals used as line
   buffers (`double flux[nx]` in a row loop, one declared outside every loop,
   one padded with ghosts) and C99 pointers to VLA rows over flat arrays
   (`double (*u)[n][n] = (double (*)[n][n]) u_flat;`, so u[k][j][i] is the
   flat element (k * n + j) * n + i). dpgen parses .c files as C; the
   adjoints are declared extern "C". */
#include "dpgen/annotate.hpp"

#include <math.h>

// A 2D upwind-like sweep through a VLA line buffer of fluxes, `double
// flux[nx]` declared in the row loop: the flux at each face, then the update.
DPGEN_KERNEL void sweep2d_vla(DPGEN_IN const double* q, DPGEN_OUT double* q_new, int nx, int ny,
                              double dt) {
  if (nx < 2)
    return;
  for (int j = 0; j < ny; j++) {
    double flux[nx];
    for (int i = 0; i < nx; i++) {
      const double w = q[j * nx + i];
      flux[i] = 0.5 * w * w; // Burgers' flux
    }
    q_new[j * nx + 0] = q[j * nx + 0];
    for (int i = 1; i < nx; i++)
      q_new[j * nx + i] = q[j * nx + i] - dt * (flux[i] - flux[i - 1]);
  }
}

// A VLA declared outside every loop (one row), filled once, read by two
// later loops.
DPGEN_KERNEL void smooth_twice_read(DPGEN_IN const double* a, DPGEN_OUT double* s,
                                    DPGEN_OUT double* d, int n) {
  double w[n];
  for (int i = 0; i < n; ++i)
    w[i] = tanh(a[i]);
  for (int i = 1; i < n - 1; ++i)
    s[i] = 0.25 * w[i - 1] + 0.5 * w[i] + 0.25 * w[i + 1];
  for (int i = 0; i < n - 1; ++i)
    d[i] = w[i + 1] - w[i];
}

// A buffer whose ends are set apart from its interior (straight-line stores
// in the row loop and an interior loop), then read everywhere: a periodic
// row padded with ghosts.
DPGEN_KERNEL void padded_rows(DPGEN_IN const double* u, DPGEN_OUT double* out, int nx, int ny) {
  for (int j = 0; j < ny; ++j) {
    double pad[nx + 2];
    pad[0] = u[j * nx + nx - 1];
    for (int i = 0; i < nx; ++i)
      pad[i + 1] = u[j * nx + i] * u[j * nx + i];
    pad[nx + 1] = u[j * nx + 0];
    for (int i = 0; i < nx; ++i)
      out[j * nx + i] = pad[i] - 2.0 * pad[i + 1] + pad[i + 2];
  }
}

// C99 VLA pointer casts over flat arrays: a variable-coefficient 3D
// Laplacian on an n^3 grid, u[k][j][i] with strides n * n, n, 1.
DPGEN_KERNEL void laplace3d_vla_cast(DPGEN_IN const double* u_flat, DPGEN_IN const double* k_flat,
                                     DPGEN_OUT double* lap_flat, int n, double h2inv) {
  const double (*u)[n][n] = (const double (*)[n][n])u_flat;
  const double (*kap)[n][n] = (const double (*)[n][n])k_flat;
  double (*lap)[n][n] = (double (*)[n][n])lap_flat;
  for (int k = 1; k < n - 1; k++)
    for (int j = 1; j < n - 1; j++)
      for (int i = 1; i < n - 1; i++)
        lap[k][j][i] = kap[k][j][i] * h2inv *
                       (u[k - 1][j][i] + u[k + 1][j][i] + u[k][j - 1][i] + u[k][j + 1][i] +
                        u[k][j][i - 1] + u[k][j][i + 1] - 6.0 * u[k][j][i]);
}

// A VLA pointer to rows of a 2D grid and a VLA line buffer together: the
// x-derivative through a buffer of squares, rows of length nx.
DPGEN_KERNEL void grad_rows_cast(DPGEN_IN const double* f_flat, DPGEN_OUT double* g_flat, int nx,
                                 int ny) {
  const double (*f)[nx] = (const double (*)[nx])f_flat;
  double (*g)[nx] = (double (*)[nx])g_flat;
  for (int j = 0; j < ny; j++) {
    double sq[nx];
    for (int i = 0; i < nx; i++)
      sq[i] = f[j][i] * f[j][i];
    for (int i = 1; i < nx - 1; i++)
      g[j][i] = 0.5 * (sq[i + 1] - sq[i - 1]);
  }
}

