// corpus: form=parallelfor expect=accept
// AMReX HeatEquation tutorial (GPU version): face fluxes on nodal boxes from
// surroundingNodes, each by its own ParallelFor, then the update that reads
// them (the flux Array4s are outputs that a later nest reads: work arrays).
// Nonlinear conductivity k(phi) = 1 + phi^2 at faces.
#include "dpgen/annotate.hpp"

#include "amrex_lite.hpp"

using namespace amrex;

DPGEN_KERNEL void advance_box(Box const& bx, DPGEN_IN Array4<Real const> const& phi_old,
                              DPGEN_OUT Array4<Real> const& fluxx,
                              DPGEN_OUT Array4<Real> const& fluxy,
                              DPGEN_OUT Array4<Real> const& phi_new, Real dt, Real dxinv,
                              Real dyinv) {
  const Box xbx = surroundingNodes(bx, 0);
  const Box ybx = surroundingNodes(bx, 1);
  ParallelFor(xbx, [=] AMREX_GPU_DEVICE(int i, int j, int k) noexcept {
    const Real pf = 0.5 * (phi_old(i, j, k) + phi_old(i - 1, j, k));
    fluxx(i, j, k) = (1.0 + pf * pf) * (phi_old(i, j, k) - phi_old(i - 1, j, k)) * dxinv;
  });
  ParallelFor(ybx, [=] AMREX_GPU_DEVICE(int i, int j, int k) noexcept {
    const Real pf = 0.5 * (phi_old(i, j, k) + phi_old(i, j - 1, k));
    fluxy(i, j, k) = (1.0 + pf * pf) * (phi_old(i, j, k) - phi_old(i, j - 1, k)) * dyinv;
  });
  ParallelFor(bx, [=] AMREX_GPU_DEVICE(int i, int j, int k) noexcept {
    phi_new(i, j, k) = phi_old(i, j, k) + dt * dxinv * (fluxx(i + 1, j, k) - fluxx(i, j, k)) +
                       dt * dyinv * (fluxy(i, j + 1, k) - fluxy(i, j, k));
  });
}
