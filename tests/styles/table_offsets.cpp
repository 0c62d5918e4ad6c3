// table_offsets (tests/styles/): lattice kernels whose offsets come from
// constant integer tables indexed by a small population loop (issue 22,
// mdspan_lbm): dpgen unrolls a loop of constant bounds that indexes such a
// table by its counter, so each copy reads a constant offset; a periodic wrap
// written with a remainder, `(x - cx[q] + nx) % nx`, is then the choice it
// is (x - cx[q] stays in [-nx, 2nx)); and the stores of one iteration to the
// populations' planes of a view, f(0, y, x) ... f(8, y, x), are apart.
#include "dpgen/annotate.hpp"

#include "include/user_views.hpp"

#include <cmath>

constexpr int kQ = 9;
constexpr int kCx[kQ] = {0, 1, 0, -1, 0, 1, -1, -1, 1};
constexpr int kCy[kQ] = {0, 0, 1, 0, -1, 1, 1, -1, -1};
constexpr double kW[kQ] = {4.0 / 9,  1.0 / 9,  1.0 / 9,  1.0 / 9, 1.0 / 9,
                           1.0 / 36, 1.0 / 36, 1.0 / 36, 1.0 / 36};

// Pull streaming, periodic in x and y, with the remainder.
DPGEN_KERNEL void table_stream(DPGEN_IN grid::Pops3D<const double> f,
                               DPGEN_OUT grid::Pops3D<double> g) {
  const int ny = f.ny, nx = f.nx;
  for (int q = 0; q < kQ; ++q)
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x)
        g(q, y, x) = f(q, (y - kCy[q] + ny) % ny, (x - kCx[q] + nx) % nx);
}

// A relaxation toward a table-weighted mean, every population of a cell in
// one iteration: nine stores to the planes 0..8 of the view.
DPGEN_KERNEL void table_relax(DPGEN_IN grid::Pops3D<const double> f,
                              DPGEN_OUT grid::Pops3D<double> g, double omega) {
  const int ny = f.ny, nx = f.nx;
  for (int y = 0; y < ny; ++y)
    for (int x = 0; x < nx; ++x) {
      double rho = 0, mx = 0;
      for (int q = 0; q < kQ; ++q) {
        rho += f(q, y, x);
        mx += kCx[q] * f(q, y, x);
      }
      const double ux = mx / (2.0 + rho * rho);
      for (int q = 0; q < kQ; ++q)
        g(q, y, x) = f(q, y, x) - omega * (f(q, y, x) - kW[q] * rho * (1.0 + 3.0 * kCx[q] * ux));
    }
}

// A flat array: the wrap by remainder in a 1D periodic shift by a table entry.
DPGEN_KERNEL void table_shift1d(DPGEN_IN const double* u, DPGEN_OUT double* v, int n) {
  for (int q = 0; q < 3; ++q)
    for (int i = 0; i < n; ++i)
      v[q * n + i] = std::sin(u[(i + kCx[q + 1] + n) % n]) * u[i];
}

// The same planes written by hand, 0 and 8 in one iteration: the plane
// stride is a placeholder symbol of 2^61 in generated code, and 8 * 2^61
// wraps to 0, so a test "same element?" on it came out true and dropped the
// first store's adjoint (dpgen before 2026-11-28); the planes are apart.
DPGEN_KERNEL void planes_first_last(DPGEN_IN grid::Pops3D<const double> f,
                                    DPGEN_OUT grid::Pops3D<double> g) {
  for (int y = 0; y < f.ny; ++y)
    for (int x = 0; x < f.nx; ++x) {
      g(0, y, x) = f(0, y, x) * f(8, y, x);
      g(8, y, x) = f(8, y, x) - 0.5 * f(0, y, x);
    }
}
