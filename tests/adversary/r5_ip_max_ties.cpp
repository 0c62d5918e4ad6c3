// adversary: in place: v / (1 + max|v|) with ties in the max (hand-computed)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_ip_max_ties(DPGEN_INOUT double* v, int n) {
  double m = 0.0;
  for (int i = 0; i < n; ++i) m = fmax(m, fabs(v[i]));
  for (int i = 0; i < n; ++i) v[i] = v[i] / (1.0 + m);
}
