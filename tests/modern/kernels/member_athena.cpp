// corpus: form=member expect=accept
// Athena++ HydroDiffusion-like class: a member kernel with parameters (prim
// in, flx out, row and range) and a member array (the viscosity field, an
// input), method defined out of the class. Adjoint:
//   HydroDiffusion_ViscousFluxX1_adjoint(const HydroDiffusion& self,
//       prim, prim_adj, flx_adj, k, j, il, iu, <nu_iso adjoint>)
#include "dpgen/annotate.hpp"

#include "athena_array.hpp"

class HydroDiffusion {
public:
  AthenaArray<Real> nu_iso DPGEN_IN; // (k, j, i)
  Real dx1;
  DPGEN_KERNEL void ViscousFluxX1(DPGEN_IN const AthenaArray<Real>& prim,
                                  DPGEN_OUT AthenaArray<Real>& flx, const int k, const int j,
                                  const int il, const int iu);
};

void HydroDiffusion::ViscousFluxX1(const AthenaArray<Real>& prim, AthenaArray<Real>& flx,
                                   const int k, const int j, const int il, const int iu) {
  for (int i = il; i <= iu; ++i) {
    const Real nu = 0.5 * (nu_iso(k, j, i) + nu_iso(k, j, i - 1));
    const Real rho = 0.5 * (prim(IDN, k, j, i) + prim(IDN, k, j, i - 1));
    flx(IVX, i) = -rho * nu * (prim(IVX, k, j, i) - prim(IVX, k, j, i - 1)) / dx1;
    flx(IVY, i) = -rho * nu * (prim(IVY, k, j, i) - prim(IVY, k, j, i - 1)) / dx1;
  }
}
