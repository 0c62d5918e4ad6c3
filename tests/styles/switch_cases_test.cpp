// switch_cases (tests/styles/): switch statements lowered to if/else arms,
// and an `if (a || b)` around a nested if. Each kind and direction: the
// adjoint and tangent against the checker's differences, the parallel
// forward against the kernel bit for bit, and the arms' values by hand.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "same_bits.hpp"
#include "switch_cases_adjoint.hpp"
#include "switch_cases_kernels.hpp"
#include "switch_cases_tangent.hpp"

#include <cmath>
#include <cstring>
#include <tuple>
#include <vector>

using dpgen_test::check_one_to_one;

using dpgen_test::same_bits;

TEST_CASE("styles: sweep_switch") {
  for (int dir : {0, 1, 2}) {
    for (auto [nx, ny] : {std::tuple{3, 3}, {5, 4}, {7, 6}}) {
      CAPTURE(dir);
      CAPTURE(nx);
      CAPTURE(ny);
      const size_t N = size_t(nx) * size_t(ny);
      check_one_to_one(
          N, N, [&](auto u, auto f) { sweep_switch(u, f, nx, ny, dir); },
          [&](auto u, auto adj, auto seed) { sweep_switch_adjoint(u, adj, seed, nx, ny, dir); },
          [&](auto u, auto d, auto f, auto fd) { sweep_switch_tangent(u, d, f, fd, nx, ny, dir); });
      same_bits(
          N, N, [&](auto u, auto f) { sweep_switch(u, f, nx, ny, dir); },
          [&](auto u, auto f) { sweep_switch_parallel_forward(u, f, nx, ny, dir); });
    }
  }
}

TEST_CASE("styles: boundary_kinds, or_then_nested, three_colours") {
  for (int kind : {0, 1, 2, 3, -1}) {
    for (int n : {2, 3, 6, 10}) {
      CAPTURE(kind);
      CAPTURE(n);
      const size_t N = size_t(n);
      check_one_to_one(
          N, N, [&](auto u, auto v) { boundary_kinds(u, v, n, kind); },
          [&](auto u, auto adj, auto seed) { boundary_kinds_adjoint(u, adj, seed, n, kind); },
          [&](auto u, auto d, auto v, auto vd) { boundary_kinds_tangent(u, d, v, vd, n, kind); });
      same_bits(
          N, N, [&](auto u, auto v) { boundary_kinds(u, v, n, kind); },
          [&](auto u, auto v) { boundary_kinds_parallel_forward(u, v, n, kind); });
      check_one_to_one(
          N, N, [&](auto u, auto v) { or_then_nested(u, v, n, kind); },
          [&](auto u, auto adj, auto seed) { or_then_nested_adjoint(u, adj, seed, n, kind); },
          [&](auto u, auto d, auto v, auto vd) { or_then_nested_tangent(u, d, v, vd, n, kind); });
      same_bits(
          N, N, [&](auto u, auto v) { or_then_nested(u, v, n, kind); },
          [&](auto u, auto v) { or_then_nested_parallel_forward(u, v, n, kind); });
    }
  }
  for (int n : {0, 1, 2, 3, 4, 9, 14}) {
    CAPTURE(n);
    const size_t N = size_t(n);
    check_one_to_one(
        N, N, [&](auto u, auto w) { three_colours(u, w, n); },
        [&](auto u, auto adj, auto seed) { three_colours_adjoint(u, adj, seed, n); },
        [&](auto u, auto d, auto w, auto wd) { three_colours_tangent(u, d, w, wd, n); });
    same_bits(
        N, N, [&](auto u, auto w) { three_colours(u, w, n); },
        [&](auto u, auto w) { three_colours_parallel_forward(u, w, n); });
  }
  // By hand: or_then_nested on u = (1, 2, 3, 4, 5) with a unit seed on v[4] and on v[1]:
  // kind 0 and 1 give v[4] = u4^2 (derivative 2 u4 = 10) and v[1] = 3 u1 (derivative 3);
  // the other kinds 2 u (derivative 2).
  const double u[5] = {1, 2, 3, 4, 5};
  for (int kind : {0, 1, 2}) {
    CAPTURE(kind);
    const double seed[5] = {0, 1, 0, 0, 1};
    double v[5] = {0, 0, 0, 0, 0}, adj[5] = {0, 0, 0, 0, 0}, pv[5] = {0, 0, 0, 0, 0};
    or_then_nested(u, v, 5, kind);
    or_then_nested_parallel_forward(u, pv, 5, kind);
    or_then_nested_adjoint(u, adj, seed, 5, kind);
    const bool nested = kind == 0 || kind == 1;
    CHECK(v[4] == (nested ? 25.0 : 10.0));
    CHECK(pv[4] == v[4]);
    CHECK(pv[1] == v[1]);
    CHECK(adj[4] == doctest::Approx(nested ? 10.0 : 2.0));
    CHECK(adj[1] == doctest::Approx(nested ? 3.0 : 2.0));
  }
  // boundary_kinds' arms: kind 1 (shares case 0) copies squares inward, kind 2 fixes 0, any
  // other kind is periodic.
  const double b[4] = {1, 2, 3, 4};
  for (int kind : {1, 2, 7}) {
    CAPTURE(kind);
    double v[4] = {-1, -1, -1, -1};
    boundary_kinds(b, v, 4, kind);
    CHECK(v[0] == (kind == 1 ? 4.0 : kind == 2 ? 0.0 : 6.0));
    CHECK(v[3] == (kind == 1 ? 9.0 : kind == 2 ? 0.0 : 6.0));
  }
}
