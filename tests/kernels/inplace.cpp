// Arrays updated in place (DPGEN_INOUT), element by element: an explicit
// reaction step on the interior only (the end cells pass through), with a
// conditional second update of the same element, and a relaxation of a
// state toward a target.
#include "test_kernels.hpp"

#include <cmath>

DPGEN_KERNEL void react_inplace(DPGEN_INOUT double* u, DPGEN_IN const double* rate, int n,
                                double dt) {
  for (int i = 1; i < n - 1; ++i) {
    u[i] += dt * rate[i] * u[i] * (1.0 - u[i]);
    if (u[i] > 0.5)
      u[i] = 0.5 + 0.5 * std::tanh(u[i] - 0.5);
  }
}

DPGEN_KERNEL void relax_inplace(DPGEN_INOUT double* u, DPGEN_IN const double* target, int n,
                                double w) {
  int i;
  for (i = 0; i < n; i++)
    u[i] = (1.0 - w) * u[i] + w * target[i] * target[i];
}

// In place across loop nests (issue 20): fluxes from the density's old
// values in one loop, then the density updated from them in the next, as
// finite-volume codes write it. The adjoint recomputes the fluxes from the
// old values (its own forward, printed from the IR, writes the new ones to a
// buffer: the user's kernel would overwrite u).
DPGEN_KERNEL void advect_fluxes_inplace(DPGEN_INOUT double* rho, DPGEN_IN const double* u,
                                        DPGEN_OUT double* flux, int n, double dt) {
  for (int i = 1; i < n; ++i)
    flux[i] = u[i] > 0.5 ? u[i] * rho[i - 1] : u[i] * rho[i];
  for (int i = 1; i < n - 1; ++i)
    rho[i] = rho[i] - dt * (flux[i + 1] - flux[i]);
}

// A norm of the old values (an accumulator), then every element rescaled.
DPGEN_KERNEL void normalize_inplace(DPGEN_INOUT double* v, DPGEN_IN const double* w, int n) {
  double s = 1.0;
  for (int i = 0; i < n; ++i)
    s += w[i] * v[i] * v[i];
  const double inv = 1.0 / std::sqrt(s);
  for (int i = 0; i < n; ++i)
    v[i] *= inv;
}

// Both arms of an if/else write the element they test: the else arm tests the
// old value, not the one the first arm may have just written (a tangent that
// updated u in place before the second test ran both arms where the first
// moved u across 0.5).
DPGEN_KERNEL void branch_inplace(DPGEN_INOUT double* u, DPGEN_IN const double* f, int n) {
  for (int i = 0; i < n; ++i) {
    if (u[i] > 0.5)
      u[i] = u[i] * 0.5 * f[i];
    else
      u[i] = u[i] + 0.2 * f[i];
  }
}

// Two arrays updated in place in one iteration, the second from the first's
// new value and from neighbours of an input (a coupled explicit update).
DPGEN_KERNEL void coupled_inplace(DPGEN_INOUT double* u, DPGEN_INOUT double* v,
                                  DPGEN_IN const double* f, int n) {
  for (int i = 1; i < n - 1; ++i) {
    u[i] = 2.0 * u[i] * f[i];
    v[i] = v[i] + u[i] * (f[i - 1] + f[i + 1]);
  }
}

// A density floor in place, then the pressure from the floored density: the
// read after the if is the new value where the floor applied (an in-place
// element stored under a condition and read after it; the generator once
// read the old value there, in the adjoint and the tangent).
DPGEN_KERNEL void floor_then_pressure(DPGEN_INOUT double* rho, DPGEN_IN const double* e,
                                      DPGEN_OUT double* p, int n) {
  for (int i = 0; i < n; ++i) {
    if (rho[i] < 0.5)
      rho[i] = 0.5 + 0.1 * e[i];
    p[i] = 0.4 * rho[i] * e[i];
  }
}

// Each arm of an if/else updates v in place; u then reads the new v.
DPGEN_KERNEL void arms_then_update(DPGEN_INOUT double* u, DPGEN_INOUT double* v,
                                   DPGEN_IN const double* f, int n) {
  for (int i = 0; i < n; ++i) {
    if (u[i] > 0.5)
      v[i] = v[i] - 0.5 * u[i];
    else
      v[i] = v[i] + u[i] * f[i];
    u[i] = u[i] + v[i];
  }
}

// A straight-line in-place store behind the kernel's guard: for n < 2 the
// kernel touches nothing, and an array of one element is enough (the adjoint
// once took u_adj's seed over [0, 2) and the tangent copied u over it,
// whatever n: one element past the array; AddressSanitizer sees it in CI).
DPGEN_KERNEL void guarded_pin(DPGEN_INOUT double* u, DPGEN_IN const double* f, int n) {
  if (n < 2)
    return;
  u[1] = 2.0 * u[1] * f[0];
}
