// adversary: [&] lambda updating the captured m
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_lambda_ref_capture(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = -3.0;
  auto upd = [&](double e) { m = std::max(m, e); };
  for (int i = 0; i < n; ++i) upd(a[i] * b[i]);
  out[0] = m * m;
}
