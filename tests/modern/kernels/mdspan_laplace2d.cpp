// corpus: form=mdspan expect=accept
// mdspan by value (C++23 style, here the C++17 reference-implementation form
// with operator()): a 5-point Laplacian on the interior, sizes from extent().
#include "dpgen/annotate.hpp"

#include "mdspan_lite.hpp"

using grid_t = stdex::mdspan<double, stdex::dextents<int, 2>>;
using cgrid_t = stdex::mdspan<const double, stdex::dextents<int, 2>>;

DPGEN_KERNEL void laplace2d(DPGEN_IN cgrid_t u, DPGEN_OUT grid_t lap, double inv_h2) {
  for (int j = 1; j < u.extent(0) - 1; ++j)
    for (int i = 1; i < u.extent(1) - 1; ++i)
      lap(j, i) = inv_h2 * (u(j, i - 1) + u(j, i + 1) + u(j - 1, i) + u(j + 1, i) - 4.0 * u(j, i));
}
