// corpus: form=athena expect=accept
// A shallow-water Riemann solver in the Athena++ layout (src/hydro/rsolvers):
// local Lax-Friedrichs (Rusanov) flux at the x1 faces il..iu of one row from
// left/right states wl(n, i), wr(n, i) (n = IDN: h, IVX, IVY: velocities),
// writing flx(n, k, j, i). Wave speed |u| + sqrt(g h).
#include "dpgen/annotate.hpp"

#include "athena_array.hpp"

#include <algorithm>
#include <cmath>

DPGEN_KERNEL void RusanovSWE(const int k, const int j, const int il, const int iu,
                             DPGEN_IN const AthenaArray<Real>& wl,
                             DPGEN_IN const AthenaArray<Real>& wr, DPGEN_OUT AthenaArray<Real>& flx,
                             const Real grav) {
  for (int i = il; i <= iu; ++i) {
    const Real hl = wl(IDN, i), ul = wl(IVX, i), vl = wl(IVY, i);
    const Real hr = wr(IDN, i), ur = wr(IVX, i), vr = wr(IVY, i);
    const Real cl = std::abs(ul) + std::sqrt(grav * hl);
    const Real cr = std::abs(ur) + std::sqrt(grav * hr);
    const Real a = std::max(cl, cr);
    const Real fl_h = hl * ul, fr_h = hr * ur;
    const Real fl_m = hl * ul * ul + 0.5 * grav * hl * hl;
    const Real fr_m = hr * ur * ur + 0.5 * grav * hr * hr;
    const Real fl_t = hl * ul * vl, fr_t = hr * ur * vr;
    flx(IDN, k, j, i) = 0.5 * (fl_h + fr_h) - 0.5 * a * (hr - hl);
    flx(IVX, k, j, i) = 0.5 * (fl_m + fr_m) - 0.5 * a * (hr * ur - hl * ul);
    flx(IVY, k, j, i) = 0.5 * (fl_t + fr_t) - 0.5 * a * (hr * vr - hl * vl);
  }
}
