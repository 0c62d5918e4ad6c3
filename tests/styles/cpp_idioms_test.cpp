// cpp_idioms (tests/styles/): `!=` loop conditions, sizeof for a table's
// length, std::min/std::max of initializer lists. Adjoints and tangents
// against differences and the dot-product test (the sizes start where the
// kernels' own loops end: `i != n - 2` from 2 needs n >= 4); the MC limiter's
// arms and its ties by hand; the median filter's every order of three values.
#include "support/adjoint_check.hpp"

#include "cpp_idioms_adjoint.hpp"
#include "cpp_idioms_kernels.hpp"
#include "cpp_idioms_tangent.hpp"

#include <utility>

TEST_CASE("styles: binomial_smooth") {
  for (int n : {4, 5, 6, 17}) {
    CAPTURE(n);
    const size_t sn = size_t(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {sn};
    p.out_sizes = {sn};
    p.forward = [&](auto in, auto out) { binomial_smooth(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      binomial_smooth_adjoint(in[0], adj[0], seed[0], n);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      binomial_smooth_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      binomial_smooth_tangent(in[0], d[0], out[0], dout[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
  // all five taps: a unit seed at cell 2 of 5 gives 2 v[2]^(1/2) w[k] to u[k]
  const double u[5] = {1.0, 2.0, 3.0, 4.0, 5.0}, seed[5] = {0.0, 0.0, 1.0, 0.0, 0.0};
  double v[5] = {}, adj[5] = {};
  binomial_smooth(u, v, 5);
  binomial_smooth_adjoint(u, adj, seed, 5);
  const double w[5] = {0.0625, 0.25, 0.375, 0.25, 0.0625};
  for (int k = 0; k < 5; ++k)
    CHECK(adj[k] == doctest::Approx(2.0 * 3.0 * w[k])); // (the filtered value is 3)
  CHECK(v[2] == doctest::Approx(9.0));
}

TEST_CASE("styles: mc_slopes") {
  for (int n : {2, 3, 4, 9, 40}) {
    CAPTURE(n);
    const size_t sn = size_t(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {sn};
    p.out_sizes = {sn, sn};
    p.forward = [&](auto in, auto out) { mc_slopes(in[0], out[0], out[1], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      mc_slopes_adjoint(in[0], adj[0], seed[0], seed[1], n);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      mc_slopes_tangent(in[0], d[0], out[0], dout[0], out[1], dout[1], n);
    };
    dpgen_test::check_adjoint(p);
  }
  // Each arm of the min by hand (q = 0, a, a + b): 2|dl| = 2a, |dl + dr|/2, 2|dr| = 2b, and
  // the ties, where the first of the list is the one differentiated.
  struct Case {
    double a, b;
    int arm; // 0: 2|dl|, 1: |dl + dr| / 2, 2: 2|dr|
  };
  for (Case c : {Case{0.1, 1.0, 0}, Case{1.0, 1.0, 1}, Case{1.0, 0.1, 2}, Case{0.25, 0.75, 0},
                 Case{0.75, 0.25, 1}}) {
    CAPTURE(c.a);
    CAPTURE(c.b);
    const double q[3] = {0.0, c.a, c.a + c.b}, seed_s[3] = {0.0, 1.0, 0.0}, seed_t[3] = {};
    double adj[3] = {};
    mc_slopes_adjoint(q, adj, seed_s, seed_t, 3);
    // d/dq of 2 dl = 2 (q1 - q0); (dl + dr) / 2 = (q2 - q0) / 2; 2 dr = 2 (q2 - q1)
    const double want[3][3] = {{-2.0, 2.0, 0.0}, {-0.5, 0.0, 0.5}, {0.0, -2.0, 2.0}};
    for (int k = 0; k < 3; ++k)
      CHECK(adj[k] == doctest::Approx(want[c.arm][k]));
  }
}

TEST_CASE("styles: backward_diff") {
  for (unsigned n : {1u, 2u, 3u, 11u}) {
    CAPTURE(n);
    dpgen_test::Problem<float> p;
    p.in_sizes = {n};
    p.out_sizes = {n};
    p.forward = [&](auto in, auto out) { backward_diff(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      backward_diff_adjoint(in[0], adj[0], seed[0], n);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      backward_diff_tangent(in[0], d[0], out[0], dout[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: median3, median3_helper") {
  for (int n : {1, 2, 3, 8, 31}) {
    CAPTURE(n);
    const size_t sn = size_t(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {sn};
    p.out_sizes = {sn};
    p.forward = [&](auto in, auto out) { median3(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { median3_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      median3_tangent(in[0], d[0], out[0], dout[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
  for (int n : {1, 3, 9, 30}) {
    CAPTURE(n);
    const size_t sn = size_t(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {sn};
    p.out_sizes = {sn};
    p.forward = [&](auto in, auto out) { median3_helper(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      median3_helper_adjoint(in[0], adj[0], seed[0], n);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      median3_helper_tangent(in[0], d[0], out[0], dout[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
  // Each of the six orders of (1, 2, 3): the median, 2, gets the whole derivative 2 |2| = 4.
  const double perms[6][3] = {{1, 2, 3}, {1, 3, 2}, {2, 1, 3}, {2, 3, 1}, {3, 1, 2}, {3, 2, 1}};
  for (const auto& q : perms) {
    const double seed[3] = {0.0, 1.0, 0.0};
    double m[3] = {0, 0, 0}, adj[3] = {0, 0, 0};
    median3(q, m, 3);
    median3_adjoint(q, adj, seed, 3);
    CHECK(m[1] == 4.0);
    for (int k = 0; k < 3; ++k)
      CHECK(adj[k] == (q[k] == 2.0 ? 4.0 : 0.0));
  }
}

TEST_CASE("styles: default_args") {
  for (auto [nx, ny] : {std::pair{1, 1}, {3, 2}, {5, 4}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t n = size_t(nx) * size_t(ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {n};
    p.out_sizes = {n};
    p.forward = [&](auto in, auto out) { default_args(in[0], out[0], nx, ny); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      default_args_adjoint(in[0], adj[0], seed[0], nx, ny);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      default_args_tangent(in[0], d[0], out[0], dout[0], nx, ny);
    };
    dpgen_test::check_adjoint(p);
  }
}
