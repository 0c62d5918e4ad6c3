// A boundary kind passed as an enum class from a header (the generated
// declarations include that header), compared with `==` and switched on,
// its cases grouped.
#include "dpgen/annotate.hpp"
#include "include/boundary_kinds.hpp"

DPGEN_KERNEL void enum_class_bc(DPGEN_IN const double* u, DPGEN_OUT double* v, int n, Bc bc) {
  for (int i = 1; i < n; ++i)
    v[i] = u[i] * u[i - 1];
  switch (bc) {
  case Bc::Zero:
    v[0] = 0.0;
    break;
  case Bc::Copy:
  case Bc::Flip:
    v[0] = bc == Bc::Flip ? -u[0] * u[1] : u[0] * u[1];
    break;
  }
}

// The same kind by const reference, as configuration structs' getters hand
// it out: the generated declarations include the header here too.
DPGEN_KERNEL void enum_ref_bc(DPGEN_IN const double* u, DPGEN_OUT double* v, int n, const Bc& bc) {
  for (int i = 1; i < n; ++i)
    v[i] = u[i] * u[i - 1];
  if (bc == Bc::Flip)
    v[0] = -u[0] * u[0];
  else
    v[0] = bc == Bc::Zero ? 0.0 : u[0];
}

// The kind as a member of an object parameter and of a member kernel's class.
DPGEN_KERNEL void enum_member_bc(DPGEN_IN const double* u, DPGEN_OUT double* v, int n,
                                 const BcParams& p) {
  for (int i = 0; i < n; ++i)
    v[i] = p.bc == Bc::Flip ? -u[i] * p.dt : u[i] * u[i] * p.dt;
}

void EdgeSolver::run() const {
  for (int i = 0; i < n_; ++i)
    v_[i] = bc_ == Bc::Zero && (i == 0 || i == n_ - 1) ? 0.0 : u_[i] * u_[i];
}
