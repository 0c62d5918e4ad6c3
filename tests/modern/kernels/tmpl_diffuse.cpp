// corpus: form=template expect=accept
// A kernel templated on the real type, instantiated explicitly for double
// and float (the adjoint: template diffuse1d_adjoint<Real> for both).
#include "dpgen/annotate.hpp"

template <typename Real>
DPGEN_KERNEL void diffuse1d(DPGEN_IN const Real* u, DPGEN_OUT Real* out, int n, Real nu) {
  out[0] = u[0];
  for (int i = 1; i < n - 1; ++i)
    out[i] = u[i] + nu * (u[i - 1] - Real(2) * u[i] + u[i + 1]);
  out[n - 1] = u[n - 1];
}

template void diffuse1d<double>(const double*, double*, int, double);
template void diffuse1d<float>(const float*, float*, int, float);
