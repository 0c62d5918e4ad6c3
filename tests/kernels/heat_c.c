/* A C kernel as C codes write it: C99 variable-length 2D array parameters,
   counters declared at the top, restrict, math.h. dpgen parses .c files as
   C; the adjoint is declared extern "C" and takes the arrays flat. */
#include "dpgen/annotate.hpp"

#include <math.h>

DPGEN_KERNEL void heat_c(int n, DPGEN_IN const double u[n][n], DPGEN_IN const double* restrict kappa,
                         DPGEN_OUT double un[n][n], double r) {
  int i, j;
  for (j = 1; j < n - 1; j++)
    for (i = 1; i < n - 1; i++)
      un[j][i] = u[j][i] + r * kappa[0] *
                               (u[j][i - 1] + u[j][i + 1] + u[j - 1][i] + u[j + 1][i] -
                                4.0 * u[j][i]) +
                 0.1 * sin(u[j][i]);
}
