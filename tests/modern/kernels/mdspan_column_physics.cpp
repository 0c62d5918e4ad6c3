// corpus: form=mdspan expect=accept
// Fortran-ordered data (layout_left, as a weather code shares with Fortran):
// a column operator, implicit-free vertical diffusion plus a relaxation term,
// k the vertical index, first index i contiguous.
#include "dpgen/annotate.hpp"

#include "mdspan_lite.hpp"

using colview = stdex::mdspan<double, stdex::dextents<int, 2>, stdex::layout_left>;
using ccolview = stdex::mdspan<const double, stdex::dextents<int, 2>, stdex::layout_left>;

DPGEN_KERNEL void column_tendency(DPGEN_IN ccolview t, DPGEN_IN ccolview kz, DPGEN_OUT colview dtdt,
                                  double inv_dz2, double tau_inv, double t_ref) {
  const int ncol = t.extent(0), nlev = t.extent(1);
  for (int k = 1; k < nlev - 1; ++k)
    for (int i = 0; i < ncol; ++i) {
      const double kup = 0.5 * (kz(i, k) + kz(i, k + 1));
      const double kdn = 0.5 * (kz(i, k) + kz(i, k - 1));
      dtdt(i, k) = inv_dz2 * (kup * (t(i, k + 1) - t(i, k)) - kdn * (t(i, k) - t(i, k - 1))) -
                   tau_inv * (t(i, k) - t_ref);
    }
}
