// Kernels whose forward forms split their loops (peel_forward): boundary
// conditions written the ways real code writes them, decided in a
// branch-free interior. tests/kernels/peel_test.cpp checks each forward form
// against the kernel bit for bit, at sizes with and without an interior.
#include "test_kernels.hpp"

#include <algorithm>

// C89: counter declared before the loop, the periodic neighbours by ternaries.
DPGEN_KERNEL void peel_wrap_c89(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  int i;
  for (i = 0; i < n; i++) {
    int l = (i == 0) ? n - 1 : i - 1;
    int r = (i == n - 1) ? 0 : i + 1;
    out[i] = 0.5 * (a[l] + a[r]) - a[i] * a[i];
  }
}

// Periodic in both directions, row-major: the inner loop's wrap is folded,
// the outer one's stays (one value per row).
DPGEN_KERNEL void peel_torus2d(DPGEN_IN const double* a, DPGEN_IN const double* k,
                               DPGEN_OUT double* out, int nx, int ny) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int ip = i + 1 < nx ? i + 1 : 0, im = i > 0 ? i - 1 : nx - 1;
      const int jp = j + 1 < ny ? j + 1 : 0, jm = j > 0 ? j - 1 : ny - 1;
      out[j * nx + i] = k[j * nx + i] * (a[j * nx + ip] + a[j * nx + im] + a[jp * nx + i] +
                                         a[jm * nx + i] - 4.0 * a[j * nx + i]);
    }
}

// Boundary cells set by an if/else: the interior runs the first branch only.
DPGEN_KERNEL void peel_guarded(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, double h) {
  for (int i = 0; i < n; ++i) {
    if (i > 0 && i < n - 1)
      out[i] = (a[i - 1] - 2.0 * a[i] + a[i + 1]) / (h * h);
    else
      out[i] = a[i];
  }
}

// A five-point periodic stencil: two cells at each end are edges.
DPGEN_KERNEL void peel_wide_wrap(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    const int m2 = i < 2 ? i + n - 2 : i - 2;
    const int p2 = i >= n - 2 ? i + 2 - n : i + 2;
    const int m1 = i < 1 ? i + n - 1 : i - 1;
    const int p1 = i >= n - 1 ? i + 1 - n : i + 1;
    out[i] = (-a[m2] + 16.0 * a[m1] - 30.0 * a[i] + 16.0 * a[p1] - a[p2]) / 12.0;
  }
}

// Counted down: not split (kept as the kernel counts).
DPGEN_KERNEL void peel_descending(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = n - 1; i >= 0; --i)
    out[i] = a[i] * (i == n - 1 ? a[0] : a[i + 1]);
}

// A clamped neighbour (std::min/std::max of indices): the ends read themselves.
DPGEN_KERNEL void peel_clamped(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    const int l = std::max(i - 1, 0), r = std::min(i + 1, n - 1);
    out[i] = a[l] - 2.0 * a[i] + a[r];
  }
}

// Walls in y (an if/else on the row), periodic in x: interior rows run one
// branch-free inner loop; the wall rows and the wrap column run as written.
DPGEN_KERNEL void peel_walls2d(DPGEN_IN const double* a, DPGEN_OUT double* out, int nx, int ny) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int ip = i == nx - 1 ? 0 : i + 1;
      if (j == 0 || j == ny - 1)
        out[j * nx + i] = a[j * nx + i];
      else
        out[j * nx + i] = a[j * nx + ip] * a[(j + 1) * nx + i] - a[(j - 1) * nx + i];
    }
}

// A local whose definition the split makes loop-invariant inside (1.0 / dx) while the edges
// keep the condition: it must stay in the loops (a copy moved before them would be shadowed
// by the edges' own: tests/CMakeLists.txt compiles these files with -Wshadow -Werror).
DPGEN_KERNEL void peel_coef(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, double dx) {
  for (int i = 0; i < n; ++i) {
    const double w = (i == 0 || i == n - 1) ? 0.5 / dx : 1.0 / dx;
    out[i] = w * a[i];
  }
}

// Offsets from a loop that starts at 2 and ends at n - 3 inclusive, a clamp nested in a clamp,
// its operands swapped, and a floating-point min that must stay as written.
DPGEN_KERNEL void peel_offsets(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 2; i <= n - 3; ++i) {
    const int l = std::min(std::max(i - 3, 0), n - 1);
    const int r = std::min(n - 1, i + 3);
    out[i] = (i == 2 ? a[i] : a[i - 1]) + (i >= n - 4 ? 0.0 : a[i + 2]) + a[l] * a[r] +
             std::min(a[i], 0.0);
  }
}

// Three loops: the outer and inner split, the middle one (no condition on j) passes the outer
// edge test through.
DPGEN_KERNEL void peel_box3d(DPGEN_IN const double* a, DPGEN_OUT double* out, int nx, int ny,
                             int nz) {
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const long c = (static_cast<long>(k) * ny + j) * nx + i;
        const long e = i == nx - 1 ? c - i : c + 1;
        out[c] = k == 0 ? a[c] : a[c - nx * ny] + a[e];
      }
}

// Counted down in the outer loop, a wrap in the inner one (a parallel nest: its forward forms
// count up, the order being free; peel_column_sums counts down).
DPGEN_KERNEL void peel_descending_rows(DPGEN_IN const double* a, DPGEN_OUT double* out, int nx,
                                       int ny) {
  for (int j = ny - 1; j >= 0; --j)
    for (int i = 0; i < nx; ++i)
      out[j * nx + i] =
          (j == 0 ? 0.0 : a[(j - 1) * nx + i]) + (i == nx - 1 ? a[j * nx] : a[j * nx + i + 1]);
}

// A lower triangle: the inner loop's bound is the outer counter.
DPGEN_KERNEL void peel_triangle(DPGEN_IN const double* a, DPGEN_OUT double* l, int n) {
  for (int i = 0; i < n; ++i)
    for (int j = 0; j <= i; ++j)
      l[i * n + j] = (j == 0 ? a[i] : a[i * n + j - 1]) * (j == i ? 2.0 : 1.0);
}

// A nest that adds (the trapezoid rule's end weights by a condition) runs serially in the
// kernel's order, split like the others; the nest before it is parallel.
DPGEN_KERNEL void peel_trapezoid(DPGEN_IN const double* a, DPGEN_OUT double* twice,
                                 DPGEN_OUT double* sum, int n, double h) {
  for (int i = 0; i < n; ++i)
    twice[i] = 2.0 * a[i];
  sum[0] = 0.0;
  for (int i = 0; i < n; ++i)
    sum[0] += (i == 0 || i == n - 1 ? 0.5 : 1.0) * h * a[i];
}

// A nest that adds, counted down in its outer loop: serial, in the kernel's order (rows from
// the top), its outer loop testing its counter and its inner one split from the wrap.
DPGEN_KERNEL void peel_column_sums(DPGEN_IN const double* a, DPGEN_OUT double* col, int nx,
                                   int ny) {
  for (int i = 0; i < nx; ++i)
    col[i] = 0.0;
  for (int j = ny - 1; j >= 0; --j)
    for (int i = 0; i < nx; ++i)
      col[i] += (j == 0 ? 0.5 : 1.0) * a[j * nx + (i == nx - 1 ? 0 : i + 1)];
}

// The adjoint's edge rows (loop_plan.cpp: CellLoop::row_terms): the stencil's interior starts
// two cells in (i - 2), and the west layer `i < m` is a box the interior's range of i does
// not decide (m is the caller's): an edge row's cell in that range must still check it.
DPGEN_KERNEL void peel_edge_rows(DPGEN_IN const double* a, DPGEN_OUT double* out, int nx, int ny,
                                 int m) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int k = j * nx + i;
      if (i < 2 || i >= nx - 2 || j == 0 || j == ny - 1) {
        out[k] = i < m ? 3.0 * a[k] : 0.0;
        continue;
      }
      out[k] = a[k - 2] - 2.0 * a[k + 1] + 0.5 * a[k + 2] + a[k - nx] * a[k + nx];
    }
}

// Counters named `row` and `col`: the adjoint's generated names (the edge flag `edge_row`, the
// edge-row function) must not meet.
DPGEN_KERNEL void peel_row_col(DPGEN_IN const double* a, DPGEN_OUT double* out, int nrows,
                               int ncols) {
  for (int row = 0; row < nrows; ++row)
    for (int col = 0; col < ncols; ++col) {
      const int k = row * ncols + col;
      if (row == 0 || row == nrows - 1 || col == 0 || col == ncols - 1)
        out[k] = 0.0;
      else
        out[k] = a[k - 1] + a[k + 1] + a[k - ncols] + a[k + ncols] - 4.0 * a[k];
    }
}

// Two inputs whose cell boxes differ by a constant at each end (loop_plan.cpp: near_boxes): a's
// cells are [0, n - 2), b's [1, n). The adjoint runs one loop over [0, n), where a cell
// outside one input's box must write nothing to that input's adjoint.
DPGEN_KERNEL void peel_near_boxes_1d(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                     DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    if (i < 2 || i >= n - 3) {
      out[i] = 0.0;
      continue;
    }
    out[i] = a[i - 2] - 2.0 * a[i + 1] + b[i + 3] * b[i - 1];
  }
}

// A MAC-grid style divergence with a product term: u is read at k and k + 1 (its cells:
// rows [0, ny - 1), every column), v at k and k + nx (every row, columns [0, nx - 1)).
DPGEN_KERNEL void peel_near_boxes_mac(DPGEN_IN const double* u, DPGEN_IN const double* v,
                                      DPGEN_OUT double* div, int nx, int ny, double h) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int k = j * nx + i;
      if (i == nx - 1 || j == ny - 1)
        div[k] = 0.0;
      else
        div[k] = (u[k + 1] - u[k]) / h + (v[k + nx] - v[k]) / h + u[k] * v[k + nx];
    }
}
