// adversary: nested if on two parameters
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_br_nested_flags(DPGEN_IN const double* a, DPGEN_OUT double* u, int n, int f1, int f2) {
  if (f1 == 1) {
    if (f2 == 1) {
      for (int i = 0; i < n; ++i) u[i] = a[i] * a[i];
    } else {
      for (int i = 0; i < n; ++i) u[i] = a[i] * 2.0;
    }
  } else {
    for (int i = 0; i < n; ++i) u[i] = a[i] * a[i] * a[i];
  }
}
