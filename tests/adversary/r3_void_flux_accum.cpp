// r3: void helper computing a flux into double& and the kernel doing rhs[i] += f; rhs[i+1] -= f
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>
static void flux(const double* q, int i, double& f) { f = 0.5 * (q[i] * q[i] + q[i + 1] * q[i + 1]); }
DPGEN_KERNEL void r3_void_flux_accum(DPGEN_IN const double* q, DPGEN_OUT double* r, int n) {
  for (int i = 0; i < n - 1; ++i) {
    double f;
    flux(q, i, f);
    r[i] += f;
    r[i + 1] -= f;
  }
}
