// corpus: form=scalarref expect=accept
// An update that also reports a conserved total through Real& (Athena++
// style history output), AthenaArray inputs by const&, dt by const&.
#include "dpgen/annotate.hpp"

#include "athena_array.hpp"

DPGEN_KERNEL void update_and_total(DPGEN_IN const AthenaArray<Real>& u,
                                   DPGEN_IN const AthenaArray<Real>& dudt,
                                   DPGEN_OUT AthenaArray<Real>& u_new, const Real& dt, int is,
                                   int ie, int js, int je, DPGEN_OUT Real& total) {
  for (int j = js; j <= je; ++j)
    for (int i = is; i <= ie; ++i)
      u_new(j, i) = u(j, i) + dt * dudt(j, i);
  total = 0.0;
  for (int j = js; j <= je; ++j)
    for (int i = is; i <= ie; ++i)
      total += u_new(j, i) * u_new(j, i);
}
