// Runs adjoints whose interiors share values along strips (the pass `share`) on fixed inputs
// at sizes below, at and above one strip (256 cells) and beyond the threaded loop's threshold
// (8192 cells), and prints every adjoint element as a hexadecimal float (exact): compiled once
// against dpgen's output with the pass and once with `dpgen --no-share`, the two must print the
// same (tests/generator/share_same_bits.py).
#include "shifted_quotients_adjoint.hpp"
#include "twin_limiter_kernels_adjoint.hpp"
#include "upwind_step_adjoint.hpp"

#include <cmath>
#include <cstdio>
#include <vector>

namespace {

template <typename T> std::vector<T> wave(size_t n, double a, double b, double shift = 0.0) {
  std::vector<T> v(n);
  for (size_t i = 0; i < n; ++i)
    v[i] = T(shift + std::sin(a * double(i) + b) + 0.25 * std::cos(3.1 * double(i)));
  return v;
}

template <typename T> void print(const char* what, int n, const std::vector<T>& v) {
  std::printf("%s n=%d\n", what, n);
  for (T x : v)
    std::printf("%a\n", double(x));
}

} // namespace

int main() {
  for (int n : {1, 2, 3, 5, 255, 256, 257, 258, 1000, 8191, 8193, 20011}) {
    const size_t m = size_t(n);
    const auto d = wave<double>(m, 0.7, 0.1), u = wave<double>(m, 1.3, 0.4, -0.1);
    const auto seed = wave<double>(m, 0.31, 1.0);
    for (int active = 0; active < 3; ++active) { // both; d alone; u alone
      std::vector<double> d_adj(m, 0.5), u_adj(m, -0.25);
      upwind_step_adjoint(d.data(), active == 2 ? nullptr : d_adj.data(), u.data(),
                          active == 1 ? nullptr : u_adj.data(), seed.data(), n, 0.1, 0.3);
      print("upwind_step d_adj", n, d_adj);
      print("upwind_step u_adj", n, u_adj);
      std::vector<double> q_adj(m, 0.0), s_adj(m, 0.0);
      centred_speed_adjoint(d.data(), active == 2 ? nullptr : q_adj.data(), u.data(),
                            active == 1 ? nullptr : s_adj.data(), seed.data(), n, 0.4);
      print("centred_speed q_adj", n, q_adj);
      print("centred_speed u_adj", n, s_adj);
      std::vector<double> fq_adj(m, 0.0), fu_adj(m, 0.0); // (u's signs mixed: both upwind cells)
      flux_form_upwind_adjoint(d.data(), active == 2 ? nullptr : fq_adj.data(), u.data(),
                               active == 1 ? nullptr : fu_adj.data(), seed.data(), n, 0.1, 0.3);
      print("flux_form_upwind q_adj", n, fq_adj);
      print("flux_form_upwind u_adj", n, fu_adj);
    }
    std::vector<double> w_adj(m, 0.0);
    mirrored_weights_adjoint(d.data(), w_adj.data(), u.data(), seed.data(), n);
    print("mirrored_weights", n, w_adj);
    std::vector<double> g_adj(m, 0.0);
    gaussian_neighbours_adjoint(d.data(), g_adj.data(), seed.data(), n, 0.7);
    print("gaussian_neighbours", n, g_adj);
    std::vector<double> r_adj(m, 0.0), m_adj(m, 0.0);
    limit_rho_adjoint(d.data(), r_adj.data(), seed.data(), n, 0.5);
    limit_mom_adjoint(u.data(), m_adj.data(), seed.data(), n, 0.5);
    print("limit_rho", n, r_adj);
    print("limit_mom", n, m_adj);
  }
  for (auto [nx, ny] : {std::pair{3, 3}, {7, 4}, {260, 5}, {600, 3}, {300, 30}}) {
    const size_t m = size_t(nx) * size_t(ny);
    const auto phi = wave<float>(m, 0.9, 0.2, 0.3), fseed = wave<float>(m, 0.41, 0.7);
    std::vector<float> phi_adj(m, 0.0f);
    sqrt_conductivity2d_adjoint(phi.data(), phi_adj.data(), fseed.data(), nx, ny, 0.05f);
    print("sqrt_conductivity2d", nx * 1000 + ny, phi_adj);
    const auto a = wave<double>(m, 0.9, 0.2, 0.3), seed = wave<double>(m, 0.41, 0.7);
    std::vector<double> a_adj(m, 0.0);
    ninepoint_weights_adjoint(a.data(), a_adj.data(), seed.data(), nx, ny);
    print("ninepoint_weights", nx * 1000 + ny, a_adj);
  }
  return 0;
}
