// flux_sums (tests/styles/): `+=` statements merged into one store. Adjoint
// and tangent against the checker's differences; the tangent's primal bit for
// bit against the kernel, from outputs that hold values (a `+=` adds to
// them), on inputs whose sums round differently when regrouped. (A nest that
// adds gets no parallel forward.)
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "flux_sums_adjoint.hpp"
#include "flux_sums_kernels.hpp"
#include "flux_sums_tangent.hpp"
#include "same_bits.hpp"

#include <vector>

using dpgen_test::same_values;

namespace {
std::vector<double> wavy(size_t n, double phase) { return dpgen_test::wavy(n, phase, 1e3); }
} // namespace

TEST_CASE("styles: face_sums, row_totals") {
  for (int n : {0, 1, 2, 5}) {
    CAPTURE(n);
    const size_t N = size_t(n);
    dpgen_test::check_one_to_one(
        N + 2, N, [&](auto u, auto r) { face_sums(u, r, n); },
        [&](auto u, auto adj, auto seed) { face_sums_adjoint(u, adj, seed, n); },
        [&](auto u, auto d, auto r, auto rd) { face_sums_tangent(u, d, r, rd, n); });
    dpgen_test::check_one_to_one(
        N * 3, 3, [&](auto u, auto t) { row_totals(u, t, n, 3); },
        [&](auto u, auto adj, auto seed) { row_totals_adjoint(u, adj, seed, n, 3); },
        [&](auto u, auto d, auto t, auto td) { row_totals_tangent(u, d, t, td, n, 3); });
  }
  const int n = 20000;
  const std::vector<double> u = wavy(n + 2, 0.3), d = wavy(n + 2, 1.1), r0 = wavy(n, 2.0);
  std::vector<double> kernel = r0, primal = r0, dot(n, 0.0);
  face_sums(u.data(), kernel.data(), n);
  face_sums_tangent(u.data(), d.data(), primal.data(), dot.data(), n);
  CHECK(same_values(kernel, primal));
  // (the regrouped sum differs somewhere: the check above can fail)
  int regrouped = 0;
  for (int i = 0; i < n; ++i) {
    double a = u[i + 1] - u[i], b = u[i + 2] * u[i + 1], c = i % 2 == 0 ? 0.1 * u[i] : 0.0;
    regrouped += r0[i] + (a + b + c + u[i] / 3.0) != kernel[i];
  }
  CHECK(regrouped > 0);
  const int nx = 300, ny = 40;
  const std::vector<double> v = wavy(nx * ny, 0.7), vd = wavy(nx * ny, 1.9), t0 = wavy(ny, 3.0);
  std::vector<double> tk = t0, tt = t0, td(ny, 0.0);
  row_totals(v.data(), tk.data(), nx, ny);
  row_totals_tangent(v.data(), vd.data(), tt.data(), td.data(), nx, ny);
  CHECK(same_values(tk, tt));
}

TEST_CASE("styles: add_then_set") {
  for (int n : {0, 1, 4}) {
    CAPTURE(n);
    const size_t N = size_t(n);
    dpgen_test::check_one_to_one(
        N, N, [&](auto u, auto r) { add_then_set(u, r, n); },
        [&](auto u, auto adj, auto seed) { add_then_set_adjoint(u, adj, seed, n); },
        [&](auto u, auto d, auto r, auto rd) { add_then_set_tangent(u, d, r, rd, n); });
  }
  // by hand: whatever r held, r = 2 u + u^2 (the old generator added it to r)
  const double u[2] = {1.0, 3.0};
  double r[2] = {100.0, 100.0}, rd[2] = {0.0, 0.0};
  const double d[2] = {1.0, 0.0};
  add_then_set_tangent(u, d, r, rd, 2);
  CHECK(r[0] == 3.0);
  CHECK(r[1] == 15.0);
  CHECK(rd[0] == 4.0);
}
