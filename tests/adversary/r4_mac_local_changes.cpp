// adversary: macro's local offset changes between the nests
#include "dpgen/annotate.hpp"
#define AT(i) ((i) + off)

DPGEN_KERNEL void r4_mac_local_changes(DPGEN_IN const double* a, DPGEN_OUT double* u, int n) {
  int off = 0;
  for (int i = 0; i < n; ++i) u[AT(i)] = a[AT(i)] * a[AT(i)];
  off = n;
  for (int i = 0; i < n; ++i) u[AT(i)] = a[i] * 3.0 + a[AT(i)];
}
