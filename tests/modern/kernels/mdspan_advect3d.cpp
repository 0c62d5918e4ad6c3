// corpus: form=mdspan expect=accept
// 3D upwind advection of a scalar by a velocity field (three mdspans),
// periodic in x through a conditional index.
#include "dpgen/annotate.hpp"

#include "mdspan_lite.hpp"

#include <algorithm>
#include <cstddef>

template <class T> using field3 = stdex::mdspan<T, stdex::dextents<std::size_t, 3>>;

DPGEN_KERNEL void advect3d_upwind(DPGEN_IN field3<const double> q, DPGEN_IN field3<const double> vx,
                                  DPGEN_IN field3<const double> vy, DPGEN_OUT field3<double> qn,
                                  double dt_dx) {
  const std::size_t nz = q.extent(0), ny = q.extent(1), nx = q.extent(2);
  for (std::size_t k = 0; k < nz; ++k)
    for (std::size_t j = 1; j + 1 < ny; ++j)
      for (std::size_t i = 0; i < nx; ++i) {
        const std::size_t ip = (i + 1 == nx) ? 0 : i + 1;
        const std::size_t im = (i == 0) ? nx - 1 : i - 1;
        const double u = vx(k, j, i), v = vy(k, j, i);
        const double dqx = u > 0 ? q(k, j, i) - q(k, j, im) : q(k, j, ip) - q(k, j, i);
        const double dqy = v > 0 ? q(k, j, i) - q(k, j - 1, i) : q(k, j + 1, i) - q(k, j, i);
        qn(k, j, i) = q(k, j, i) - dt_dx * (u * dqx + v * dqy);
      }
}
