// Loops with more than one counter, and strided loops counting down, as C
// and Fortran-minded code writes them: a mirror `for (i = 0, j = n - 1; i <
// n; ++i, --j)`, a C89 pair walking an interleaved complex array (`k += 2`),
// a flat index carried beside the column counter of a 2D sweep, a reversed
// copy counting the other way, a post-decrement pair, stencil offsets as a
// companion of an unrolled weight loop, and `i -= 2` from the end (also with
// a start that alternates with the row).
#include "dpgen/annotate.hpp"

#include <cstddef>

DPGEN_KERNEL void mirror_product(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0, j = n - 1; i < n; ++i, --j)
    b[i] = a[j] * a[i];
}

DPGEN_KERNEL void unsigned_mirror(DPGEN_IN const double* a, DPGEN_OUT double* b, unsigned n) {
  for (unsigned i = 0, j = n - 1; i < n; ++i, --j) // (j wraps only after the last iteration)
    b[i] = a[j] * a[i] * (j < 2 ? 3.0 : 1.0);
}

DPGEN_KERNEL void complex_magnitude(DPGEN_IN const double* z, DPGEN_OUT double* mag, int n) {
  int i, k;
  for (i = 0, k = 0; i < n; i++, k += 2)
    mag[i] = z[k] * z[k] + z[k + 1] * z[k + 1] + 0.5 * z[k] * z[k + 1];
}

DPGEN_KERNEL void laplace_flat_index(DPGEN_IN const double* u, DPGEN_OUT double* lap, int nx,
                                     int ny, double inv_h2) {
  for (int j = 1; j < ny - 1; ++j)
    for (int i = 1, p = j * nx + 1; i < nx - 1; ++i, ++p)
      lap[p] = inv_h2 * (u[p - 1] + u[p + 1] + u[p - nx] + u[p + nx] - 4.0 * u[p]) * u[p];
}

DPGEN_KERNEL void reverse_blend(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = n - 1, k = 0; i >= 0; --i, ++k)
    b[k] = a[i] * a[i] + 2.0 * a[k];
}

DPGEN_KERNEL void postdec_pair(DPGEN_IN const double* a, DPGEN_OUT double* c, int n) {
  for (int i = n, k = 0; i-- > 0; ++k)
    c[k] = a[i] * a[k];
}

DPGEN_KERNEL void offset_weights(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  const double w[3] = {0.25, 0.5, 0.25};
  for (int i = 1; i < n - 1; ++i) {
    double s = 0.0;
    for (int q = 0, o = -1; q < 3; ++q, ++o)
      s += w[q] * u[i + o] * u[i + o];
    out[i] = s;
  }
}

DPGEN_KERNEL void down_by_two(DPGEN_IN const double* a, DPGEN_OUT double* e, long long n) {
  for (long long i = n - 1; i >= 0; i -= 2)
    e[i] = a[i] * a[n - 1 - i];
}

DPGEN_KERNEL void rb_down_sweep(DPGEN_IN const double* u, DPGEN_OUT double* v, int nx, int ny) {
  for (int j = 1; j < ny - 1; ++j)
    for (int i = nx - 2 - j % 2; i >= 1; i -= 2)
      v[j * nx + i] = 0.25 * (u[j * nx + i - 1] + u[j * nx + i + 1] + u[(j - 1) * nx + i] +
                              u[(j + 1) * nx + i]) *
                      u[j * nx + i];
}

DPGEN_KERNEL void unsigned_down_by_three(DPGEN_IN const double* a, DPGEN_OUT double* e,
                                         unsigned n) {
  for (unsigned i = n; i >= 3; i -= 3)
    e[i] = a[i] * a[i] * a[i / 3];
}

DPGEN_KERNEL void strided_unsigned_scatter(DPGEN_IN const double* a, DPGEN_OUT double* e,
                                           std::size_t n) {
  for (std::size_t i = 10; i < n; i += 3) // (no iteration below n = 11)
    e[i] = a[i / 3] * a[i];
}
