// adversary: helpers: multiple returns, nested ifs, helper calling helper, array parameter
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
static double diff(const double* p, int i) { return p[i + 1] - p[i]; }
DPGEN_KERNEL void a24_helpers(DPGEN_IN const double* q, DPGEN_OUT double* o, int n) {
  for (int i = 1; i < n - 1; ++i) o[i] = q[i] + 0.5 * lim(diff(q, i - 1), diff(q, i)) * q[i];
}
