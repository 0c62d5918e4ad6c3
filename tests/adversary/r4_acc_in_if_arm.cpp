// adversary: accumulator inside an if arm on a parameter
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r4_acc_in_if_arm(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, int flag) {
  if (flag == 0) {
    double s = 0.0;
    for (int i = 0; i < n; ++i) s += a[i] * a[i];
    out[0] = std::sqrt(1.0 + s);
  } else {
    double s = 1.0;
    for (int i = 0; i < n; ++i) s += a[i];
    out[0] = s * s;
  }
}
