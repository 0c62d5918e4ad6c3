// corpus: form=template expect=accept
// Direction as a non-type template parameter (the dimension-generic style of
// many codes): centered gradient along Dir, offsets and bounds constexpr in
// Dir; instantiated by the calls in gradients(), not explicitly.
#include "dpgen/annotate.hpp"

template <typename Real, int Dir>
DPGEN_KERNEL void gradient(DPGEN_IN const Real* p, DPGEN_OUT Real* g, int nx, int ny, Real inv_2h) {
  constexpr int di = Dir == 0 ? 1 : 0;
  constexpr int dj = Dir == 1 ? 1 : 0;
  for (int j = dj; j < ny - dj; ++j)
    for (int i = di; i < nx - di; ++i)
      g[j * nx + i] = (p[(j + dj) * nx + i + di] - p[(j - dj) * nx + i - di]) * inv_2h;
}

void gradients(const double* p, double* gx, double* gy, int nx, int ny, double h) {
  gradient<double, 0>(p, gx, nx, ny, 0.5 / h);
  gradient<double, 1>(p, gy, nx, ny, 0.5 / h);
}
