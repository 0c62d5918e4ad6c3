// member_inplace (tests/styles/): a member kernel that updates a member array
// in place (DPGEN_INOUT), as a solver object's state.
#include "include/member_classes.hpp"

void Reaction1D::step(double dt) const {
  for (int i = 0; i < n; ++i)
    u[i] += dt * rate[i] * u[i] * (1.0 - u[i]);
}
