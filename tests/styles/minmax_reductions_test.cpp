// minmax_reductions (tests/styles/): min/max reductions (issue 20), adjoint and
// tangent on random inputs (no ties), and what ties do: the adjoint is split
// equally among the elements equal to the extremum.
#include "support/adjoint_check.hpp"

#include "minmax_reductions_adjoint.hpp"
#include "minmax_reductions_kernels.hpp"
#include "minmax_reductions_tangent.hpp"
#include "dpgen/annotate.hpp"

#include <tuple>

using dpgen_test::check_one_to_one;

TEST_CASE("styles: red_maxnorm") {
  for (int n : {1, 4, 33}) {
    CAPTURE(n);
    check_one_to_one(
        size_t(n), 1, [&](auto* in, auto* out) { red_maxnorm(in, out, n); },
        [&](auto* in, auto* adj, auto* seed) { red_maxnorm_adjoint(in, adj, seed, n); },
        [&](auto* in, auto* d, auto* out, auto* dout) {
          red_maxnorm_tangent(in, d, out, dout, n);
        });
  }
}

TEST_CASE("styles: red_cfl") {
  for (int n : {1, 7, 40}) {
    CAPTURE(n);
    check_one_to_one(
        size_t(n), 1, [&](auto* in, auto* out) { red_cfl(in, out, 0.3, 0.1, n); },
        [&](auto* in, auto* adj, auto* seed) { red_cfl_adjoint(in, adj, seed, 0.3, 0.1, n); },
        [&](auto* in, auto* d, auto* out, auto* dout) {
          red_cfl_tangent(in, d, out, dout, 0.3, 0.1, n);
        });
  }
}

TEST_CASE("styles: red_rowmax_macro, red_min_if_c89") {
  for (auto [nx, ny] : {std::tuple{1, 1}, {3, 5}, {17, 4}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    size_t X = size_t(nx), Y = size_t(ny);
    check_one_to_one(
        X * Y, Y, [&](auto* in, auto* out) { red_rowmax_macro(in, out, nx, ny); },
        [&](auto* in, auto* adj, auto* seed) { red_rowmax_macro_adjoint(in, adj, seed, nx, ny); },
        [&](auto* in, auto* d, auto* out, auto* dout) {
          red_rowmax_macro_tangent(in, d, out, dout, nx, ny);
        });

    check_one_to_one(
        X * Y, 1, [&](auto* in, auto* out) { red_min_if_c89(in, out, nx, ny); },
        [&](auto* in, auto* adj, auto* seed) { red_min_if_c89_adjoint(in, adj, seed, nx, ny); },
        [&](auto* in, auto* d, auto* out, auto* dout) {
          red_min_if_c89_tangent(in, d, out, dout, nx, ny);
        });
  }
}

TEST_CASE("styles: red_two_updates_float") {
  for (int n : {1, 5, 12}) { // (float: a wider gap between the largest products than the FD step needs)
    CAPTURE(n);
    dpgen_test::Problem<float> p;
    p.in_sizes = {size_t(n), size_t(n)};
    p.out_sizes = {1};
    p.forward = [&](auto in, auto out) { red_two_updates_float(in[0], in[1], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      red_two_updates_float_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      red_two_updates_float_tangent(in[0], d[0], in[1], d[1], out[0], dout[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}

// Ties: the adjoint of the extremum is split equally among the elements equal
// to it (and the start value, where it is one of them), whatever their order;
// the tangent is the mean of their directions (the two agree: the dot test).
TEST_CASE("styles: min/max reductions at ties") {
  const double r[6] = {0.5, -2.0, 1.0, 2.0, -2.0, 0.25};
  double err = 0;
  red_maxnorm(r, &err, 6);
  CHECK(err == 2.0);
  double r_adj[6] = {0, 0, 0, 0, 0, 0};
  const double seed = 3.0;
  red_maxnorm_adjoint(r, r_adj, &seed, 6);
  // |r| = 2 at 1, 3, 4: a third each, with the sign of r
  const double want[6] = {0, -1.0, 0, 1.0, -1.0, 0};
  for (int i = 0; i < 6; ++i) {
    CAPTURE(i);
    CHECK(r_adj[i] == doctest::Approx(want[i]));
  }
  const double dir[6] = {1, 1, 1, 1, 1, 1};
  double v = 0, v_dot = 0;
  red_maxnorm_tangent(r, dir, &v, &v_dot, 6);
  CHECK(v == 2.0);
  CHECK(v_dot == doctest::Approx((-1.0 + 1.0 - 1.0) / 3)); // the mean of sign(r_k)·1

  // The start value ties with the data: rowmax = a[j*nx] is one of the ties
  // (the scan starts from it and meets it again at no other index here).
  const double a[4] = {5.0, 5.0, 1.0, 5.0}; // one row of 4: 5 at 0 (start, also a[0]), 1, 3
  double rowmax = 0;
  red_rowmax_macro(a, &rowmax, 4, 1);
  CHECK(rowmax == 25.0); // MAX of the squares from i = 1, started at a[0] = 5 (not squared)
  double a_adj[4] = {0, 0, 0, 0};
  const double one = 1.0;
  red_rowmax_macro_adjoint(a, a_adj, &one, 4, 1);
  // 25 = a[1]^2 = a[3]^2 (the start 5 is below): half each, times 2·a
  CHECK(a_adj[0] == 0.0);
  CHECK(a_adj[1] == doctest::Approx(5.0));
  CHECK(a_adj[3] == doctest::Approx(5.0));
  CHECK(a_adj[2] == 0.0);
}

TEST_CASE("styles: red_jacobi_error, red_colmin_out") {
  for (auto [nx, ny] : {std::tuple{3, 3}, {5, 4}, {9, 7}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    size_t X = size_t(nx), Y = size_t(ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {X * Y, X * Y};
    p.out_sizes = {1};
    p.forward = [&](auto in, auto out) { red_jacobi_error(in[0], in[1], out[0], nx, ny, 0.5); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      red_jacobi_error_adjoint(in[0], adj[0], in[1], adj[1], seed[0], nx, ny, 0.5);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      red_jacobi_error_tangent(in[0], d[0], in[1], d[1], out[0], dout[0], nx, ny, 0.5);
    };
    dpgen_test::check_adjoint(p);

    check_one_to_one(
        X * Y, X, [&](auto* in, auto* out) { red_colmin_out(in, out, nx, ny); },
        [&](auto* in, auto* adj, auto* seed) { red_colmin_out_adjoint(in, adj, seed, nx, ny); },
        [&](auto* in, auto* d, auto* out, auto* dout) {
          red_colmin_out_tangent(in, d, out, dout, nx, ny);
        });
  }
}

TEST_CASE("styles: red_limits_and_cond") {
  for (int n : {1, 2, 7}) {
    CAPTURE(n);
    check_one_to_one(
        size_t(n), 3, [&](auto* in, auto* out) { red_limits_and_cond(in, out, n); },
        [&](auto* in, auto* adj, auto* seed) { red_limits_and_cond_adjoint(in, adj, seed, n); },
        [&](auto* in, auto* d, auto* out, auto* dout) {
          red_limits_and_cond_tangent(in, d, out, dout, n);
        });
  }
}

TEST_CASE("styles: red_range_two_elements") {
  for (int n : {1, 2, 9}) {
    CAPTURE(n);
    check_one_to_one(
        size_t(n), 2, [&](auto* in, auto* out) { red_range_two_elements(in, out, n); },
        [&](auto* in, auto* adj, auto* seed) { red_range_two_elements_adjoint(in, adj, seed, n); },
        [&](auto* in, auto* d, auto* out, auto* dout) {
          red_range_two_elements_tangent(in, d, out, dout, n);
        });
  }
}

TEST_CASE("styles: red_user_helpers") {
  for (int n : {2, 3, 12}) {
    CAPTURE(n);
    check_one_to_one(
        size_t(n), 2, [&](auto* in, auto* out) { red_user_helpers(in, out, n); },
        [&](auto* in, auto* adj, auto* seed) { red_user_helpers_adjoint(in, adj, seed, n); },
        [&](auto* in, auto* d, auto* out, auto* dout) {
          red_user_helpers_tangent(in, d, out, dout, n);
        });
  }
}

TEST_CASE("styles: red_list_updates") {
  for (int n : {1, 2, 6, 31}) {
    CAPTURE(n);
    const size_t sn = size_t(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {sn, sn};
    p.out_sizes = {1, 1};
    p.forward = [&](auto in, auto out) { red_list_updates(in[0], in[1], out[0], out[1], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      red_list_updates_adjoint(in[0], adj[0], in[1], adj[1], seed[0], seed[1], n);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      red_list_updates_tangent(in[0], d[0], in[1], d[1], out[0], dout[0], out[1], dout[1], n);
    };
    dpgen_test::check_adjoint(p);
  }
  // A tie inside one list: a = 2, b = 2 gives a b = a + b = 4 = m; the derivative of m^2 = 16
  // (2 m = 8) is split between the two terms: 4 (b + 1) = 12 to a, 4 (a + 1) = 12 to b.
  const double a[1] = {2.0}, b[1] = {2.0}, seed_hi = 1.0, seed_lo = 0.0;
  double hi = 0.0, lo = 0.0, a_adj[1] = {0.0}, b_adj[1] = {0.0};
  red_list_updates(a, b, &hi, &lo, 1);
  CHECK(hi == 16.0);
  red_list_updates_adjoint(a, a_adj, b, b_adj, &seed_hi, &seed_lo, 1);
  CHECK(a_adj[0] == doctest::Approx(12.0));
  CHECK(b_adj[0] == doctest::Approx(12.0));
}
