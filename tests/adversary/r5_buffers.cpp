// Adversarial round r5 (issue 20, line buffers): kernels aimed at the
// buffer rules that dpgen accepts; each is checked (dot product, FD, tangent)
// by r5_buffers_test.cpp. The ones it must reject are in
// tests/diagnostics/line_buffers.cpp.
#include "dpgen/annotate.hpp"
#include <cmath>
DPGEN_KERNEL void b01_reverse(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double t[200];
  for (int i = 0; i < n; ++i) t[i] = std::sin(a[i]);
  for (int i = 0; i < n; ++i) out[i] = t[n - 1 - i] * a[i];
}
DPGEN_KERNEL void b02_countdown(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double t[512];
  for (int i = n - 1; i >= 0; --i) t[i] = a[i] * a[i];
  for (int i = 0; i < n - 1; ++i) out[i] = t[i + 1] - t[i];
}
DPGEN_KERNEL void b03_halves(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double t[200];
  const int m = n / 2;
  for (int i = 0; i < m; ++i) t[i] = a[i];
  for (int i = m; i < n; ++i) t[i] = 2.0 * a[i] * a[i];
  for (int i = 0; i < n; ++i) out[i] = t[i];
}
DPGEN_KERNEL void b08_chain(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double t1[150], t2[150];
  for (int i = 0; i < n; ++i) t1[i] = std::exp(a[i]);
  for (int i = 1; i < n - 1; ++i) t2[i] = t1[i - 1] * t1[i + 1];
  for (int i = 1; i < n - 1; ++i) out[i] = t2[i] - a[i];
}
DPGEN_KERNEL void b13_unrolled_taps(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  const double w[3] = {0.25, 0.5, 0.25};
  double t[300];
  for (int i = 0; i < n - 2; ++i) {
    t[i] = 0.0;
    for (int m = 0; m < 3; m++) t[i] += w[m] * a[i + m] * a[i + m];
  }
  for (int i = 1; i < n - 3; ++i) out[i] = t[i - 1] + t[i + 1];
}
DPGEN_KERNEL void b16_two_sizes(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, int m) {
  double t[512];
  for (int i = 0; i < n; ++i) t[i] = a[i] * a[i];
  for (int i = 0; i < m; ++i) out[i] = t[i];
}
DPGEN_KERNEL void b17_local_index(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double t[513];
  for (int i = 0; i < n; ++i) { const int k = i + 1; t[k] = a[i] * a[i]; }
  t[0] = 0.0;
  for (int i = 0; i < n; ++i) out[i] = t[i + 1] - t[i];
}
DPGEN_KERNEL void b05_inner2(DPGEN_IN const double* a, DPGEN_OUT double* out, int nx, int ny) {
  for (int j = 0; j < ny; ++j) {
    double t[512];
    for (int i = 0; i < nx; ++i) t[i] = a[j * nx + i] * a[j * nx + i];
    for (int k = 0; k < 2; ++k)
      for (int i = 0; i < nx; ++i) out[(2 * j + k) * nx + i] = t[i] * (k + 1);
  }
}
DPGEN_KERNEL void b09_3d(DPGEN_IN const double* a, DPGEN_OUT double* out, int nx, int ny) {
  for (int k = 1; k < ny - 1; ++k)
    for (int j = 1; j < ny - 1; ++j) {
      double t[512];
      for (int i = 0; i < nx; ++i) t[i] = a[(k * ny + j) * (long)nx + i] * a[((k - 1) * ny + j) * (long)nx + i];
      for (int i = 1; i < nx - 1; ++i) out[(k * ny + j) * (long)nx + i] = t[i - 1] + t[i + 1] - 2.0 * t[i];
    }
}
DPGEN_KERNEL void b11_rowlevel_only(DPGEN_IN const double* a, DPGEN_OUT double* out, int nx, int ny) {
  for (int j = 0; j < ny; ++j) {
    double t[100];
    t[0] = a[j * nx];
    t[1] = a[j * nx] * a[j * nx];
    out[j] = t[0] * t[1];
  }
}
DPGEN_KERNEL void b18_rows_top_decl(DPGEN_IN const double* a, DPGEN_OUT double* out, int nx, int ny) {
  double t[500];
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) t[i] = std::tanh(a[j * nx + i]);
    for (int i = 0; i < nx; ++i) out[j * nx + i] = t[nx - 1 - i] * t[i];
  }
}
DPGEN_KERNEL void b21_row_counter_index(DPGEN_IN const double* a, DPGEN_OUT double* out, int nx, int ny) {
  for (int j = 0; j < ny; ++j) {
    double t[600];
    for (int i = 0; i < nx; ++i) t[i + j] = a[j * nx + i] * a[j * nx + i];
    for (int i = 0; i < nx; ++i) out[j * nx + i] = t[i + j] + 1.0;
  }
}

DPGEN_KERNEL void c18_acc(DPGEN_IN const double* a, DPGEN_OUT double* out, int nx, int ny) {
  for (int j = 0; j < ny; ++j) {
    double t[512];
    for (int i = 0; i < nx; ++i) t[i] = std::sin(a[j * nx + i]);
    double s = 0;
    for (int i = 0; i < nx; ++i) s += t[i] * t[i];
    out[j] = std::sqrt(1.0 + s);
  }
}
DPGEN_KERNEL void c12_flag(DPGEN_IN const double* a, DPGEN_OUT double* out, int nx, int ny, int flag) {
  for (int j = 0; j < ny; ++j) {
    double t[128];
    if (flag) {
      for (int i = 0; i < nx; ++i) t[i] = a[j * nx + i] * a[j * nx + i];
      for (int i = 0; i < nx; ++i) out[j * nx + i] = t[nx - 1 - i];
    } else {
      for (int i = 0; i < nx; ++i) out[j * nx + i] = a[j * nx + i];
    }
  }
}

// A max reduction over a buffer's values (the reduction's hidden arrays next
// to the buffer's).
DPGEN_KERNEL void m2_maxofbuf(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double t[256];
  for (int i = 0; i < n; ++i) t[i] = a[i] * a[i];
  double m = 0.0;
  for (int i = 0; i < n; ++i) m = std::fmax(m, t[i]);
  out[0] = m;
}
