// guarded_reads (tests/styles/): each kernel's adjoint and tangent against
// the checker's differences, and every generated function called on arrays of
// exactly the kernel's sizes (what the sanitizer build checks), the forward
// forms bit for bit against the kernel.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "guarded_reads_adjoint.hpp"
#include "guarded_reads_kernels.hpp"
#include "guarded_reads_tangent.hpp"
#include "same_bits.hpp"

#include <vector>

namespace {
// (exactly n values, none for n <= 0)
std::vector<double> wavy(int n, double phase) {
  return dpgen_test::wavy(size_t(n > 0 ? n : 0), phase);
}
} // namespace

TEST_CASE("styles: limiter_after_continue, unit_inner") {
  for (int n : {0, 1, 2, 3, 4, 9}) {
    CAPTURE(n);
    const size_t N = size_t(n);
    dpgen_test::check_one_to_one(
        N, N, [&](auto q, auto s) { limiter_after_continue(q, s, n); },
        [&](auto q, auto adj, auto seed) { limiter_after_continue_adjoint(q, adj, seed, n); },
        [&](auto q, auto d, auto s, auto sd) { limiter_after_continue_tangent(q, d, s, sd, n); });
    dpgen_test::check_one_to_one(
        N, N, [&](auto u, auto v) { unit_inner(u, v, n); },
        [&](auto u, auto adj, auto seed) { unit_inner_adjoint(u, adj, seed, n); },
        [&](auto u, auto d, auto v, auto vd) { unit_inner_tangent(u, d, v, vd, n); });
    // exactly n values each
    const std::vector<double> q = wavy(n, 0.2), d = wavy(n, 0.9);
    std::vector<double> s(N, 5.0), sp(N, 5.0), st(N, 5.0), sd(N, 0.0);
    limiter_after_continue(q.data(), s.data(), n);
    limiter_after_continue_parallel_forward(q.data(), sp.data(), n);
    limiter_after_continue_tangent(q.data(), d.data(), st.data(), sd.data(), n);
    CHECK(s == sp);
    CHECK(s == st);
  }
}

TEST_CASE("styles: guarded_pair") {
  for (int n : {0, 1, 2, 3, 6}) {
    CAPTURE(n);
    const size_t N = size_t(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {N};
    p.out_sizes = {N, 1};
    p.forward = [&](auto in, auto out) { guarded_pair(in[0], out[0], out[1], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      guarded_pair_adjoint(in[0], adj[0], seed[0], seed[1], n);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto od) {
      guarded_pair_tangent(in[0], dir[0], out[0], od[0], out[1], od[1], n);
    };
    dpgen_test::check_adjoint(p);
    // exactly n values of u, u_adj and w_adj
    const std::vector<double> u = wavy(n, 0.4), w_adj = wavy(n, 1.4);
    std::vector<double> u_adj(N, 0.0);
    const double v_adj = 0.5;
    guarded_pair_adjoint(u.data(), u_adj.data(), w_adj.data(), &v_adj, n);
    for (int i = 0; i < n; ++i)
      CHECK(u_adj[size_t(i)] ==
            doctest::Approx(2.0 * u[size_t(i)] *
                            (w_adj[size_t(i)] + (n > 1 && i < 2 ? v_adj : 0.0))));
  }
}
