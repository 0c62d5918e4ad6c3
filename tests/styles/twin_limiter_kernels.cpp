// Two identical smooth-limiter kernels (tanh/exp) in one file, e.g. one per
// conserved variable; each uses a helper.
#include "dpgen/annotate.hpp"

#include <cmath>

static inline double soft_limit(double d, double w) { return w * std::tanh(d / w); }

DPGEN_KERNEL void limit_rho(DPGEN_IN const double* q, DPGEN_OUT double* dq, int n, double w) {
  for (int i = 1; i < n - 1; ++i)
    dq[i] = soft_limit(q[i + 1] - q[i - 1], w) * std::exp(-q[i] * q[i]);
}

DPGEN_KERNEL void limit_mom(DPGEN_IN const double* q, DPGEN_OUT double* dq, int n, double w) {
  for (int i = 1; i < n - 1; ++i)
    dq[i] = soft_limit(q[i + 1] - q[i - 1], w) * std::exp(-q[i] * q[i]);
}
