// corpus: form=mdspan expect=accept
// D2Q9 lattice Boltzmann on mdspans f(q, y, x): BGK collision (moments from
// sums over the 9 populations, equilibrium), and pull streaming with periodic
// wrap written with % as LBM codes do; lattice tables are global constexpr.
#include "dpgen/annotate.hpp"

#include "mdspan_lite.hpp"

using pop_t = stdex::mdspan<double, stdex::dextents<int, 3>>;
using cpop_t = stdex::mdspan<const double, stdex::dextents<int, 3>>;

constexpr int Q = 9;
constexpr int cx[Q] = {0, 1, 0, -1, 0, 1, -1, -1, 1};
constexpr int cy[Q] = {0, 0, 1, 0, -1, 1, 1, -1, -1};
constexpr double wq[Q] = {4.0 / 9,  1.0 / 9,  1.0 / 9,  1.0 / 9, 1.0 / 9,
                          1.0 / 36, 1.0 / 36, 1.0 / 36, 1.0 / 36};

DPGEN_KERNEL void lbm_collide(DPGEN_IN cpop_t f, DPGEN_OUT pop_t fpost, double omega) {
  const int ny = f.extent(1), nx = f.extent(2);
  for (int y = 0; y < ny; ++y)
    for (int x = 0; x < nx; ++x) {
      double rho = 0, mx = 0, my = 0;
      for (int q = 0; q < Q; ++q) {
        rho += f(q, y, x);
        mx += cx[q] * f(q, y, x);
        my += cy[q] * f(q, y, x);
      }
      const double ux = mx / rho, uy = my / rho;
      const double usq = 1.5 * (ux * ux + uy * uy);
      for (int q = 0; q < Q; ++q) {
        const double cu = 3.0 * (cx[q] * ux + cy[q] * uy);
        const double feq = wq[q] * rho * (1.0 + cu + 0.5 * cu * cu - usq);
        fpost(q, y, x) = f(q, y, x) - omega * (f(q, y, x) - feq);
      }
    }
}

DPGEN_KERNEL void lbm_stream(DPGEN_IN cpop_t fpost, DPGEN_OUT pop_t fnew) {
  const int ny = fpost.extent(1), nx = fpost.extent(2);
  for (int q = 0; q < Q; ++q)
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x) {
        const int xs = (x - cx[q] + nx) % nx;
        const int ys = (y - cy[q] + ny) % ny;
        fnew(q, y, x) = fpost(q, ys, xs);
      }
}
