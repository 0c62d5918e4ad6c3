// member_advect (tests/styles/): a member kernel with private members, defined
// out of class, calling a private helper method.
#include "include/member_classes.hpp"

void Advection1D::step(double dt) const {
  q_new_[0] = q_[0];
  for (int i = 1; i < n_ - 1; ++i)
    q_new_[i] = q_[i] - dt * (flux(q_[i], q_[i + 1]) - flux(q_[i - 1], q_[i]));
  q_new_[n_ - 1] = q_[n_ - 1];
}
