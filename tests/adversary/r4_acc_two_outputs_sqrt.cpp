// adversary: one sum read by two outputs after
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r4_acc_two_outputs_sqrt(DPGEN_IN const double* a, DPGEN_OUT double* o1,
                                          DPGEN_OUT double* o2, int n) {
  double s = 0;
  for (int i = 0; i < n; ++i) s += a[i] * a[i];
  o1[0] = std::sqrt(1.0 + s);
  o2[0] = s * s;
}
