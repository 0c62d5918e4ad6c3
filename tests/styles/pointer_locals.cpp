// pointer_locals (tests/styles/): pointers into the kernel's arrays made once and indexed
// after, the way C and C++ stencil codes walk rows and planes: a row pointer per input and
// output, rows above and below from `&a[...]` and `row - nx`, `*(row + i)`, a helper given
// `a + j * nx`, plane then row pointers in 3D, a sum into `*total` of an output element, a
// lambda reading captured row pointers, and a pointer one past the first element indexed
// at -1. Each element read or written through a pointer is the parameter's element at the
// pointer's offset plus the index; the generated code names the parameters only. Before,
// every one of these was refused ("local 'row' of type 'const double *' is outside the
// kernel subset", "pointer arithmetic is outside the kernel subset").
#include "dpgen/annotate.hpp"

#include <cmath>
#include <cstddef>

// One pointer per row of the input and of the output.
DPGEN_KERNEL void rows_in_out(DPGEN_IN const double* a, DPGEN_OUT double* b, int nx, int ny) {
  for (int j = 0; j < ny; ++j) {
    const double* row = a + j * nx;
    double* out = b + j * nx;
    for (int i = 0; i < nx; ++i)
      out[i] = row[i] * std::sin(row[i]);
  }
}

// A 5-point Laplacian over the interior: the rows above and below from `&a[...]` and from
// the middle row's pointer; the output row from `&b[...]`.
DPGEN_KERNEL void laplace_rows(DPGEN_IN const double* a, DPGEN_OUT double* b, int nx, int ny,
                               double inv_h2) {
  for (int j = 1; j < ny - 1; ++j) {
    const double* mid = &a[j * nx];
    const double* up = mid + nx;
    const double* down = mid - nx;
    double* out = &b[j * nx];
    for (int i = 1; i < nx - 1; ++i)
      out[i] = (up[i] + down[i] + mid[i - 1] + mid[i + 1] - 4.0 * mid[i]) * inv_h2 * mid[i];
  }
}

// `*(row + i)`, C's way of writing row[i].
DPGEN_KERNEL void deref_sums(DPGEN_IN const double* a, DPGEN_OUT double* b, int nx, int ny) {
  for (int j = 0; j < ny; ++j) {
    const double* row = a + j * nx;
    for (int i = 0; i < nx; ++i)
      *(b + j * nx + i) = *(row + i) * *(row + i) + 0.5 * *(row + i);
  }
}

namespace {
// A helper over one row, called with pointers to the row's first elements.
void smooth_row(const double* in, double* out, int n) {
  out[0] = in[0];
  for (int i = 1; i < n - 1; ++i)
    out[i] = 0.25 * in[i - 1] + 0.5 * in[i] * in[i] + 0.25 * in[i + 1];
  out[n - 1] = in[n - 1];
}
} // namespace

DPGEN_KERNEL void helper_rows(DPGEN_IN const double* a, DPGEN_OUT double* b, int nx, int ny) {
  for (int j = 0; j < ny; ++j)
    smooth_row(a + j * nx, &b[j * nx], nx);
}

// 3D: a plane pointer, then a row pointer into the plane.
DPGEN_KERNEL void planes_rows(DPGEN_IN const double* a, DPGEN_OUT double* b, int nx, int ny,
                              int nz) {
  for (int k = 0; k < nz; ++k) {
    const double* plane = a + std::ptrdiff_t(k) * nx * ny;
    double* out_plane = b + std::ptrdiff_t(k) * nx * ny;
    for (int j = 0; j < ny; ++j) {
      const double* row = plane + j * nx;
      double* out = out_plane + j * nx;
      for (int i = 0; i < nx; ++i)
        out[i] = std::exp(-row[i] * row[i]);
    }
  }
}

// A sum into an output element through a pointer to it.
DPGEN_KERNEL void total_through_pointer(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  double* total = &e[0];
  *total = 0.0;
  for (int i = 0; i < n; ++i)
    *total += a[i] * a[i] * a[i];
}

// A lambda reading the row pointers it captured by reference.
DPGEN_KERNEL void lambda_rows(DPGEN_IN const double* a, DPGEN_IN const double* c,
                              DPGEN_OUT double* b, int nx, int ny) {
  for (int j = 0; j < ny; ++j) {
    const double* ra = a + j * nx;
    const double* rc = c + j * nx;
    auto cell = [&](int i) { return ra[i] * rc[i] + std::tanh(rc[i]); };
    for (int i = 0; i < nx; ++i)
      b[j * nx + i] = cell(i);
  }
}

// A pointer to the second element, indexed from -1: differences of neighbours.
DPGEN_KERNEL void shifted_base(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  const double* next = a + 1;
  for (int i = 0; i < n - 1; ++i)
    b[i] = next[i] * next[i] - next[i - 1];
}

// C casts that keep the element type, as C code spells its row pointers.
DPGEN_KERNEL void c_casts(DPGEN_IN const double* a, DPGEN_OUT double* b, int nx, int ny) {
  int i, j;
  for (j = 0; j < ny; j++) {
    const double* r = (const double*)(a + j * nx);
    double* o = (double*)&b[j * nx];
    for (i = 0; i < nx; i++)
      o[i] = r[i] * r[i] - 0.5 * r[i];
  }
}

// Const references to the input's elements, as C++ codes name neighbours (also through a
// row pointer and `const auto&`): locals of their values, the input never changing.
DPGEN_KERNEL void ref_neighbours(DPGEN_IN const double* a, DPGEN_OUT double* b, int nx, int ny) {
  for (int j = 0; j < ny; ++j) {
    const double* row = a + j * nx;
    for (int i = 1; i < nx - 1; ++i) {
      const double& w = row[i - 1];
      const auto& c = a[j * nx + i];
      const double& e = *(row + i + 1);
      b[j * nx + i] = (w - 2.0 * c + e) * c;
    }
  }
}
