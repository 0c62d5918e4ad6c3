// wide_constants (tests/styles/): each kernel's adjoint and tangent against the
// checker's differences where they are smooth, the parallel forward bit for
// bit on inputs that make std::sqrt NaN, and the values by hand.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "wide_constants_adjoint.hpp"
#include "wide_constants_kernels.hpp"
#include "wide_constants_tangent.hpp"

#include <cmath>
#include <cstring>
#include <vector>

TEST_CASE("styles: wide_constants") {
  for (int n : {0, 1, 2, 7}) {
    CAPTURE(n);
    const size_t N = size_t(n);
    const unsigned un = unsigned(n);
    dpgen_test::check_one_to_one(
        N, N, [&](auto u, auto v) { big_unsigned_literal(u, v, un); },
        [&](auto u, auto adj, auto seed) { big_unsigned_literal_adjoint(u, adj, seed, un); },
        [&](auto u, auto d, auto v, auto vd) { big_unsigned_literal_tangent(u, d, v, vd, un); });
    dpgen_test::check_one_to_one(
        N, N, [&](auto u, auto v) { copysign_neg_zero(u, v, n); },
        [&](auto u, auto adj, auto seed) { copysign_neg_zero_adjoint(u, adj, seed, n); },
        [&](auto u, auto d, auto v, auto vd) { copysign_neg_zero_tangent(u, d, v, vd, n); });
  }
  // By hand: u = 1.5: u^2 + 3 + 2.147483648; -(u^2 + 0.5) u, derivative -(3 u^2 + 0.5).
  const double u[1] = {1.5}, seed[1] = {1.0};
  double v[1] = {0.0}, pv[1] = {0.0}, adj[1] = {0.0};
  big_unsigned_literal(u, v, 1);
  big_unsigned_literal_parallel_forward(u, pv, 1);
  CHECK(v[0] == doctest::Approx(2.25 + 3.0 + 2.147483648));
  CHECK(pv[0] == v[0]);
  copysign_neg_zero(u, v, 1);
  copysign_neg_zero_parallel_forward(u, pv, 1);
  copysign_neg_zero_adjoint(u, adj, seed, 1);
  CHECK(v[0] == doctest::Approx(-(2.25 + 0.5) * 1.5));
  CHECK(pv[0] == v[0]);
  CHECK(adj[0] == doctest::Approx(-(3.0 * 2.25 + 0.5)));
  // fmax/fmin with a NaN argument: sqrt(-0.8) is NaN, fmax(NaN, 0) = 0 and
  // fmin(u, sqrt(-0.3)) = u; the parallel forward and the tangent's values bit for bit.
  const std::vector<double> w = {-0.8, -0.3, 0.0, 0.4, 2.0, -2.0};
  std::vector<double> a(w.size(), std::nan("")), b(w.size(), std::nan("")),
      c(w.size(), std::nan("")), cd(w.size(), 0.0), dir(w.size(), 1.0);
  fmax_nan_clip(w.data(), a.data(), int(w.size()));
  fmax_nan_clip_parallel_forward(w.data(), b.data(), int(w.size()));
  fmax_nan_clip_tangent(w.data(), dir.data(), c.data(), cd.data(), int(w.size()));
  CHECK(std::memcmp(a.data(), b.data(), sizeof(double) * w.size()) == 0);
  CHECK(std::memcmp(a.data(), c.data(), sizeof(double) * w.size()) == 0);
  CHECK(a[0] == doctest::Approx(-0.8 * -0.8)); // 0 + u * u
  CHECK(a[5] == doctest::Approx(4.0));
  CHECK(cd[0] == doctest::Approx(2.0 * -0.8)); // d(u^2)
  CHECK(cd[4] ==
        doctest::Approx(0.5 / std::sqrt(2.0) + (0.5 / std::sqrt(2.5)) * 2.0 + std::sqrt(2.5)));
}
