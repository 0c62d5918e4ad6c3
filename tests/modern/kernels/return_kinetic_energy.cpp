// corpus: form=return expect=accept
// Kinetic energy of a 2D flow over mdspans, returned (a diagnostic that a
// loss is made of).
#include "dpgen/annotate.hpp"

#include "mdspan_lite.hpp"

using field = stdex::mdspan<const double, stdex::dextents<int, 2>>;

DPGEN_KERNEL double kinetic_energy(DPGEN_IN field rho, DPGEN_IN field u, DPGEN_IN field v,
                                   double cell_area) {
  double e = 0.0;
  for (int j = 0; j < rho.extent(0); ++j)
    for (int i = 0; i < rho.extent(1); ++i)
      e += 0.5 * rho(j, i) * (u(j, i) * u(j, i) + v(j, i) * v(j, i));
  return e * cell_area;
}
