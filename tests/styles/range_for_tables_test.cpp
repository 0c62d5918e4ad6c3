// range_for_tables (tests/styles/): range-based for over local tables; each
// adjoint and tangent against the checker's differences, and one value by
// hand.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "range_for_tables_adjoint.hpp"
#include "range_for_tables_kernels.hpp"
#include "range_for_tables_tangent.hpp"

#include <cmath>

using dpgen_test::check_one_to_one;

TEST_CASE("styles: range_for_tables") {
  for (int n : {0, 1, 3, 5, 6, 12}) {
    CAPTURE(n);
    const size_t N = size_t(n);
    check_one_to_one(
        N, N, [&](auto a, auto b) { smooth_running_offset(a, b, n); },
        [&](auto a, auto adj, auto seed) { smooth_running_offset_adjoint(a, adj, seed, n); },
        [&](auto a, auto d, auto b, auto bd) { smooth_running_offset_tangent(a, d, b, bd, n); });
    check_one_to_one(
        N, N, [&](auto u, auto du) { fd4_constexpr_range(u, du, n, 2.0); },
        [&](auto u, auto adj, auto seed) { fd4_constexpr_range_adjoint(u, adj, seed, n, 2.0); },
        [&](auto u, auto d, auto du, auto dud) {
          fd4_constexpr_range_tangent(u, d, du, dud, n, 2.0);
        });
    check_one_to_one(
        N, N, [&](auto u, auto o) { offsets_table(u, o, n); },
        [&](auto u, auto adj, auto seed) { offsets_table_adjoint(u, adj, seed, n); },
        [&](auto u, auto d, auto o, auto od) { offsets_table_tangent(u, d, o, od, n); });
    check_one_to_one(
        N, N, [&](auto q, auto o) { sum_of_squared_diffs(q, o, n); },
        [&](auto q, auto adj, auto seed) { sum_of_squared_diffs_adjoint(q, adj, seed, n); },
        [&](auto q, auto d, auto o, auto od) { sum_of_squared_diffs_tangent(q, d, o, od, n); });
  }
  // Every element of the table, once each: b[1] = 0.25 a0^2 + 0.5 a1^2 + 0.25 a2^2, and
  // d b[1] / d a[k] = 2 w_k a_k.
  const double a[3] = {1.0, 2.0, 3.0}, seed[3] = {0.0, 1.0, 0.0};
  double b[3] = {0, 0, 0}, adj[3] = {0, 0, 0};
  smooth_running_offset_adjoint(a, adj, seed, 3);
  CHECK(adj[0] == doctest::Approx(0.5 * 1.0));
  CHECK(adj[1] == doctest::Approx(1.0 * 2.0));
  CHECK(adj[2] == doctest::Approx(0.5 * 3.0));
  smooth_running_offset(a, b, 3);
  CHECK(b[1] == doctest::Approx(0.25 + 2.0 + 2.25));
}
