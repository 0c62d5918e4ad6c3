// adversary: per-row max, then a sum of exp(a - max), then the normalised row (softmax)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_rowmax_softmax(DPGEN_IN const double* a, DPGEN_OUT double* p, int nx, int ny) {
  for (int j = 0; j < ny; ++j) {
    double m = a[j * nx];
    for (int i = 1; i < nx; ++i) m = fmax(m, a[j * nx + i]);
    double s = 0.0;
    for (int i = 0; i < nx; ++i) s += std::exp(a[j * nx + i] - m);
    for (int i = 0; i < nx; ++i) p[j * nx + i] = std::exp(a[j * nx + i] - m) / s;
  }
}
