// clamp_limiter (tests/styles/): std::clamp with bounds from neighbours
// (lowered as std::min of std::max, which is std::clamp for lo <= hi); the
// inputs in [-1, 1] put a[i] + 2 b[i] below, inside and above [lo, hi] on 30
// cells; nonlinear.
#include "support/adjoint_check.hpp"

#include "clamp_limiter_adjoint.hpp"
#include "clamp_limiter_tangent.hpp"
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void clamp_limiter(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                DPGEN_OUT double* out, int n);

TEST_CASE("styles: clamp_limiter") {
  for (int n : {1, 2, 3, 7, 30}) {
    CAPTURE(n);
    const size_t sn = size_t(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {sn, sn};
    p.out_sizes = {sn};
    p.forward = [&](auto in, auto out) { clamp_limiter(in[0], in[1], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      clamp_limiter_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      clamp_limiter_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1],
                                    in_n[1], seed[0], out_n[0], n);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      clamp_limiter_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
  // The three arms and the two ties, by hand: a = (0, v, 1), b = (., 0.1, .):
  // clamp(v + 0.2, 0, 1) * 0.1; v = -0.2 and 0.8 put v + 0.2 exactly on lo and on hi, where
  // std::clamp returns v itself: the derivative goes to a[1], not to the bound.
  for (double v : {-0.9, -0.2, 0.2, 0.8, 0.9}) {
    CAPTURE(v);
    const double a[3] = {0.0, v, 1.0}, b[3] = {0.0, 0.1, 0.0}, seed[3] = {0.0, 1.0, 0.0};
    double out[3] = {0, 0, 0}, a_adj[3] = {0, 0, 0}, b_adj[3] = {0, 0, 0};
    clamp_limiter(a, b, out, 3);
    clamp_limiter_adjoint(a, a_adj, b, b_adj, seed, 3);
    const double x = v + 0.2;
    const bool below = x < 0.0;
    const bool above = x > 1.0;
    CHECK(out[1] == doctest::Approx((below ? 0.0 : above ? 1.0 : x) * 0.1));
    CHECK(a_adj[0] == doctest::Approx(below ? 0.1 : 0.0)); // lo = a[0]
    CHECK(a_adj[1] == doctest::Approx((below || above) ? 0.0 : 0.1));
    CHECK(a_adj[2] == doctest::Approx(above ? 0.1 : 0.0)); // hi = a[2]
    CHECK(b_adj[1] == doctest::Approx((below || above) ? (below ? 0.0 : 1.0) : x + 0.2));
  }
}
