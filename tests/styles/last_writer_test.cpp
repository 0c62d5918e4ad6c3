// last_writer (tests/styles/): adjoint and tangent of stores in one
// iteration and of later-writer-wins stores, and the forward values they
// must reproduce (the overwritten instances contribute nothing).
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "last_writer_adjoint.hpp"
#include "last_writer_kernels.hpp"
#include "last_writer_tangent.hpp"

TEST_CASE("styles: lw_first_last") {
  for (int n : {1, 2, 9}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n), 2};
    p.forward = [&](auto in, auto out) { lw_first_last(in[0], out[0], out[1], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      lw_first_last_adjoint(in[0], adj[0], seed[0], seed[1], n);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      lw_first_last_tangent(in[0], d[0], out[0], dout[0], out[1], dout[1], n);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: lw_next_guess, lw_stride2_c89") {
  for (int n : {1, 2, 7}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n + 1)};
    p.forward = [&](auto in, auto out) { lw_next_guess(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      lw_next_guess_adjoint(in[0], adj[0], seed[0], n);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      lw_next_guess_tangent(in[0], d[0], out[0], dout[0], n);
    };
    dpgen_test::check_adjoint(p);

    dpgen_test::Problem<double> q;
    q.in_sizes = {size_t(n)};
    q.out_sizes = {size_t(2 * n + 1)};
    q.forward = [&](auto in, auto out) { lw_stride2_c89(in[0], out[0], n); };
    q.adjoint = [&](auto in, auto adj, auto seed) {
      lw_stride2_c89_adjoint(in[0], adj[0], seed[0], n);
    };
    q.tangent = [&](auto in, auto d, auto out, auto dout) {
      lw_stride2_c89_tangent(in[0], d[0], out[0], dout[0], n);
    };
    dpgen_test::check_adjoint(q);
  }
  // Only the last guess stays: K[n] = a[n-1]/2, every other K[j] = a[j]^2;
  // its adjoint at a[j] < n - 1 is the entry's alone.
  const double a[3] = {1.0, 2.0, 3.0};
  double K[4] = {0, 0, 0, 0};
  lw_next_guess(a, K, 3);
  CHECK(K[1] == 4.0);
  CHECK(K[3] == 1.5);
  double a_adj[3] = {0, 0, 0};
  const double seed[4] = {1, 1, 1, 1};
  lw_next_guess_adjoint(a, a_adj, seed, 3);
  CHECK(a_adj[0] == doctest::Approx(2.0));
  CHECK(a_adj[1] == doctest::Approx(4.0));
  CHECK(a_adj[2] == doctest::Approx(6.0 + 0.5));
}

TEST_CASE("styles: lw_guarded_down") {
  for (int n : {2, 3, 8}) {
    CAPTURE(n);
    const size_t N = size_t(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {N};
    p.out_sizes = {N, N + 1, 1};
    p.forward = [&](auto in, auto out) { lw_guarded_down(in[0], out[0], out[1], out[2], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      lw_guarded_down_adjoint(in[0], adj[0], seed[0], seed[1], seed[2], n);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      lw_guarded_down_tangent(in[0], d[0], out[0], dout[0], out[1], dout[1], out[2], dout[2], n);
    };
    dpgen_test::check_adjoint(p);
  }
  // Counting down, the smaller j writes last: L[1] = a[0]^2, not exp(a[1]).
  const double a[3] = {2.0, 0.5, 1.0};
  double K[3], L[4], mid[1];
  lw_guarded_down(a, K, L, mid, 3);
  CHECK(L[1] == 4.0);
  double a_adj[3] = {0, 0, 0};
  const double zK[3] = {0, 0, 0}, sL[4] = {0, 1, 0, 0}, zm[1] = {0};
  lw_guarded_down_adjoint(a, a_adj, zK, sL, zm, 3);
  CHECK(a_adj[0] == doctest::Approx(4.0)); // d(a0^2)/da0
  CHECK(a_adj[1] == 0.0);                  // exp(a[1]) was overwritten
}
