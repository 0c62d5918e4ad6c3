#include "dpgen/annotate.hpp"
static inline double sq(double x) { return x * x; }
static inline double lim(double l, double r) { if (l < r) { if (l > 0) return sq(l); return -sq(l); } return r; }
DPGEN_KERNEL void a43_helper_sq_nested_crash_min(DPGEN_IN const double* q, DPGEN_OUT double* o, int n) {
  for (int i = 1; i < n - 1; ++i) o[i] = lim(q[i] - q[i - 1], q[i + 1] - q[i]);
}
