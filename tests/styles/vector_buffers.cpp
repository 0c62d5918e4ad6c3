// Local std::vector work arrays, the way C++ codes write temporaries: a vector made with its
// length (and a value), filled by one loop and read by a later one. dpgen reads each as a line
// buffer (tool/lib/lower_buffer.cpp): one row per iteration of the loops around its uses.
#include "dpgen/annotate.hpp"

#include <cmath>
#include <vector>

// Conservative flux form: face fluxes into a vector of n + 1 faces (upwind by the face speed),
// the walls' faces set by hand, then the update from the flux differences.
DPGEN_KERNEL void vector_flux_form(DPGEN_IN const double* q, DPGEN_IN const double* c,
                                   DPGEN_OUT double* q_next, int n, double dt_dx) {
  std::vector<double> flux(n + 1, 0.0);
  flux[0] = 0.0;
  for (int f = 1; f < n; ++f) {
    const double a = 0.5 * (c[f - 1] + c[f]);
    flux[f] = a > 0.0 ? a * q[f - 1] : a * q[f];
  }
  flux[n] = 0.0;
  for (int i = 0; i < n; ++i)
    q_next[i] = q[i] - dt_dx * (flux[i + 1] - flux[i]);
}

// A per-row temporary made inside the row loop (its length only), a nonlinear row filter.
DPGEN_KERNEL void vector_row_filter(DPGEN_IN const double* u, DPGEN_OUT double* v, int nx, int ny) {
  for (int j = 0; j < ny; ++j) {
    std::vector<double> row(nx);
    for (int i = 0; i < nx; ++i)
      row[i] = std::tanh(u[j * nx + i]);
    for (int i = 1; i < nx - 1; ++i)
      v[j * nx + i] = 0.25 * row[i - 1] + 0.5 * row[i] * row[i] + 0.25 * row[i + 1];
  }
}

// Single precision: two vectors, gradient then a product of its neighbours.
DPGEN_KERNEL void vector_float_grad(DPGEN_IN const float* p, DPGEN_OUT float* e, int n, float h) {
  std::vector<float> gx(n), w(n, 1.0f);
  for (int i = 0; i < n - 1; ++i)
    gx[i] = (p[i + 1] - p[i]) / h;
  for (int i = 0; i < n - 1; ++i)
    w[i] = gx[i] * gx[i];
  for (int i = 1; i < n - 1; ++i)
    e[i] = w[i - 1] + gx[i] * w[i];
}

// A gather at a data-dependent index from a std::vector parameter (`a[k]` with k from the
// data; operator[] takes size_type, which k only indexes): the adjoint's scatter form.
DPGEN_KERNEL void vector_gather(DPGEN_IN const std::vector<double>& a,
                                const std::vector<double>& pos, DPGEN_OUT std::vector<double>& out,
                                int n) {
  for (int i = 0; i < n; ++i) {
    const int k = static_cast<int>(std::floor(pos[i]));
    out[i] = a[k] * a[k] + a[k + 1];
  }
}

// The faces counted by the vector's size(), the walls chosen by a ternary.
DPGEN_KERNEL void vector_size_faces(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  std::vector<double> flux(n + 1);
  for (std::size_t f = 0; f < flux.size(); ++f)
    flux[f] = f == 0 || f == std::size_t(n) ? 0.0 : u[f] * u[f] - u[f - 1];
  for (int i = 0; i < n; ++i)
    out[i] = flux[i + 1] - flux[i];
}

// Zero-flux walls left at the value the vector is made with: a finite-volume diffusion step
// whose loop writes the interior faces only (faces 0 and n keep 0.0).
DPGEN_KERNEL void vector_walls_at_zero(DPGEN_IN const double* u, DPGEN_IN const double* k,
                                       DPGEN_OUT double* u_next, int n, double dt) {
  std::vector<double> flux(n + 1, 0.0);
  for (int f = 1; f < n; ++f)
    flux[f] = 0.5 * (k[f - 1] + k[f]) * (u[f] - u[f - 1]);
  for (int i = 0; i < n; ++i)
    u_next[i] = u[i] + dt * (flux[i + 1] - flux[i]);
}

// A prescribed boundary flux: the vector made with an input's value (its gradient flows
// through the faces no loop writes), two loops writing the faces either side of a gap at m.
DPGEN_KERNEL void vector_inflow_value(DPGEN_IN const double* u, DPGEN_IN const double* g,
                                      DPGEN_OUT double* r, int n, int m) {
  std::vector<double> face(n + 1, g[0]);
  for (int f = 1; f < m; ++f)
    face[f] = u[f] * u[f - 1];
  for (int f = m + 1; f < n; ++f)
    face[f] = std::sin(u[f]) - u[f - 1];
  for (int i = 0; i < n; ++i)
    r[i] = face[i + 1] - 2.0 * face[i] * u[i];
}

// Per row of a 2D grid: x-face fluxes in a vector made (zero) inside the row loop, the walls
// left out.
DPGEN_KERNEL void vector_row_walls(DPGEN_IN const double* u, DPGEN_OUT double* out, int nx,
                                   int ny) {
  for (int j = 0; j < ny; ++j) {
    std::vector<double> fx(nx + 1);
    for (int i = 1; i < nx; ++i)
      fx[i] = u[j * nx + i] * u[j * nx + i] - u[j * nx + i - 1];
    for (int i = 0; i < nx; ++i)
      out[j * nx + i] = fx[i + 1] - fx[i];
  }
}

// Elements read into locals (`const double a = v[i + 1];`), and a vector made with the value of
// another vector's element.
DPGEN_KERNEL void vector_reads_in_declarations(DPGEN_IN const double* u, DPGEN_OUT double* r,
                                               int n) {
  std::vector<double> w(n + 1);
  for (int i = 0; i <= n; ++i)
    w[i] = u[i] * u[i];
  std::vector<double> v(n + 1, w[0]);
  for (int i = 1; i < n; ++i)
    v[i] = u[i] + w[i];
  for (int i = 0; i < n; ++i) {
    const double a = v[i + 1];
    const double b = w[i] * v[i];
    r[i] = a * b;
  }
}
