// adversary: *err = max |v - t| of the old values (output reduction), then v = t in place blended
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_ip_normalize_by_max_err_out(DPGEN_INOUT double* v, DPGEN_IN const double* t, DPGEN_OUT double* err, int n) {
  *err = 0.0;
  for (int i = 0; i < n; ++i) *err = fmax(*err, fabs(v[i] - t[i]));
  for (int i = 0; i < n; ++i) v[i] = 0.5 * (v[i] + t[i] * t[i]);
}
