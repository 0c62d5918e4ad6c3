// nested_escapes (tests/styles/): escapes nested in ifs and switch cases. For
// every kind: adjoint and tangent against the checker's differences, the
// parallel forward bit for bit (outputs prefilled with NaN, so an element
// written where the kernel does not write shows), and the skipped elements by
// hand.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "nested_escapes_adjoint.hpp"
#include "nested_escapes_kernels.hpp"
#include "nested_escapes_tangent.hpp"
#include "same_bits.hpp"

#include <cmath>
#include <cstring>
#include <tuple>
#include <vector>

using dpgen_test::check_one_to_one;

using dpgen_test::same_bits;

TEST_CASE("styles: nested returns and continues") {
  for (int kind : {-1, 0, 1, 2}) {
    for (int n : {0, 1, 2, 3, 7}) {
      CAPTURE(kind);
      CAPTURE(n);
      const size_t N = size_t(n);
#define DPGEN_NESTED_ESCAPES_CHECK(k)                                                              \
  check_one_to_one(                                                                                \
      N, N, [&](auto u, auto v) { k(u, v, n, kind); },                                             \
      [&](auto u, auto adj, auto seed) { k##_adjoint(u, adj, seed, n, kind); },                    \
      [&](auto u, auto d, auto v, auto vd) { k##_tangent(u, d, v, vd, n, kind); });                \
  same_bits(                                                                                       \
      N, N, [&](auto u, auto v) { k(u, v, n, kind); },                                             \
      [&](auto u, auto v) { k##_parallel_forward(u, v, n, kind); })
      DPGEN_NESTED_ESCAPES_CHECK(ret_nested_if);
      DPGEN_NESTED_ESCAPES_CHECK(ret_switch_case);
      DPGEN_NESTED_ESCAPES_CHECK(cont_else_if);
      DPGEN_NESTED_ESCAPES_CHECK(cont_switch_case_if);
      DPGEN_NESTED_ESCAPES_CHECK(store_nested_continue);
      DPGEN_NESTED_ESCAPES_CHECK(edge_store_else_if);
#undef DPGEN_NESTED_ESCAPES_CHECK
      dpgen_test::Problem<double> p;
      p.in_sizes = {N};
      p.out_sizes = {N, N};
      p.forward = [&](auto in, auto out) { ret_between_nests(in[0], out[0], out[1], n, kind); };
      p.adjoint = [&](auto in, auto adj, auto seed) {
        ret_between_nests_adjoint(in[0], adj[0], seed[0], seed[1], n, kind);
      };
      p.tangent = [&](auto in, auto d, auto out, auto od) {
        ret_between_nests_tangent(in[0], d[0], out[0], od[0], out[1], od[1], n, kind);
      };
      dpgen_test::check_adjoint(p);
    }
    for (auto [nx, ny] : {std::tuple{1, 1}, {4, 3}, {5, 5}}) {
      CAPTURE(nx);
      CAPTURE(ny);
      const size_t N = size_t(nx) * size_t(ny);
      check_one_to_one(
          N, N, [&](auto u, auto v) { cont_inner_2d(u, v, nx, ny, kind); },
          [&](auto u, auto adj, auto seed) { cont_inner_2d_adjoint(u, adj, seed, nx, ny, kind); },
          [&](auto u, auto d, auto v, auto vd) {
            cont_inner_2d_tangent(u, d, v, vd, nx, ny, kind);
          });
      same_bits(
          N, N, [&](auto u, auto v) { cont_inner_2d(u, v, nx, ny, kind); },
          [&](auto u, auto v) { cont_inner_2d_parallel_forward(u, v, nx, ny, kind); });
    }
  }
  // By hand: kind 1 with n = 2 returns before the loop (v untouched, no derivative); kind 0
  // with n = 2 writes v = 2 u^2 (derivative 4 u).
  const double u[2] = {0.5, -3.0}, seed[2] = {1.0, 1.0};
  for (int kind : {0, 1}) {
    CAPTURE(kind);
    double v[2] = {7.0, 7.0}, pv[2] = {7.0, 7.0}, adj[2] = {0.0, 0.0};
    ret_nested_if(u, v, 2, kind);
    ret_nested_if_parallel_forward(u, pv, 2, kind);
    ret_nested_if_adjoint(u, adj, seed, 2, kind);
    CHECK(v[1] == (kind == 1 ? 7.0 : 18.0));
    CHECK(pv[1] == v[1]);
    CHECK(adj[0] == doctest::Approx(kind == 1 ? 0.0 : 4.0 * 0.5));
    CHECK(adj[1] == doctest::Approx(kind == 1 ? 0.0 : 4.0 * -3.0));
  }
  // cont_switch_case_if, kind 0: the negative u[1] is skipped, u[0] cubed.
  {
    double v[2] = {7.0, 7.0}, adj[2] = {0.0, 0.0};
    cont_switch_case_if(u, v, 2, 0);
    cont_switch_case_if_adjoint(u, adj, seed, 2, 0);
    CHECK(v[0] == 0.125);
    CHECK(v[1] == 7.0);
    CHECK(adj[0] == doctest::Approx(0.75));
    CHECK(adj[1] == 0.0);
  }
}

TEST_CASE("styles: an escape condition reads a local made in its arm") {
  for (int n : {0, 1, 2, 5, 9}) {
    CAPTURE(n);
    const size_t N = size_t(n);
    check_one_to_one(
        N, N, [&](auto u, auto v) { cont_local_in_arm(u, v, n); },
        [&](auto u, auto adj, auto seed) { cont_local_in_arm_adjoint(u, adj, seed, n); },
        [&](auto u, auto d, auto v, auto vd) { cont_local_in_arm_tangent(u, d, v, vd, n); });
  }
  // On arrays of exactly n elements (the sanitizer build reports a read of u[-1], which the
  // generated code made at i = 0 while the local was defined before the combined condition):
  const std::vector<double> u = {1.0, 0.5, 2.0}, seed = {1.0, 1.0, 1.0};
  std::vector<double> v(3, 7.0), pv(3, 7.0), adj(3, 0.0), vd(3, 0.0);
  cont_local_in_arm(u.data(), v.data(), 3);
  cont_local_in_arm_parallel_forward(u.data(), pv.data(), 3);
  cont_local_in_arm_tangent(u.data(), seed.data(), pv.data(), vd.data(), 3);
  cont_local_in_arm_adjoint(u.data(), adj.data(), seed.data(), 3);
  CHECK(v[0] == 1.0);
  CHECK(v[1] == 7.0); // d = -0.5: skipped
  CHECK(v[2] == 4.0);
  CHECK(pv == v);
  CHECK(adj[0] == 2.0);
  CHECK(adj[1] == 0.0);
  CHECK(adj[2] == 4.0);
}
