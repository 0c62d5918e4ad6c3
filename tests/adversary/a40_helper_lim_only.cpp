// adversary: a24 split: nested-if helper with several returns only
#include "dpgen/annotate.hpp"

#include <cmath>
static inline double sq(double x) { return x * x; }
static inline double lim(double l, double r) {
  if (l * r <= 0) return 0.0;
  if (std::fabs(l) < std::fabs(r)) {
    if (l > 0) return sq(l);
    return -sq(l);
  }
  return r;
}
DPGEN_KERNEL void a40_helper_lim_only(DPGEN_IN const double* q, DPGEN_OUT double* o, int n) {
  for (int i = 1; i < n - 1; ++i) o[i] = q[i] + lim(q[i] - q[i - 1], q[i + 1] - q[i]) * q[i];
}
