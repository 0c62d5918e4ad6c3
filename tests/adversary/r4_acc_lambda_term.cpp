// adversary: accumulating a lambda's value
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_lambda_term(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  auto e = [&](int i) { return a[i] * a[i + 1]; };
  double s = 0;
  for (int i = 0; i + 1 < n; ++i) s += e(i);
  out[0] = s * s;
}
