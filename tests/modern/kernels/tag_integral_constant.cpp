// corpus: form=tag expect=accept
// Direction tags as std::integral_constant (unnamed parameters), one
// overload per direction: a harmonic face average of a conductivity.
#include "dpgen/annotate.hpp"

#include <type_traits>

using XFace = std::integral_constant<int, 0>;
using YFace = std::integral_constant<int, 1>;

DPGEN_KERNEL void face_conductivity(DPGEN_IN const double* k, DPGEN_OUT double* kf, int nx, int ny,
                                    XFace) {
  for (int j = 0; j < ny; ++j)
    for (int i = 1; i < nx; ++i)
      kf[j * nx + i] =
          2.0 * k[j * nx + i] * k[j * nx + i - 1] / (k[j * nx + i] + k[j * nx + i - 1]);
}

DPGEN_KERNEL void face_conductivity(DPGEN_IN const double* k, DPGEN_OUT double* kf, int nx, int ny,
                                    YFace) {
  for (int j = 1; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      kf[j * nx + i] =
          2.0 * k[j * nx + i] * k[(j - 1) * nx + i] / (k[j * nx + i] + k[(j - 1) * nx + i]);
}
