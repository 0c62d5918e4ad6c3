// Hand-written yardsticks for the generated adjoints: a careful gather form
// (what a person writes: branch-free interior, boundaries apart, OpenMP), the
// scatter form general AD tools emit (push each partial into the cell that
// was read; serial, since parallel scatter would race), and peeled forward
// kernels where the kernel as a user wrote it does not vectorize (a boundary
// branch or a periodic conditional index in every iteration).
#pragma once

#include <algorithm>

namespace hand {

// ---- laplacian2d: out[k] = (a[k-1] + a[k+1] + a[k-nx] + a[k+nx] - 4a[k]) / h^2
// inside, 0 on the boundary. Its adjoint is the same stencil applied to the
// seed masked to the interior.
inline void laplacian2d_gather(double* a_adj, const double* g, int nx, int ny, double h) {
  const double c = 1.0 / (h * h);
  auto gi = [&](int i, int j) { // the seed where it exists (interior cells)
    return (i > 0 && i < nx - 1 && j > 0 && j < ny - 1) ? g[j * nx + i] : 0.0;
  };
  auto edge = [&](int i, int j) {
    a_adj[j * nx + i] +=
        c * (gi(i - 1, j) + gi(i + 1, j) + gi(i, j - 1) + gi(i, j + 1) - 4.0 * gi(i, j));
  };
#pragma omp parallel for
  for (int j = 0; j < ny; ++j) {
    if (j < 2 || j >= ny - 2 || nx < 4) {
      for (int i = 0; i < nx; ++i)
        edge(i, j);
      continue;
    }
    edge(0, j), edge(1, j);
    for (int i = 2; i < nx - 2; ++i) {
      const int k = j * nx + i;
      a_adj[k] += c * (g[k - 1] + g[k + 1] + g[k - nx] + g[k + nx] - 4.0 * g[k]);
    }
    edge(nx - 2, j), edge(nx - 1, j);
  }
}

inline void laplacian2d_scatter(double* a_adj, const double* g, int nx, int ny, double h) {
  const double c = 1.0 / (h * h);
  for (int j = 1; j < ny - 1; ++j)
    for (int i = 1; i < nx - 1; ++i) {
      const int k = j * nx + i;
      const double s = c * g[k];
      a_adj[k - 1] += s;
      a_adj[k + 1] += s;
      a_adj[k - nx] += s;
      a_adj[k + nx] += s;
      a_adj[k] -= 4.0 * s;
    }
}

// ---- divergence2d: div[k] = (u[k+1] - u[k-1] + v[k+nx] - v[k-nx]) / 2h inside.
inline void divergence2d_gather(double* u_adj, double* v_adj, const double* g, int nx, int ny,
                                double h) {
  const double c = 1.0 / (2.0 * h);
  auto gi = [&](int i, int j) {
    return (i > 0 && i < nx - 1 && j > 0 && j < ny - 1) ? g[j * nx + i] : 0.0;
  };
  auto edge = [&](int i, int j) {
    u_adj[j * nx + i] += c * (gi(i - 1, j) - gi(i + 1, j));
    v_adj[j * nx + i] += c * (gi(i, j - 1) - gi(i, j + 1));
  };
#pragma omp parallel for
  for (int j = 0; j < ny; ++j) {
    if (j < 2 || j >= ny - 2 || nx < 4) {
      for (int i = 0; i < nx; ++i)
        edge(i, j);
      continue;
    }
    edge(0, j), edge(1, j);
    for (int i = 2; i < nx - 2; ++i) {
      const int k = j * nx + i;
      u_adj[k] += c * (g[k - 1] - g[k + 1]);
      v_adj[k] += c * (g[k - nx] - g[k + nx]);
    }
    edge(nx - 2, j), edge(nx - 1, j);
  }
}

inline void divergence2d_scatter(double* u_adj, double* v_adj, const double* g, int nx, int ny,
                                 double h) {
  const double c = 1.0 / (2.0 * h);
  for (int j = 1; j < ny - 1; ++j)
    for (int i = 1; i < nx - 1; ++i) {
      const int k = j * nx + i;
      const double s = c * g[k];
      u_adj[k + 1] += s;
      u_adj[k - 1] -= s;
      v_adj[k + nx] += s;
      v_adj[k - nx] -= s;
    }
}

// ---- upwind_step (periodic): seed eq. 17 and its gather adjoint (DESIGN.md).
// min/max as conditionals by value, neighbours wrapped only at the two ends.
inline void upwind_gather_cell(const double* d, double* d_adj, const double* u, double* u_adj,
                               const double* g, int j, int jm, int jp, double dt, double dx) {
  const double uj = u[j] / dx, ujm = u[jm] / dx, ujp = u[jp] / dx;
  const double up_j = uj < 0.0 ? uj : 0.0, um_j = uj > 0.0 ? uj : 0.0;
  const double up_jm = ujm < 0.0 ? ujm : 0.0, um_jp = ujp > 0.0 ? ujp : 0.0;
  d_adj[j] += (1.0 + dt * up_j - dt * um_j) * g[j] - dt * up_jm * g[jm] + dt * um_jp * g[jp];
  const double dup = u[j] <= 0.0 ? 1.0 / dx : 0.0, dum = u[j] >= 0.0 ? 1.0 / dx : 0.0;
  u_adj[j] += -dt * (dup * (d[jp] - d[j]) + dum * (d[j] - d[jm])) * g[j];
}

inline void upwind_gather(const double* d, double* d_adj, const double* u, double* u_adj,
                          const double* g, int n, double dt, double dx) {
  if (n == 1) {
    upwind_gather_cell(d, d_adj, u, u_adj, g, 0, 0, 0, dt, dx);
    return;
  }
  upwind_gather_cell(d, d_adj, u, u_adj, g, 0, n - 1, 1, dt, dx);
#pragma omp parallel for
  for (int j = 1; j < n - 1; ++j)
    upwind_gather_cell(d, d_adj, u, u_adj, g, j, j - 1, j + 1, dt, dx);
  upwind_gather_cell(d, d_adj, u, u_adj, g, n - 1, n - 2, 0, dt, dx);
}

inline void upwind_scatter(const double* d, double* d_adj, const double* u, double* u_adj,
                           const double* g, int n, double dt, double dx) {
  for (int i = 0; i < n; ++i) {
    const int ip = i == n - 1 ? 0 : i + 1, im = i == 0 ? n - 1 : i - 1;
    const double upv = std::min(u[i] / dx, 0.0), umv = std::max(u[i] / dx, 0.0);
    const double gi = g[i];
    d_adj[i] += (1.0 + dt * upv - dt * umv) * gi;
    d_adj[ip] += -dt * upv * gi;
    d_adj[im] += dt * umv * gi;
    const double dup = u[i] <= 0.0 ? 1.0 / dx : 0.0, dum = u[i] >= 0.0 ? 1.0 / dx : 0.0;
    u_adj[i] += -dt * (dup * (d[ip] - d[i]) + dum * (d[i] - d[im])) * gi;
  }
}

// ---- peeled forwards: the interior without per-cell branches ---------------

inline void laplacian2d_peeled(const double* a, double* out, int nx, int ny, double h) {
  const double c = 1.0 / (h * h);
  for (int i = 0; i < nx; ++i)
    out[i] = 0.0, out[(ny - 1) * nx + i] = 0.0;
  for (int j = 1; j < ny - 1; ++j) {
    out[j * nx] = 0.0, out[j * nx + nx - 1] = 0.0;
    for (int i = 1; i < nx - 1; ++i) {
      const int k = j * nx + i;
      out[k] = (a[k - 1] + a[k + 1] + a[k - nx] + a[k + nx] - 4.0 * a[k]) * c;
    }
  }
}

inline void divergence2d_peeled(const double* u, const double* v, double* div, int nx, int ny,
                                double h) {
  const double c = 1.0 / (2.0 * h);
  for (int i = 0; i < nx; ++i)
    div[i] = 0.0, div[(ny - 1) * nx + i] = 0.0;
  for (int j = 1; j < ny - 1; ++j) {
    div[j * nx] = 0.0, div[j * nx + nx - 1] = 0.0;
    for (int i = 1; i < nx - 1; ++i) {
      const int k = j * nx + i;
      div[k] = (u[k + 1] - u[k - 1] + v[k + nx] - v[k - nx]) * c;
    }
  }
}

inline double upwind_cell(const double* d, const double* u, int i, int im, int ip, double dt,
                          double dx) {
  const double ui = u[i] / dx;
  const double up = ui < 0.0 ? ui : 0.0, um = ui > 0.0 ? ui : 0.0;
  return d[i] - dt * (up * (d[ip] - d[i]) + um * (d[i] - d[im]));
}

inline void upwind_peeled(const double* d, const double* u, double* out, int n, double dt,
                          double dx) {
  out[0] = upwind_cell(d, u, 0, n - 1, n > 1 ? 1 : 0, dt, dx);
  for (int i = 1; i < n - 1; ++i)
    out[i] = upwind_cell(d, u, i, i - 1, i + 1, dt, dx);
  if (n > 1)
    out[n - 1] = upwind_cell(d, u, n - 1, n - 2, 0, dt, dx);
}

// burgers_step (tests/kernels): u + dt (nu lap(u) - u du/dx), periodic.
inline double burgers_cell(const double* u, int i, int im, int ip, double dt, double dx,
                           double nu) {
  const double adv = u[i] * (u[ip] - u[im]) / (2.0 * dx);
  const double diff = nu * (u[ip] - 2.0 * u[i] + u[im]) / (dx * dx);
  return u[i] + dt * (diff - adv);
}

inline void burgers_peeled(const double* u, double* out, int n, double dt, double dx, double nu) {
  out[0] = burgers_cell(u, 0, n - 1, n > 1 ? 1 : 0, dt, dx, nu);
  for (int i = 1; i < n - 1; ++i)
    out[i] = burgers_cell(u, i, i - 1, i + 1, dt, dx, nu);
  if (n > 1)
    out[n - 1] = burgers_cell(u, n - 1, n - 2, 0, dt, dx, nu);
}

// ---- burgers_step adjoints -----------------------------------------------------
// d out[i]/d u[i] = 1 + dt (-2 nu/dx^2 - (u[ip] - u[im]) / 2dx),
// d out[i]/d u[ip] = dt (nu/dx^2 - u[i] / 2dx), d out[i]/d u[im] = dt (nu/dx^2 + u[i] / 2dx).
inline void burgers_gather_cell(const double* u, double* u_adj, const double* g, int j, int jm,
                                int jp, double dt, double dx, double nu) {
  const double a = nu / (dx * dx), b = 1.0 / (2.0 * dx);
  u_adj[j] += (1.0 + dt * (-2.0 * a - (u[jp] - u[jm]) * b)) * g[j] +
              dt * (a - u[jm] * b) * g[jm] + dt * (a + u[jp] * b) * g[jp];
}

inline void burgers_gather(const double* u, double* u_adj, const double* g, int n, double dt,
                           double dx, double nu) {
  if (n == 1) {
    burgers_gather_cell(u, u_adj, g, 0, 0, 0, dt, dx, nu);
    return;
  }
  burgers_gather_cell(u, u_adj, g, 0, n - 1, 1, dt, dx, nu);
#pragma omp parallel for
  for (int j = 1; j < n - 1; ++j)
    burgers_gather_cell(u, u_adj, g, j, j - 1, j + 1, dt, dx, nu);
  burgers_gather_cell(u, u_adj, g, n - 1, n - 2, 0, dt, dx, nu);
}

inline void burgers_scatter(const double* u, double* u_adj, const double* g, int n, double dt,
                            double dx, double nu) {
  const double a = nu / (dx * dx), b = 1.0 / (2.0 * dx);
  for (int i = 0; i < n; ++i) {
    const int ip = i == n - 1 ? 0 : i + 1, im = i == 0 ? n - 1 : i - 1;
    u_adj[i] += (1.0 + dt * (-2.0 * a - (u[ip] - u[im]) * b)) * g[i];
    u_adj[ip] += dt * (a - u[i] * b) * g[i];
    u_adj[im] += dt * (a + u[i] * b) * g[i];
  }
}

// ---- laplacian3d adjoints (7-point, boundary cells zero) --------------------------
inline void laplacian3d_gather(double* a_adj, const double* g, int nx, int ny, int nz, double h) {
  const double c = 1.0 / (h * h);
  const long plane = static_cast<long>(nx) * ny;
  auto gi = [&](int i, int j, int l) {
    return (i > 0 && i < nx - 1 && j > 0 && j < ny - 1 && l > 0 && l < nz - 1)
               ? g[(static_cast<long>(l) * ny + j) * nx + i]
               : 0.0;
  };
  auto edge = [&](int i, int j, int l) {
    a_adj[(static_cast<long>(l) * ny + j) * nx + i] +=
        c * (gi(i - 1, j, l) + gi(i + 1, j, l) + gi(i, j - 1, l) + gi(i, j + 1, l) +
             gi(i, j, l - 1) + gi(i, j, l + 1) - 6.0 * gi(i, j, l));
  };
#pragma omp parallel for
  for (int l = 0; l < nz; ++l)
    for (int j = 0; j < ny; ++j) {
      if (l < 2 || l >= nz - 2 || j < 2 || j >= ny - 2 || nx < 4) {
        for (int i = 0; i < nx; ++i)
          edge(i, j, l);
        continue;
      }
      edge(0, j, l), edge(1, j, l);
      const long row = (static_cast<long>(l) * ny + j) * nx;
      for (int i = 2; i < nx - 2; ++i) {
        const long k = row + i;
        a_adj[k] += c * (g[k - 1] + g[k + 1] + g[k - nx] + g[k + nx] + g[k - plane] +
                         g[k + plane] - 6.0 * g[k]);
      }
      edge(nx - 2, j, l), edge(nx - 1, j, l);
    }
}

inline void laplacian3d_scatter(double* a_adj, const double* g, int nx, int ny, int nz,
                                double h) {
  const double c = 1.0 / (h * h);
  const long plane = static_cast<long>(nx) * ny;
  for (int l = 1; l < nz - 1; ++l)
    for (int j = 1; j < ny - 1; ++j)
      for (int i = 1; i < nx - 1; ++i) {
        const long k = (static_cast<long>(l) * ny + j) * nx + i;
        const double s = c * g[k];
        a_adj[k - 1] += s, a_adj[k + 1] += s, a_adj[k - nx] += s, a_adj[k + nx] += s;
        a_adj[k - plane] += s, a_adj[k + plane] += s, a_adj[k] -= 6.0 * s;
      }
}

} // namespace hand
