// Variable-coefficient 2D Laplacian (harmonic face means), arrays passed as
// pointers to fixed-length rows `double (*u)[NX]`.
#include "dpgen/annotate.hpp"

constexpr int NX = 6;

DPGEN_KERNEL void varcoef_laplace2d_rowarray(DPGEN_IN const double (*k)[NX],
                                             DPGEN_IN const double (*u)[NX],
                                             DPGEN_OUT double (*lu)[NX], int ny, double inv_h2) {
  for (int j = 1; j < ny - 1; ++j)
    for (int i = 1; i < NX - 1; ++i) {
      double ke = 2.0 * k[j][i] * k[j][i + 1] / (k[j][i] + k[j][i + 1]);
      double kw = 2.0 * k[j][i] * k[j][i - 1] / (k[j][i] + k[j][i - 1]);
      double kn = 2.0 * k[j][i] * k[j + 1][i] / (k[j][i] + k[j + 1][i]);
      double ks = 2.0 * k[j][i] * k[j - 1][i] / (k[j][i] + k[j - 1][i]);
      lu[j][i] = inv_h2 * (ke * (u[j][i + 1] - u[j][i]) - kw * (u[j][i] - u[j][i - 1]) +
                           kn * (u[j + 1][i] - u[j][i]) - ks * (u[j][i] - u[j - 1][i]));
    }
}
