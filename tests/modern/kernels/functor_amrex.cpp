// corpus: form=functor expect=accept
// A named functor handed to amrex::ParallelFor (as codes do to share a body
// between CPU and GPU builds): Array4 members, operator()(i, j, k) const.
#include "dpgen/annotate.hpp"

#include "amrex_lite.hpp"

struct GradMagnitude {
  amrex::Array4<amrex::Real const> phi;
  amrex::Array4<amrex::Real> gsq;
  amrex::Real half_dxinv;
  AMREX_GPU_DEVICE void operator()(int i, int j, int k) const noexcept {
    const amrex::Real gx = half_dxinv * (phi(i + 1, j, k) - phi(i - 1, j, k));
    const amrex::Real gy = half_dxinv * (phi(i, j + 1, k) - phi(i, j - 1, k));
    gsq(i, j, k) = gx * gx + gy * gy;
  }
};

DPGEN_KERNEL void grad_magnitude(amrex::Box const& bx,
                                 DPGEN_IN amrex::Array4<amrex::Real const> const& phi,
                                 DPGEN_OUT amrex::Array4<amrex::Real> const& gsq,
                                 amrex::Real dxinv) {
  amrex::ParallelFor(bx, GradMagnitude{phi, gsq, 0.5 * dxinv});
}
