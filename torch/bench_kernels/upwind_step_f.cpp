// float twins of kernels/upwind_step.cpp and kernels/laplacian2d.cpp, for the float32 rows of
// bench/torch_ops.py (a kernel has one precision; its op takes tensors of that dtype).
#include "dpgen/annotate.hpp"

#include <algorithm>

DPGEN_KERNEL void upwind_step_f(DPGEN_IN const float* d, DPGEN_IN const float* u,
                                DPGEN_OUT float* d_next, int n, float dt, float dx) {
  for (int i = 0; i < n; ++i) {
    const int ip = (i == n - 1) ? 0 : i + 1;
    const int im = (i == 0) ? n - 1 : i - 1;
    const float up = std::min(u[i] / dx, 0.0f);
    const float um = std::max(u[i] / dx, 0.0f);
    d_next[i] = d[i] - dt * (up * (d[ip] - d[i]) + um * (d[i] - d[im]));
  }
}

DPGEN_KERNEL void laplacian2d_f(DPGEN_IN const float* a, DPGEN_OUT float* out, int nx, int ny,
                                float h) {
  const float inv_h2 = 1.0f / (h * h);
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const int k = j * nx + i;
      if (i == 0 || i == nx - 1 || j == 0 || j == ny - 1) {
        out[k] = 0.0f;
      } else {
        out[k] = (a[k - 1] + a[k + 1] + a[k - nx] + a[k + nx] - 4.0f * a[k]) * inv_h2;
      }
    }
  }
}
