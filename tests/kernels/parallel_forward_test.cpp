// <kernel>_parallel_forward (the adjoint files): the shipped kernels printed from their IR with
// the nests that set each element once on every thread. On grids above the threshold (8192
// iterations), on 1 and on 2 threads, each must give the kernel's values bit for bit: the
// flow solver's forward and the torch ops call it instead of the kernel.
#include "divergence2d_adjoint.hpp"
#include "divergence2d_kernels.hpp"
#include "flow2d_adjoint.hpp"
#include "flow2d_kernels.hpp"
#include "laplacian2d_adjoint.hpp"
#include "laplacian2d_kernels.hpp"
#include "upwind_step_adjoint.hpp"
#include "upwind_step_kernels.hpp"

#include <doctest/doctest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <random>
#include <vector>

namespace {

std::vector<double> random_values(size_t n, unsigned seed, double lo = -1.0, double hi = 1.0) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> dist(lo, hi);
  std::vector<double> v(n);
  for (auto& x : v)
    x = dist(gen);
  return v;
}

// The output of `kernel` and of `parallel` (same arguments, output buffers prefilled with NaN:
// an element one writes and the other does not shows), on `threads` threads, bit for bit.
void same_bits(const char* what, size_t out_size,
               const std::function<void(double*)>& kernel,
               const std::function<void(double*)>& parallel) {
  for (int threads : {1, 2}) {
    CAPTURE(what);
    CAPTURE(threads);
    omp_set_num_threads(threads);
    std::vector<double> a(out_size, std::nan("")), b(out_size, std::nan(""));
    kernel(a.data());
    parallel(b.data());
    CHECK(std::memcmp(a.data(), b.data(), sizeof(double) * out_size) == 0);
  }
}

} // namespace

TEST_CASE("parallel forward: the shipped kernels' values, bit for bit") {
  const int n = 1 << 15, nx = 192, ny = 160; // above the threshold of 8192 iterations
  const auto d = random_values(n, 1), u = random_values(n, 2);
  same_bits(
      "upwind_step", n, [&](double* out) { upwind_step(d.data(), u.data(), out, n, 0.3, 0.7); },
      [&](double* out) { upwind_step_parallel_forward(d.data(), u.data(), out, n, 0.3, 0.7); });
  const size_t cells = size_t(nx) * ny;
  const auto a = random_values(cells, 3), b = random_values(cells, 4);
  same_bits(
      "laplacian2d", cells, [&](double* out) { laplacian2d(a.data(), out, nx, ny, 0.5); },
      [&](double* out) { laplacian2d_parallel_forward(a.data(), out, nx, ny, 0.5); });
  same_bits(
      "divergence2d", cells,
      [&](double* out) { divergence2d(a.data(), b.data(), out, nx, ny, 0.5); },
      [&](double* out) { divergence2d_parallel_forward(a.data(), b.data(), out, nx, ny, 0.5); });
  // the flow solver's MAC grid: u on ny x (nx + 1) faces, v on (ny + 1) x nx
  const size_t uf = size_t(ny) * (nx + 1), vf = size_t(ny + 1) * nx;
  const auto fu = random_values(uf, 5, -2.0, 2.0), fv = random_values(vf, 6, -2.0, 2.0);
  const auto s = random_values(cells, 7), inflow = random_values(cells, 8, 0.0, 0.1);
  for (int periodic : {0, 1}) {
    CAPTURE(periodic);
    same_bits(
        "flow_advect_marker", cells,
        [&](double* out) {
          flow_advect_marker(s.data(), fu.data(), fv.data(), inflow.data(), out, nx, ny, 0.4,
                             periodic, 1 - periodic);
        },
        [&](double* out) {
          flow_advect_marker_parallel_forward(s.data(), fu.data(), fv.data(), inflow.data(), out,
                                              nx, ny, 0.4, periodic, 1 - periodic);
        });
    same_bits(
        "flow_advect_u", uf,
        [&](double* out) {
          flow_advect_u(fu.data(), fv.data(), out, nx, ny, 0.4, periodic, 1 - periodic, 1);
        },
        [&](double* out) {
          flow_advect_u_parallel_forward(fu.data(), fv.data(), out, nx, ny, 0.4, periodic,
                                         1 - periodic, 1);
        });
    same_bits(
        "flow_divergence", cells,
        [&](double* out) {
          flow_divergence(fu.data(), fv.data(), out, nx, ny, 0.5, periodic, 1 - periodic);
        },
        [&](double* out) {
          flow_divergence_parallel_forward(fu.data(), fv.data(), out, nx, ny, 0.5, periodic,
                                           1 - periodic);
        });
    // the pressure solve's operator (the multigrid applies the parallel form by row strips,
    // also on grids below the threshold and on single rows)
    for (auto [mx, my] : {std::pair{nx, ny}, {2, 2}, {3, 5}, {7, 1}, {1, 4}}) {
      CAPTURE(mx);
      CAPTURE(my);
      const double ox = periodic, oy = 1 - periodic;
      same_bits(
          "flow_pressure_operator", size_t(mx) * my,
          [&](double* out) {
            flow_pressure_operator(s.data(), inflow.data(), out, mx, my, 0.5, ox, oy);
          },
          [&](double* out) {
            flow_pressure_operator_parallel_forward(s.data(), inflow.data(), out, mx, my, 0.5, ox,
                                                    oy);
          });
    }
  }
}

// The generated adjoints' parallel branch (above 8192 cells: `if (parallel_ok)`, the outer
// loop of a 2D adjoint a lambda per row that returns early on an edge row) against the
// forward, by the dot-product test <w, J v> = <J^T w, v> of the linear kernels, on 2 threads.
TEST_CASE("adjoints above the threshold: dot-product test on 2 threads") {
  const int nx = 192, ny = 160, n = nx * ny;
  omp_set_num_threads(2);
  const auto v = random_values(size_t(n), 11), v2 = random_values(size_t(n), 12),
             w = random_values(size_t(n), 13), u = random_values(size_t(n), 14);
  const auto dot = [](const std::vector<double>& a, const std::vector<double>& b) {
    double s = 0.0;
    for (size_t i = 0; i < a.size(); ++i)
      s += a[i] * b[i];
    return s;
  };
  const auto near = [](double a, double b) {
    return std::fabs(a - b) <= 1e-12 * std::max(1.0, std::fabs(a));
  };
  std::vector<double> jv(size_t(n), 0.0), jtw(size_t(n), 0.0), jtw2(size_t(n), 0.0);
  {
    laplacian2d(v.data(), jv.data(), nx, ny, 0.5);
    laplacian2d_adjoint(v.data(), jtw.data(), w.data(), nx, ny, 0.5);
    CHECK(near(dot(w, jv), dot(jtw, v)));
  }
  {
    std::fill(jv.begin(), jv.end(), 0.0);
    std::fill(jtw.begin(), jtw.end(), 0.0);
    divergence2d(v.data(), v2.data(), jv.data(), nx, ny, 0.5);
    divergence2d_adjoint(v.data(), jtw.data(), v2.data(), jtw2.data(), w.data(), nx, ny, 0.5);
    CHECK(near(dot(w, jv), dot(jtw, v) + dot(jtw2, v2)));
  }
  {
    // upwind is linear in d for a fixed u: J_d v = upwind(v, u)
    std::fill(jtw.begin(), jtw.end(), 0.0);
    std::fill(jtw2.begin(), jtw2.end(), 0.0);
    upwind_step(v.data(), u.data(), jv.data(), n, 0.3, 0.7);
    upwind_step_adjoint(v.data(), jtw.data(), u.data(), jtw2.data(), w.data(), n, 0.3, 0.7);
    CHECK(near(dot(w, jv), dot(jtw, v)));
  }
}
