// adversary: MINIMAL: a [&] lambda assigning a captured local inside a loop; the local read after the loop
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_min_lambda_ref_after_loop(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 1.0;
  auto set = [&](double e) { s = e; };
  for (int i = 0; i < n; ++i) set(a[i] * a[i]);
  out[0] = s;
}
