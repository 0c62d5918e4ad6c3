// adversary: loops counting down, > and >=
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void a16_countdown(DPGEN_IN const double* a, DPGEN_OUT double* o, DPGEN_OUT double* p, int n) {
  for (int i = n - 1; i > 0; --i) o[i] = a[i] * a[i - 1];
  for (int i = n - 2; i >= 0; i--) { p[i] = a[i + 1] * a[i]; p[i] = p[i] * a[i + 1]; }
}
