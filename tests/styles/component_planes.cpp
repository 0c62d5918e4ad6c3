// component_planes (tests/styles/): the components of a system (density,
// momentum, energy) as planes of one flat array, `f[c * ny * (nx + 1) + j *
// (nx + 1) + i]` with a constant c per store, as miniWeather writes its
// fluxes (issue 22). The plane offsets are products of sizes: dpgen proves
// from the loop bounds that the planes never meet (j * (nx + 1) + i stays
// below ny * (nx + 1)), or checks the sizes on entry where a parameter sets
// the plane stride.
#include "dpgen/annotate.hpp"

#include <cmath>

// Face values of three components on x faces (nx + 1 per row), then their
// differences per cell: `face` is a work array read plane by plane by the
// second loop nest.
DPGEN_KERNEL void planes_faces(DPGEN_IN const double* q, DPGEN_OUT double* face,
                               DPGEN_OUT double* div, int nx, int ny) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx + 1; ++i) {
      const double a = q[0 * ny * (nx + 2) + j * (nx + 2) + i];
      const double b = q[0 * ny * (nx + 2) + j * (nx + 2) + i + 1];
      const double m = q[1 * ny * (nx + 2) + j * (nx + 2) + i];
      const double mp = q[1 * ny * (nx + 2) + j * (nx + 2) + i + 1];
      const double e = q[2 * ny * (nx + 2) + j * (nx + 2) + i];
      const double ep = q[2 * ny * (nx + 2) + j * (nx + 2) + i + 1];
      const double ra = std::exp(0.3 * a), rb = std::exp(0.3 * b);
      face[0 * ny * (nx + 1) + j * (nx + 1) + i] = 0.5 * (m + mp);
      face[1 * ny * (nx + 1) + j * (nx + 1) + i] = 0.5 * (m * m / ra + mp * mp / rb);
      face[2 * ny * (nx + 1) + j * (nx + 1) + i] = 0.5 * (e * m / ra + ep * mp / rb);
    }
  for (int c = 0; c < 3; ++c)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        div[c * ny * nx + j * nx + i] =
            face[c * ny * (nx + 1) + j * (nx + 1) + i + 1] - face[c * ny * (nx + 1) + j * (nx + 1) + i];
}

// Three planes of a 3D block (nz + 1 planes of (ny + 1) * (nx + 1) nodes
// each component), offsets products of three sizes, written by the
// interior nest; the planes' node rows are l * (nz + 1) * (ny + 1) * (nx + 1).
DPGEN_KERNEL void planes_nodes3d(DPGEN_IN const double* u, DPGEN_OUT double* g, int nx, int ny,
                                 int nz) {
  for (int k = 0; k < nz + 1; ++k)
    for (int j = 0; j < ny + 1; ++j)
      for (int i = 0; i < nx + 1; ++i) {
        const double c = u[k * (ny + 1) * (nx + 1) + j * (nx + 1) + i];
        g[0 * (nz + 1) * (ny + 1) * (nx + 1) + k * (ny + 1) * (nx + 1) + j * (nx + 1) + i] = c * c;
        g[1 * (nz + 1) * (ny + 1) * (nx + 1) + k * (ny + 1) * (nx + 1) + j * (nx + 1) + i] =
            std::sin(c);
        g[2 * (nz + 1) * (ny + 1) * (nx + 1) + k * (ny + 1) * (nx + 1) + j * (nx + 1) + i] =
            c * std::cos(c);
      }
}

// The plane stride a parameter: the planes are apart only when stride >= n,
// which the generated code checks on entry (std::invalid_argument otherwise).
DPGEN_KERNEL void planes_strided(DPGEN_IN const double* u, DPGEN_OUT double* out, int n,
                                 int stride) {
  for (int i = 0; i < n; ++i) {
    out[i] = u[i] * u[i];
    out[stride + i] = std::sin(u[i]);
    out[2 * stride + i] = u[i] * std::exp(-u[i]);
  }
}
