// Running indices, as C codes carry a flat index through their loops: set
// before the nest, stepped (`idx++`, `idx += 2` past a row's ghost cells) in
// every iteration. dpgen gives each iteration its index in closed form
// (`idx + j * idx_per_j + i * idx_per_i`), so the adjoint's gathers and the
// parallel forward run iterations apart.
#include "dpgen/annotate.hpp"

#include <cstddef>

// A 5-point product stencil on the interior of an nx x ny grid (row-major),
// the index stepping over the two ghost cells between rows.
DPGEN_KERNEL void ghost_rows(DPGEN_IN const double* a, DPGEN_OUT double* b, int nx, int ny) {
  int idx = nx + 1;
  for (int j = 1; j < ny - 1; ++j) {
    for (int i = 1; i < nx - 1; ++i) {
      b[idx] = a[idx - 1] + a[idx + 1] - 2.0 * a[idx] + a[idx - nx] * a[idx + nx];
      idx++;
    }
    idx += 2;
  }
}

// C89: counters and the index declared at the top, the index set apart.
DPGEN_KERNEL void c89_flat(DPGEN_IN const double* a, DPGEN_OUT double* b, int nx, int ny) {
  int i, j, k;
  k = 0;
  for (j = 0; j < ny; j++) {
    for (i = 0; i < nx; i++) {
      b[k] = a[k] * (double)(i + 1) - a[k] * a[k];
      k++;
    }
  }
}

// Two indices at different strides: pairs of the input into one output.
DPGEN_KERNEL void pair_products(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  int in = 1, out = 0;
  for (int i = 0; i < n; ++i) {
    b[out] = a[in] * a[in - 1] + a[in + 1];
    in += 2;
    out++;
  }
}

// An index counting up while the loop counts down (a reversal), and one
// stepped first in the body.
DPGEN_KERNEL void reverse_fill(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  int idx = 0;
  for (int i = n - 1; i >= 0; --i) {
    b[idx] = a[i] * a[idx];
    idx++;
  }
}

DPGEN_KERNEL void step_first(DPGEN_IN const double* a, DPGEN_OUT double* b, std::size_t n) {
  std::size_t p = 0;
  for (std::size_t i = 0; i < n; ++i) {
    ++p;
    b[p - 1] = a[p - 1] * 3.0 - a[i] * a[i];
  }
}

// Three levels (a long index), a strided loop, a small loop (unrolled, the
// index stepped in each copy).
DPGEN_KERNEL void flat3d(DPGEN_IN const double* a, DPGEN_OUT double* b, int nx, int ny, int nz) {
  long idx = 0;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        b[idx] = a[idx] * (1.0 + k) + (i > 0 ? a[idx - 1] * a[idx] : 0.0);
        ++idx;
      }
}

DPGEN_KERNEL void pair_sums(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  int o = 0;
  for (int i = 0; i + 1 < n; i += 2) {
    b[o] = a[i] * a[i + 1];
    o++;
  }
}

DPGEN_KERNEL void rgb_scale(DPGEN_IN const double* a, DPGEN_OUT double* b, int npix) {
  static const double w[3] = {0.299, 0.587, 0.114};
  int idx = 0;
  for (int p = 0; p < npix; ++p)
    for (int c = 0; c < 3; ++c) {
      b[idx] = a[idx] * w[c] * a[idx];
      idx++;
    }
}

// Read after its loop, where a guard proves the loop runs.
DPGEN_KERNEL void tail_after(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  if (n < 1)
    return;
  int idx = 0;
  for (int i = 0; i < n; ++i) {
    b[idx] = a[idx] * a[idx + 1];
    idx++;
  }
  b[idx] = a[idx] * a[idx];
}

// Read after a nest, where the guard proves both loops run: nx - 1 cells of
// each row, the row's last skipped, then one cell past the rows.
DPGEN_KERNEL void tail_after_nest(DPGEN_IN const double* a, DPGEN_OUT double* b, int nx, int ny) {
  if (nx < 2 || ny < 1)
    return;
  int idx = 0;
  for (int j = 0; j < ny; ++j) {
    for (int i = 1; i < nx; ++i) {
      b[idx] = a[idx] * a[idx + 1];
      idx++;
    }
    idx += 1;
  }
  b[idx] = a[idx] * a[0];
}

// The step inside the store, as C writes a packed output (`b[k++] = x`), or
// in the read (`a[k++]`), the index read nowhere else in the statement.
DPGEN_KERNEL void pack_squares(DPGEN_IN const double* a, DPGEN_OUT double* b, int nx, int ny) {
  int k = 0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      b[k++] = a[j * nx + i] * a[j * nx + i] + j;
}

DPGEN_KERNEL void unpack_pairs(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  int k = 0;
  for (int i = 0; i < n; ++i) {
    b[i] = a[k++] * 2.0;
    b[i] += a[k++] * a[i];
  }
}

DPGEN_KERNEL void fill_backwards(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  int k = n;
  for (int i = 0; i < n; ++i)
    b[--k] = a[i] - a[i] * a[i];
}

// A local set before the loop that its increment steps beside the counter
// (`int p = j * nx + 1; for (i = 1; ...; ++i, ++p)`): a companion from its
// value there, stepped also after a `continue`.
DPGEN_KERNEL void row_pointer_index(DPGEN_IN const double* a, DPGEN_OUT double* b, int nx, int ny) {
  for (int j = 1; j < ny - 1; ++j) {
    int p = j * nx + 1;
    for (int i = 1; i < nx - 1; ++i, ++p)
      b[p] = a[p - 1] + a[p + 1] - 2.0 * a[p] * a[p - nx];
  }
}

DPGEN_KERNEL void strided_before(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  int k = 0, m = 2 * n - 1;
  int i;
  for (i = 0; i < n; ++i, k += 2, m -= 2) {
    b[i] = 0.0;
    if (i % 3 == 1)
      continue;
    b[i] = a[k] * a[m];
  }
}
