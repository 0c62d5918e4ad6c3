// adversary: switch on a parameter with loop nests in cases
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_br_switch(DPGEN_IN const double* a, DPGEN_OUT double* u, int n, int flag) {
  switch (flag) {
  case 0:
    for (int i = 0; i < n; ++i) u[i] = a[i] * a[i];
    break;
  case 1:
    for (int i = 0; i < n; ++i) u[i] = a[i];
    break;
  default:
    for (int i = 0; i < n; ++i) u[i] = -a[i] * a[i] * a[i];
  }
}
