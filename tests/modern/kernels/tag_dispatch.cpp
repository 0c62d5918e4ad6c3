// corpus: form=tag expect=accept
// Tag dispatch: two overloads of one kernel name told apart by an unnamed
// empty tag parameter (the adjoints are overloads too:
// sweep_adjoint(..., XDir) and sweep_adjoint(..., YDir)).
#include "dpgen/annotate.hpp"

struct XDir {};
struct YDir {};

DPGEN_KERNEL void sweep(DPGEN_IN const double* u, DPGEN_OUT double* out, int nx, int ny, double c,
                        XDir) {
  for (int j = 0; j < ny; ++j)
    for (int i = 1; i < nx - 1; ++i)
      out[j * nx + i] =
          u[j * nx + i] + c * (u[j * nx + i - 1] - 2.0 * u[j * nx + i] + u[j * nx + i + 1]);
}

DPGEN_KERNEL void sweep(DPGEN_IN const double* u, DPGEN_OUT double* out, int nx, int ny, double c,
                        YDir) {
  for (int j = 1; j < ny - 1; ++j)
    for (int i = 0; i < nx; ++i)
      out[j * nx + i] =
          u[j * nx + i] + c * (u[(j - 1) * nx + i] - 2.0 * u[j * nx + i] + u[(j + 1) * nx + i]);
}
