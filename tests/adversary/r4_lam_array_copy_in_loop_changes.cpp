// adversary: [=] copy of a local array changed inside the loop before each call
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_lam_array_copy_in_loop_changes(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  double w[1] = {1.0};
  auto f = [=](int i) { return w[0] * u[i]; };
  for (int i = 0; i < n; ++i) {
    w[0] = u[i];
    out[i] = f(i) + w[0];
  }
}
