// local_chains (tests/styles/): each kernel's adjoint and tangent against the
// checker's differences; the parallel forward (for a nest that adds, the
// tangent's primal) bit for bit against the kernel, and the checked adjoint
// on arrays of exactly the kernel's sizes. The generator of session 21 ran out
// of memory on chain14 (std::bad_alloc: its partial printed as a tree of 3^13
// copies of the first local's derivative), on chain_merged_past_arm and on
// conditional_adds (3.8 GB in 9 s), and wrote a 54 KB adjoint file for a
// four-step read-back chain and one small kernel beside it (18 KB now).
// names_like_hoisted checks that the names of the locals this adds stay apart
// from those hoist gives (`inv_d0`).
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "local_chains_adjoint.hpp"
#include "local_chains_kernels.hpp"
#include "local_chains_tangent.hpp"
#include "same_bits.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace {
using dpgen_test::same_values;
using Vec = std::vector<double>;
} // namespace

TEST_CASE("styles: chain14, chain_in_arm") {
  for (int n : {0, 1, 2, 5, 13}) {
    CAPTURE(n);
    const size_t N = size_t(n);
    dpgen_test::check_one_to_one(
        N, N, [&](auto a, auto b) { chain14(a, b, n); },
        [&](auto a, auto adj, auto seed) { chain14_adjoint(a, adj, seed, n); },
        [&](auto a, auto d, auto b, auto bd) { chain14_tangent(a, d, b, bd, n); });
    dpgen_test::check_one_to_one(
        N, N, [&](auto a, auto b) { chain_in_arm(a, b, n); },
        [&](auto a, auto adj, auto seed) { chain_in_arm_adjoint(a, adj, seed, n); },
        [&](auto a, auto d, auto b, auto bd) { chain_in_arm_tangent(a, d, b, bd, n); });
    const Vec a = dpgen_test::wavy(N, 0.4), seed = dpgen_test::wavy(N, 2.0);
    Vec b(N, std::nan("")), bp = b, adj(N, 0.0), adj_checked = adj;
    chain_in_arm(a.data(), b.data(), n);
    chain_in_arm_parallel_forward(a.data(), bp.data(), n);
    CHECK(same_values(b, bp));
    chain_in_arm_adjoint(a.data(), adj.data(), seed.data(), n);
    chain_in_arm_adjoint_checked(a.data(), N, adj_checked.data(), N, seed.data(), N, n);
    CHECK(same_values(adj, adj_checked));
    chain14(a.data(), b.data(), n);
    chain14_parallel_forward(a.data(), bp.data(), n);
    CHECK(same_values(b, bp));
  }
}

TEST_CASE("styles: chain_merged_past_arm, names_like_hoisted") {
  for (int n : {0, 1, 2, 5}) {
    CAPTURE(n);
    const size_t N = size_t(n);
    dpgen_test::check_one_to_one(
        N, N, [&](auto a, auto b) { chain_merged_past_arm(a, b, n); },
        [&](auto a, auto adj, auto seed) { chain_merged_past_arm_adjoint(a, adj, seed, n); },
        [&](auto a, auto d, auto b, auto bd) { chain_merged_past_arm_tangent(a, d, b, bd, n); });
    const double d0 = 3.0;
    dpgen_test::check_one_to_one(
        N, N, [&](auto a, auto b) { names_like_hoisted(a, b, d0, n); },
        [&](auto a, auto adj, auto seed) { names_like_hoisted_adjoint(a, adj, seed, d0, n); },
        [&](auto a, auto d, auto b, auto bd) { names_like_hoisted_tangent(a, d, b, bd, d0, n); });
    const Vec a = dpgen_test::wavy(N, 0.4);
    Vec b(N, std::nan("")), bp = b;
    chain_merged_past_arm(a.data(), b.data(), n);
    chain_merged_past_arm_parallel_forward(a.data(), bp.data(), n);
    CHECK(same_values(b, bp));
  }
}

TEST_CASE("styles: helper_iterates") {
  for (int n : {0, 1, 2, 3, 4, 11}) {
    for (double r : {0.5, 1.5}) {
      CAPTURE(n);
      CAPTURE(r);
      const size_t N = size_t(n);
      dpgen_test::Problem<double> p; // (the logistic map keeps [0, 1] bounded)
      p.in_sizes = {N};
      p.out_sizes = {N};
      p.in_ranges = {{0.0, 1.0}};
      p.forward = [&](auto in, auto out) { helper_iterates(in[0], out[0], r, n); };
      p.adjoint = [&](auto in, auto adj, auto seed) {
        helper_iterates_adjoint(in[0], adj[0], seed[0], r, n);
      };
      p.tangent = [&](auto in, auto dir, auto out, auto outd) {
        helper_iterates_tangent(in[0], dir[0], out[0], outd[0], r, n);
      };
      dpgen_test::check_adjoint(p);
      Vec a = dpgen_test::wavy(N, 0.7);
      for (double& x : a)
        x = 0.5 + 0.5 * x;
      Vec b(N, 0.0), bp = b;
      helper_iterates(a.data(), b.data(), r, n);
      helper_iterates_parallel_forward(a.data(), bp.data(), r, n);
      CHECK(same_values(b, bp));
    }
  }
}

TEST_CASE("styles: lambda_loop") {
  for (int n : {0, 1, 7}) {
    CAPTURE(n);
    const size_t N = size_t(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {N, N};
    p.out_sizes = {N};
    p.in_ranges = {{-0.5, 0.5}, {-0.5, 0.5}};
    p.forward = [&](auto in, auto out) { lambda_loop(in[0], in[1], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      lambda_loop_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      lambda_loop_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: shared_chain_2d") {
  for (auto [nx, ny] : {std::pair{1, 1}, {2, 1}, {5, 3}, {9, 4}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t N = size_t(nx * ny);
    dpgen_test::check_one_to_one(
        N, N, [&](auto u, auto v) { shared_chain_2d(u, v, nx, ny); },
        [&](auto u, auto adj, auto seed) { shared_chain_2d_adjoint(u, adj, seed, nx, ny); },
        [&](auto u, auto d, auto v, auto vd) { shared_chain_2d_tangent(u, d, v, vd, nx, ny); });
    const Vec u = dpgen_test::wavy(N, 0.2), seed = dpgen_test::wavy(N, 1.3);
    Vec v(N, 0.0), vp = v, adj(N, 0.0), adj_checked = adj;
    shared_chain_2d(u.data(), v.data(), nx, ny);
    shared_chain_2d_parallel_forward(u.data(), vp.data(), nx, ny);
    CHECK(same_values(v, vp));
    shared_chain_2d_adjoint(u.data(), adj.data(), seed.data(), nx, ny);
    shared_chain_2d_adjoint_checked(u.data(), N, adj_checked.data(), N, seed.data(), N, nx, ny);
    CHECK(same_values(adj, adj_checked));
  }
}

TEST_CASE("styles: readback_chain, conditional_updates") {
  for (int n : {0, 1, 2, 9}) {
    CAPTURE(n);
    const size_t N = size_t(n);
    dpgen_test::check_one_to_one(
        N, N, [&](auto a, auto b) { readback_chain(a, b, n); },
        [&](auto a, auto adj, auto seed) { readback_chain_adjoint(a, adj, seed, n); },
        [&](auto a, auto d, auto b, auto bd) { readback_chain_tangent(a, d, b, bd, n); });
    dpgen_test::Problem<double> p;
    p.in_sizes = {N};
    p.out_sizes = {N, N};
    p.forward = [&](auto in, auto out) { conditional_updates(in[0], out[0], out[1], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      conditional_updates_adjoint(in[0], adj[0], seed[0], seed[1], n);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      conditional_updates_tangent(in[0], dir[0], out[0], outd[0], out[1], outd[1], n);
    };
    dpgen_test::check_adjoint(p);
    const Vec a = dpgen_test::wavy(N, 0.9);
    Vec b(N, std::nan("")), c = b, bp = b, cp = b, rb = b, rbp = b;
    conditional_updates(a.data(), b.data(), c.data(), n);
    conditional_updates_parallel_forward(a.data(), bp.data(), cp.data(), n);
    CHECK(same_values(b, bp));
    CHECK(same_values(c, cp));
    readback_chain(a.data(), rb.data(), n);
    readback_chain_parallel_forward(a.data(), rbp.data(), n);
    CHECK(same_values(rb, rbp));
  }
}

TEST_CASE("styles: conditional_adds") {
  for (int n : {0, 1, 2, 9}) {
    CAPTURE(n);
    const size_t N = size_t(n);
    dpgen_test::check_one_to_one(
        N, N, [&](auto a, auto d) { conditional_adds(a, d, n); },
        [&](auto a, auto adj, auto seed) { conditional_adds_adjoint(a, adj, seed, n); },
        [&](auto a, auto dir, auto d, auto dd) { conditional_adds_tangent(a, dir, d, dd, n); });
    // (the sums start from what the caller's array holds)
    const Vec a = dpgen_test::wavy(N, 0.9), start = dpgen_test::wavy(N, 0.1);
    Vec d = start, dt = start, dd(N, 0.0);
    conditional_adds(a.data(), d.data(), n);
    conditional_adds_tangent(a.data(), a.data(), dt.data(), dd.data(), n); // (its primal)
    CHECK(same_values(d, dt));
  }
}

TEST_CASE("styles: inplace_stages") {
  for (int n : {0, 1, 6}) {
    CAPTURE(n);
    const size_t N = size_t(n);
    const double dt = 0.05;
    dpgen_test::Problem<double> p;
    p.in_sizes = {N, N}; // u before the stages, f
    p.out_sizes = {N};   // u after them
    p.forward = [&](auto in, auto out) {
      std::copy(in[0], in[0] + N, out[0]);
      inplace_stages(out[0], in[1], dt, n);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      Vec u_adj(seed[0], seed[0] + N); // the seed of the new u in, the old u's adjoint out
      inplace_stages_adjoint(in[0], u_adj.data(), in[1], adj[1], dt, n);
      for (size_t i = 0; i < N; ++i)
        adj[0][i] += u_adj[i];
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      std::copy(in[0], in[0] + N, out[0]);
      std::copy(d[0], d[0] + N, dout[0]);
      inplace_stages_tangent(out[0], dout[0], in[1], d[1], dt, n);
    };
    dpgen_test::check_adjoint(p);
  }
}
