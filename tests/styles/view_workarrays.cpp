// view_workarrays (tests/styles/): views as work arrays, outputs that a later
// loop reads back, as hydro and AMReX-style codes write a two-pass update:
// face fluxes into a view, then the cells from them. The adjoint recomputes
// such an output into a buffer laid out like the view (dpgen/view_buffer.hpp).
#include "dpgen/annotate.hpp"

#include "include/user_views.hpp"

#include <cmath>

// Faces (j, i) for i = 0..nx between cells i-1 and i of a row with one ghost
// cell each side (u has nx + 2 columns, the flux nx + 1, the update nx): a
// nonlinear flux (Rusanov on Burgers) read linearly by the update.
DPGEN_KERNEL void view_faces_then_cells(DPGEN_IN grid::View2D<const double> u,
                                        DPGEN_OUT grid::View2D<double> flux,
                                        DPGEN_OUT grid::View2D<double> un, double dt_dx) {
  const int nx = un.cols(), ny = un.rows();
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const double ql = u(j, i), qr = u(j, i + 1);
      const double a = std::fabs(ql) > std::fabs(qr) ? std::fabs(ql) : std::fabs(qr);
      flux(j, i) = 0.25 * (ql * ql + qr * qr) - 0.5 * a * (qr - ql);
    }
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      un(j, i) = u(j, i + 1) - dt_dx * (flux(j, i + 1) - flux(j, i));
}

// A deep-const field (its const operator() returns a value, as Athena++'s
// AthenaArray): the new state, then a total of its squares that reads it back
// (nonlinear: the adjoint needs the recomputed values), reported by reference.
DPGEN_KERNEL void field_update_energy(DPGEN_IN const grid::Field& u,
                                      DPGEN_IN const grid::Field& dudt,
                                      DPGEN_OUT grid::Field& u_new, double dt,
                                      DPGEN_OUT double& energy) {
  const int n = u.size();
  for (int i = 0; i < n; ++i)
    u_new(i) = u(i) + dt * dudt(i) * (1.0 + u(i) * u(i));
  energy = 0.0;
  for (int i = 0; i < n; ++i)
    energy += 0.5 * u_new(i) * u_new(i);
}

// A Fortran-order view with ghost cells below index 0 (ilo = -1): a smoothed
// field on the interior and its ghosts, stored where a mask (an input) says,
// zero elsewhere; then a centred difference reads it one cell either side.
DPGEN_KERNEL void fortran_smooth_then_diff(DPGEN_IN grid::FortranView3D q,
                                           DPGEN_CONST grid::FortranView3D mask,
                                           DPGEN_OUT grid::FortranView3D s,
                                           DPGEN_OUT grid::FortranView3D d, int ni, int nj,
                                           int nk) {
  for (int k = 0; k < nk; ++k)
    for (int j = 0; j < nj; ++j)
      for (int i = -1; i <= ni; ++i) {
        if (mask(i, j, k) > 0.5)
          s(i, j, k) = 0.5 * q(i, j, k) + 0.25 * q(i, j, k) * q(i, j, k);
        else
          s(i, j, k) = 0.0;
      }
  for (int k = 0; k < nk; ++k)
    for (int j = 0; j < nj; ++j)
      for (int i = 0; i < ni; ++i)
        d(i, j, k) = s(i + 1, j, k) - s(i - 1, j, k) + s(i, j, k) * q(i, j, k);
}

// One loop nest whose bounds come from the output view's own shape (as
// Kokkos code loops to `out.extent(0)`): the adjoint has no output, only its
// seed, of the same shape, and reads the bounds from that.
DPGEN_KERNEL void view_bounds_from_output(DPGEN_IN grid::View2D<const double> u,
                                          DPGEN_OUT grid::View2D<double> out, double a) {
  for (int j = 0; j < out.rows(); ++j)
    for (int i = 0; i < out.cols(); ++i)
      out(j, i) = a * u(j, i) * u(j, i + 1);
}
