// r3: void helper with two double& outputs (split flux), unsigned counter
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>
static void split(double q, double c, double& fp, double& fm) {
  fp = 0.5 * (q * q + c * q);
  fm = 0.5 * (q * q - c * q);
}
DPGEN_KERNEL void r3_void_ref_two(DPGEN_IN const double* a, DPGEN_OUT double* o, unsigned n) {
  for (unsigned i = 1; i + 1 < n; ++i) {
    double p1, m1, p2, m2;
    split(a[i - 1], 0.3, p1, m1);
    split(a[i + 1], 0.3, p2, m2);
    o[i] = p1 - m2 + a[n - 1 - i];
  }
}
