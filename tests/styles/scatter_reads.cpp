// Reads at indices that depend on array values, in the styles users write them: a
// semi-Lagrangian trace with bilinear weights (flat 2D arrays, clamped to the grid), a
// lookup through an index array, a float table lookup, a C89 particle gather with
// `unsigned` counters from 1, a lookup under a branch, a 3D nest, and a lambda taking
// the index. Their adjoints are scatter form: each iteration adds its terms at the
// indices it computes (many iterations reach the same elements here), serially, in the
// loop's order (scatter_reads_test.cpp also checks that 1, 2 and 3 threads give the same
// bits: an OpenMP scatter with atomics would not).
#include "dpgen/annotate.hpp"

#include <cmath>

// The marker advection of a smoke solver: each cell traced back by dt * (its velocity),
// clamped to the cell centres, bilinear interpolation.
DPGEN_KERNEL void trace_bilinear(DPGEN_IN const double* s, DPGEN_IN const double* u,
                                 DPGEN_IN const double* v, DPGEN_OUT double* s_out, int nx, int ny,
                                 double dt) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int c = j * nx + i;
      const double x = std::fmin(std::fmax(i - dt * u[c], 0.0), nx - 1.0);
      const double y = std::fmin(std::fmax(j - dt * v[c], 0.0), ny - 1.0);
      const int i0 = x < nx - 1 ? (int)std::floor(x) : nx - 2;
      const int j0 = y < ny - 1 ? (int)std::floor(y) : ny - 2;
      const double fx = x - i0, fy = y - j0;
      s_out[c] = (1.0 - fy) * ((1.0 - fx) * s[j0 * nx + i0] + fx * s[j0 * nx + i0 + 1]) +
                 fy * ((1.0 - fx) * s[(j0 + 1) * nx + i0] + fx * s[(j0 + 1) * nx + i0 + 1]);
    }
}

// A table lookup through an index array (a gather in the forward, a scatter back).
DPGEN_KERNEL void lookup_index(DPGEN_IN const double* w, DPGEN_IN const double* x, const int* idx,
                               DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    out[i] = w[idx[i]] * x[i] + w[idx[i] + 1];
}

// Single precision: the bin of x * scale in a table of m + 1 values, linear between them.
DPGEN_KERNEL void table_float(DPGEN_IN const float* table, DPGEN_IN const float* x,
                              DPGEN_OUT float* out, int n, int m, float scale) {
  for (int i = 0; i < n; ++i) {
    float t = x[i] * scale;
    t = t < 0.0f ? 0.0f : (t > (float)m - 0.5f ? (float)m - 0.5f : t);
    const int b = (int)t;
    const float f = t - (float)b;
    out[i] = (1.0f - f) * table[b] + f * table[b + 1];
  }
}

// C89: counters declared first, `unsigned` loops from 1; a particle's charge read from the
// two cells around its position (the transpose of a deposit).
DPGEN_KERNEL void gather_c89(DPGEN_IN const double* field, DPGEN_IN const double* pos,
                             DPGEN_OUT double* force, unsigned np, unsigned ncell) {
  unsigned p;
  int c;
  double x, w;
  force[0] = 0.0;
  for (p = 1; p < np; ++p) {
    x = pos[p];
    if (x < 0.0)
      x = 0.0;
    if (x > ncell - 1.001)
      x = ncell - 1.001;
    c = (int)x;
    w = x - c;
    force[p] = (1.0 - w) * field[c] + w * field[c + 1];
  }
}

// A lookup only where a condition holds.
DPGEN_KERNEL void lookup_branch(DPGEN_IN const double* t, DPGEN_IN const double* x,
                                DPGEN_OUT double* out, int n, int m) {
  for (int i = 0; i < n; ++i) {
    if (x[i] > 0.0) {
      const int k = (int)(x[i] * 7.0) % m;
      out[i] = t[k] * x[i];
    } else {
      out[i] = 0.0;
    }
  }
}

// Three loops: each column of each plane shifted along z by an amount read from an array.
DPGEN_KERNEL void shift_planes(DPGEN_IN const double* f, DPGEN_IN const double* dz,
                               DPGEN_OUT double* g, int nx, int ny, int nz) {
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const int c = (k * ny + j) * nx + i;
        int kk = k + (int)std::floor(dz[c]);
        kk = kk < 0 ? 0 : (kk > nz - 1 ? nz - 1 : kk);
        g[c] = 0.5 * f[(kk * ny + j) * nx + i] + 0.25 * f[c];
      }
}

// A lambda taking the index, the way a user wraps a periodic access.
DPGEN_KERNEL void lambda_wrap(DPGEN_IN const double* q, DPGEN_IN const double* vel,
                              DPGEN_OUT double* q_next, int n, double dt) {
  auto at = [&](int c) { return q[((c % n) + n) % n]; };
  for (int i = 0; i < n; ++i) {
    const double x = i - dt * vel[i];
    const double fl = std::floor(x);
    const int i0 = (int)fl;
    q_next[i] = (1.0 - (x - fl)) * at(i0) + (x - fl) * at(i0 + 1);
  }
}
