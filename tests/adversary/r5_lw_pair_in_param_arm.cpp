// adversary: the pair inside an arm of an if on a parameter; the other arm writes K[j] only
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_lw_pair_in_param_arm(DPGEN_IN const double* a, DPGEN_OUT double* K, int n, int flag) {
  if (flag == 1) {
    for (int j = 0; j < n; ++j) {
      K[j] = a[j] * a[j];
      K[j + 1] = std::sin(a[j]);
    }
  } else {
    for (int j = 0; j < n; ++j) K[j] = 3.0 * a[j];
    K[n] = 1.0;
  }
}
