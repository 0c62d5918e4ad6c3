// corpus: form=mask expect=accept
// Masks that are not differentiated: `const bool* solid` (an immersed solid
// with zero-flux walls: a solid neighbour contributes no flux) and a uint8_t
// wet/dry mask combined with & in a shallow-water flux.
#include "dpgen/annotate.hpp"

#include <cstdint>

DPGEN_KERNEL void ib_diffuse(DPGEN_IN const double* T, const bool* solid, DPGEN_OUT double* Tn,
                             int nx, int ny, double a) {
  for (int j = 1; j < ny - 1; ++j)
    for (int i = 1; i < nx - 1; ++i) {
      const int c = j * nx + i;
      if (solid[c]) {
        Tn[c] = T[c];
        continue;
      }
      const double fe = solid[c + 1] ? 0.0 : T[c + 1] - T[c];
      const double fw = solid[c - 1] ? 0.0 : T[c - 1] - T[c];
      const double fn = solid[c + nx] ? 0.0 : T[c + nx] - T[c];
      const double fs = solid[c - nx] ? 0.0 : T[c - nx] - T[c];
      Tn[c] = T[c] + a * (fe + fw + fn + fs);
    }
}

DPGEN_KERNEL void wetdry_flux(DPGEN_IN const double* h, const std::uint8_t* wet,
                              DPGEN_OUT double* dh, int n, double c) {
  for (int i = 1; i < n - 1; ++i) {
    const double fr = double(wet[i] & wet[i + 1]) * (h[i + 1] * h[i + 1] - h[i] * h[i]);
    const double fl = double(wet[i - 1] & wet[i]) * (h[i] * h[i] - h[i - 1] * h[i - 1]);
    dh[i] = c * (fr - fl);
  }
}
