// arm_locals (tests/styles/): each kernel's adjoint and tangent against the
// checker's differences, then every generated function called on arrays of
// exactly the kernel's sizes (what the sanitizer build checks): the forward
// forms bit for bit against the kernel, the checked adjoints accepting the
// sizes (the generator of session 20 threw "touches elements -1 to ..." for
// left_square), and adjoints by hand where they are short.
#include "support/adjoint_check.hpp"

#include "arm_locals_adjoint.hpp"
#include "arm_locals_kernels.hpp"
#include "arm_locals_tangent.hpp"
#include "dpgen/annotate.hpp"
#include "same_bits.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace {
using dpgen_test::same_values;
using Vec = std::vector<double>;

// (exactly n values, none for n <= 0)
Vec wavy(int n, double phase) { return dpgen_test::wavy(size_t(n > 0 ? n : 0), phase); }
Vec filled(int n, double v) { return Vec(size_t(n > 0 ? n : 0), v); }

// `kernel`, `parallel` and the tangent's primal `tangent(in, dir, out, out_dot)`
// on one input of exactly n values, outputs of exactly m prefilled with NaN:
// bit for bit.
template <typename K, typename P, typename T>
void forward_forms(int n, int m, K kernel, P parallel, T tangent) {
  const Vec a = wavy(n, 0.3), dir = wavy(n, 1.1);
  Vec b = filled(m, std::nan("")), bp = b, bt = b, bd = b;
  kernel(a.data(), b.data());
  parallel(a.data(), bp.data());
  tangent(a.data(), dir.data(), bt.data(), bd.data());
  CHECK(same_values(b, bp));
  CHECK(same_values(b, bt));
}
} // namespace

TEST_CASE("styles: left_square, nested_arms") {
  for (int n : {0, 1, 2, 3, 6, 9}) {
    CAPTURE(n);
    const size_t N = size_t(n);
    dpgen_test::check_one_to_one(
        N, N, [&](auto a, auto b) { left_square(a, b, n); },
        [&](auto a, auto adj, auto seed) { left_square_adjoint(a, adj, seed, n); },
        [&](auto a, auto d, auto b, auto bd) { left_square_tangent(a, d, b, bd, n); });
    dpgen_test::check_one_to_one(
        N, N, [&](auto a, auto b) { nested_arms(a, b, n); },
        [&](auto a, auto adj, auto seed) { nested_arms_adjoint(a, adj, seed, n); },
        [&](auto a, auto d, auto b, auto bd) { nested_arms_tangent(a, d, b, bd, n); });
    forward_forms(
        n, n, [&](auto a, auto b) { left_square(a, b, n); },
        [&](auto a, auto b) { left_square_parallel_forward(a, b, n); },
        [&](auto a, auto d, auto b, auto bd) { left_square_tangent(a, d, b, bd, n); });
    forward_forms(
        n, n, [&](auto a, auto b) { nested_arms(a, b, n); },
        [&](auto a, auto b) { nested_arms_parallel_forward(a, b, n); },
        [&](auto a, auto d, auto b, auto bd) { nested_arms_tangent(a, d, b, bd, n); });
    // by hand, exactly n values: a_adj[i] = 2 a[i] b_adj[i + 1] below n - 1
    const Vec a = wavy(n, 0.7), seed = wavy(n, 2.0);
    Vec adj = filled(n, 0.5), adj_checked = adj;
    left_square_adjoint(a.data(), adj.data(), seed.data(), n);
    left_square_adjoint_checked(a.data(), N, adj_checked.data(), N, seed.data(), N, n);
    for (int i = 0; i < n; ++i)
      CHECK(adj[size_t(i)] ==
            doctest::Approx(0.5 + (i + 1 < n ? 2.0 * a[size_t(i)] * seed[size_t(i) + 1] : 0.0)));
    CHECK(same_values(adj, adj_checked));
    Vec nadj = filled(n, 0.0), nadj_checked = nadj;
    nested_arms_adjoint(a.data(), nadj.data(), seed.data(), n);
    nested_arms_adjoint_checked(a.data(), N, nadj_checked.data(), N, seed.data(), N, n);
    CHECK(same_values(nadj, nadj_checked));
  }
}

TEST_CASE("styles: slope_energy") {
  for (int n : {0, 1, 2, 3, 7}) {
    CAPTURE(n);
    const size_t N = size_t(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {N};
    p.out_sizes = {N, N};
    p.forward = [&](auto in, auto out) { slope_energy(in[0], out[0], out[1], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      slope_energy_adjoint(in[0], adj[0], seed[0], seed[1], n);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto od) {
      slope_energy_tangent(in[0], dir[0], out[0], od[0], out[1], od[1], n);
    };
    dpgen_test::check_adjoint(p);
    const Vec a = wavy(n, 0.1), dir = wavy(n, 0.8), bs = wavy(n, 1.5), es = wavy(n, 2.5);
    Vec b = filled(n, std::nan("")), e = b, bp = b, ep = b, bt = b, et = b, bd = b, ed = b;
    slope_energy(a.data(), b.data(), e.data(), n);
    slope_energy_parallel_forward(a.data(), bp.data(), ep.data(), n);
    slope_energy_tangent(a.data(), dir.data(), bt.data(), bd.data(), et.data(), ed.data(), n);
    CHECK(same_values(b, bp));
    CHECK(same_values(e, ep));
    CHECK(same_values(b, bt));
    CHECK(same_values(e, et));
    Vec adj = filled(n, 0.0), adj_checked = adj;
    slope_energy_adjoint(a.data(), adj.data(), bs.data(), es.data(), n);
    slope_energy_adjoint_checked(a.data(), N, adj_checked.data(), N, bs.data(), N, es.data(), N, n);
    CHECK(same_values(adj, adj_checked));
  }
}

TEST_CASE("styles: masked_exp, a mask that keeps a[i + 1] in bounds") {
  for (int n : {0, 1, 2, 3, 8}) {
    CAPTURE(n);
    const size_t N = size_t(n);
    // the caller's mask: 1 inside, 0 at the last cell (and at cell 2)
    Vec mask = filled(n, 1.0);
    if (n > 0)
      mask[N - 1] = 0.0;
    if (n > 2)
      mask[2] = 0.0;
    dpgen_test::Problem<double> p;
    p.in_sizes = {N};
    p.out_sizes = {N};
    p.forward = [&](auto in, auto out) { masked_exp(in[0], mask.data(), out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      masked_exp_adjoint(in[0], adj[0], mask.data(), seed[0], n);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto od) {
      masked_exp_tangent(in[0], dir[0], mask.data(), out[0], od[0], n);
    };
    dpgen_test::check_adjoint(p);
    forward_forms(
        n, n, [&](auto a, auto e) { masked_exp(a, mask.data(), e, n); },
        [&](auto a, auto e) { masked_exp_parallel_forward(a, mask.data(), e, n); },
        [&](auto a, auto d, auto e, auto ed) { masked_exp_tangent(a, d, mask.data(), e, ed, n); });
    // the tangent by hand: exp(a[i + 1] - a[i]) (d[i + 1] - d[i]) where the mask is set
    const Vec a = wavy(n, 0.4), d = wavy(n, 1.9);
    Vec e = filled(n, 0.0), ed = e;
    masked_exp_tangent(a.data(), d.data(), mask.data(), e.data(), ed.data(), n);
    for (size_t i = 0; i < N; ++i)
      CHECK(ed[i] ==
            doctest::Approx(mask[i] > 0.5 ? std::exp(a[i + 1] - a[i]) * (d[i + 1] - d[i]) : 0.0));
    // the adjoint by hand: exp(a[i] - a[i - 1]) d[i - 1] - exp(a[i + 1] - a[i]) d[i]
    Vec adj = filled(n, 0.0);
    masked_exp_adjoint(a.data(), adj.data(), mask.data(), d.data(), n);
    for (size_t i = 0; i < N; ++i)
      CHECK(adj[i] ==
            doctest::Approx(
                (i > 0 && mask[i - 1] > 0.5 ? std::exp(a[i] - a[i - 1]) * d[i - 1] : 0.0) -
                (mask[i] > 0.5 ? std::exp(a[i + 1] - a[i]) * d[i] : 0.0)));
  }
}

TEST_CASE("styles: last_squared, after_return (one output, guarded by the size)") {
  for (int n : {0, 1, 2, 5}) {
    CAPTURE(n);
    const size_t N = size_t(n);
    for (int k = 0; k < 2; ++k) {
      auto fwd = [&](const double* a, double* out) {
        k == 0 ? last_squared(a, out, n) : after_return(a, out, n);
      };
      auto adjoint = [&](const double* a, double* adj, const double* seed) {
        k == 0 ? last_squared_adjoint(a, adj, seed, n) : after_return_adjoint(a, adj, seed, n);
      };
      auto tangent = [&](const double* a, const double* d, double* out, double* od) {
        k == 0 ? last_squared_tangent(a, d, out, od, n) : after_return_tangent(a, d, out, od, n);
      };
      dpgen_test::check_one_to_one(N, 1, fwd, adjoint, tangent);
      // exactly n values of a and a_adj (none at n = 0)
      const Vec a = wavy(n, 0.6), dir = wavy(n, 1.3);
      Vec out{7.0}, out_t{7.0}, out_dot{7.0}, adj = filled(n, 0.25), adj_checked = adj;
      const double seed = 1.5;
      fwd(a.data(), out.data());
      tangent(a.data(), dir.data(), out_t.data(), out_dot.data());
      CHECK(same_values(out, out_t));
      adjoint(a.data(), adj.data(), &seed);
      if (k == 0) {
        last_squared_adjoint_checked(a.data(), N, adj_checked.data(), N, &seed, 1, n);
        for (size_t i = 0; i < N; ++i)
          CHECK(adj[i] == doctest::Approx(0.25 + (i + 1 == N ? 3.0 * a[i] : 0.0)));
      } else {
        after_return_adjoint_checked(a.data(), N, adj_checked.data(), N, &seed, 1, n);
      }
      CHECK(same_values(adj, adj_checked));
    }
  }
}

TEST_CASE("styles: scaled_by_last, row_below") {
  for (int n : {0, 1, 2, 6}) {
    CAPTURE(n);
    const size_t N = size_t(n);
    dpgen_test::check_one_to_one(
        N, N, [&](auto a, auto b) { scaled_by_last(a, b, n); },
        [&](auto a, auto adj, auto seed) { scaled_by_last_adjoint(a, adj, seed, n); },
        [&](auto a, auto d, auto b, auto bd) { scaled_by_last_tangent(a, d, b, bd, n); });
    forward_forms(
        n, n, [&](auto a, auto b) { scaled_by_last(a, b, n); },
        [&](auto a, auto b) { scaled_by_last_parallel_forward(a, b, n); },
        [&](auto a, auto d, auto b, auto bd) { scaled_by_last_tangent(a, d, b, bd, n); });
    // by hand: a_adj[i] = seed[i] last, and the last cell also sum_j seed[j] a[j]
    Vec adj = filled(n, 0.0);
    const Vec a = wavy(n, 0.2), seed = wavy(n, 0.9);
    scaled_by_last_adjoint(a.data(), adj.data(), seed.data(), n);
    double dot = 0.0;
    for (size_t i = 0; i < N; ++i)
      dot += seed[i] * a[i];
    for (size_t i = 0; i < N; ++i)
      CHECK(adj[i] == doctest::Approx(seed[i] * a[N - 1] + (i + 1 == N ? dot : 0.0)));
    for (int ny : {0, 1, 3}) {
      CAPTURE(ny);
      const int nx = n, cells = nx * ny;
      dpgen_test::check_one_to_one(
          size_t(cells), size_t(cells), [&](auto a, auto b) { row_below(a, b, nx, ny); },
          [&](auto a, auto adj, auto seed) { row_below_adjoint(a, adj, seed, nx, ny); },
          [&](auto a, auto d, auto b, auto bd) { row_below_tangent(a, d, b, bd, nx, ny); });
      forward_forms(
          cells, cells, [&](auto a, auto b) { row_below(a, b, nx, ny); },
          [&](auto a, auto b) { row_below_parallel_forward(a, b, nx, ny); },
          [&](auto a, auto d, auto b, auto bd) { row_below_tangent(a, d, b, bd, nx, ny); });
      // by hand: seed times the row below (1 in row 0), plus the row above's seed times its a
      const Vec a2 = wavy(cells, 0.5), seed2 = wavy(cells, 1.7);
      Vec adj2 = filled(cells, 0.0);
      row_below_adjoint(a2.data(), adj2.data(), seed2.data(), nx, ny);
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
          const size_t c = size_t(j * nx + i), up = c + size_t(nx);
          CHECK(adj2[c] == doctest::Approx(seed2[c] * (j > 0 ? a2[c - size_t(nx)] : 1.0) +
                                           (j + 1 < ny ? seed2[up] * a2[up] : 0.0)));
        }
    }
  }
}

TEST_CASE("styles: relax_left (in place, read back after the arm)") {
  for (int n : {0, 1, 2, 5}) {
    CAPTURE(n);
    const size_t N = size_t(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {N, N};
    p.out_sizes = {N, N};
    p.forward = [&](auto in, auto out) {
      std::copy(in[1], in[1] + N, out[0]);
      relax_left(in[0], out[0], out[1], n);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      Vec u_adj(seed[0], seed[0] + N);
      relax_left_adjoint(in[0], adj[0], in[1], u_adj.data(), seed[1], n);
      for (size_t i = 0; i < N; ++i)
        adj[1][i] += u_adj[i];
    };
    p.tangent = [&](auto in, auto dir, auto out, auto od) {
      std::copy(in[1], in[1] + N, out[0]);
      std::copy(dir[1], dir[1] + N, od[0]);
      relax_left_tangent(in[0], dir[0], out[0], od[0], out[1], od[1], n);
    };
    dpgen_test::check_adjoint(p);
    const Vec a = wavy(n, 0.3), u0 = wavy(n, 1.2), d = wavy(n, 2.2);
    Vec u = u0, f = filled(n, std::nan("")), ut = u0, ft = f, ud = d, fd = f;
    relax_left(a.data(), u.data(), f.data(), n);
    relax_left_tangent(a.data(), d.data(), ut.data(), ud.data(), ft.data(), fd.data(), n);
    CHECK(same_values(u, ut));
    CHECK(same_values(f, ft));
  }
}

TEST_CASE("styles: early_returns, arm_chain, every_sth") {
  for (int n : {0, 1, 2, 3, 8}) {
    CAPTURE(n);
    const size_t N = size_t(n);
    dpgen_test::check_one_to_one(
        N, N, [&](auto a, auto b) { early_returns(a, b, n); },
        [&](auto a, auto adj, auto seed) { early_returns_adjoint(a, adj, seed, n); },
        [&](auto a, auto d, auto b, auto bd) { early_returns_tangent(a, d, b, bd, n); });
    dpgen_test::check_one_to_one(
        N, N, [&](auto a, auto b) { arm_chain(a, b, n); },
        [&](auto a, auto adj, auto seed) { arm_chain_adjoint(a, adj, seed, n); },
        [&](auto a, auto d, auto b, auto bd) { arm_chain_tangent(a, d, b, bd, n); });
    forward_forms(
        n, n, [&](auto a, auto b) { early_returns(a, b, n); },
        [&](auto a, auto b) { early_returns_parallel_forward(a, b, n); },
        [&](auto a, auto d, auto b, auto bd) { early_returns_tangent(a, d, b, bd, n); });
    forward_forms(
        n, n, [&](auto a, auto b) { arm_chain(a, b, n); },
        [&](auto a, auto b) { arm_chain_parallel_forward(a, b, n); },
        [&](auto a, auto d, auto b, auto bd) { arm_chain_tangent(a, d, b, bd, n); });
    // exactly n values: the adjoints read and write nothing outside
    const Vec a = wavy(n, 0.9), seed = wavy(n, 0.1);
    Vec adj = filled(n, 0.0), adj2 = adj;
    early_returns_adjoint(a.data(), adj.data(), seed.data(), n);
    arm_chain_adjoint(a.data(), adj2.data(), seed.data(), n);
    for (int s : {0, 1, 3}) {
      CAPTURE(s);
      const size_t M = s > 0 ? size_t(n / s) : 0;
      dpgen_test::check_one_to_one(
          N, N, [&](auto a, auto b) { every_sth(a, b, n, s); },
          [&](auto a, auto adj, auto seed) { every_sth_adjoint(a, adj, seed, n, s); },
          [&](auto a, auto d, auto b, auto bd) { every_sth_tangent(a, d, b, bd, n, s); });
      Vec b = filled(n, 0.0);
      every_sth(a.data(), b.data(), n, s);
      for (size_t i = 0; i < M; ++i)
        CHECK(b[i] == a[i * size_t(s)] * a[i * size_t(s)]);
    }
  }
}

TEST_CASE("styles: pow2_after_guard, pow2_in_arm, neg_shift_in_arm (shifts, under UBSan)") {
  for (int n : {0, 1, 3, 25}) {
    CAPTURE(n);
    const size_t N = size_t(n);
    for (int sh : {-2, 0, 2, 40}) {
      CAPTURE(sh);
      dpgen_test::check_one_to_one(
          N, N, [&](auto a, auto b) { pow2_after_guard(a, b, n, sh); },
          [&](auto a, auto adj, auto seed) { pow2_after_guard_adjoint(a, adj, seed, n, sh); },
          [&](auto a, auto d, auto b, auto bd) { pow2_after_guard_tangent(a, d, b, bd, n, sh); });
      forward_forms(
          n, n, [&](auto a, auto b) { pow2_after_guard(a, b, n, sh); },
          [&](auto a, auto b) { pow2_after_guard_parallel_forward(a, b, n, sh); },
          [&](auto a, auto d, auto b, auto bd) { pow2_after_guard_tangent(a, d, b, bd, n, sh); });
    }
    dpgen_test::check_one_to_one(
        N, N, [&](auto a, auto b) { neg_shift_in_arm(a, b, n); },
        [&](auto a, auto adj, auto seed) { neg_shift_in_arm_adjoint(a, adj, seed, n); },
        [&](auto a, auto d, auto b, auto bd) { neg_shift_in_arm_tangent(a, d, b, bd, n); });
    forward_forms(
        n, n, [&](auto a, auto b) { neg_shift_in_arm(a, b, n); },
        [&](auto a, auto b) { neg_shift_in_arm_parallel_forward(a, b, n); },
        [&](auto a, auto d, auto b, auto bd) { neg_shift_in_arm_tangent(a, d, b, bd, n); });
    dpgen_test::check_one_to_one(
        N, N, [&](auto a, auto b) { pow2_in_arm(a, b, n); },
        [&](auto a, auto adj, auto seed) { pow2_in_arm_adjoint(a, adj, seed, n); },
        [&](auto a, auto d, auto b, auto bd) { pow2_in_arm_tangent(a, d, b, bd, n); });
    forward_forms(
        n, n, [&](auto a, auto b) { pow2_in_arm(a, b, n); },
        [&](auto a, auto b) { pow2_in_arm_parallel_forward(a, b, n); },
        [&](auto a, auto d, auto b, auto bd) { pow2_in_arm_tangent(a, d, b, bd, n); });
  }
}

TEST_CASE("styles: cond_on_arm_value, damp_by_right (conditions on an arm's values)") {
  for (int n : {0, 1, 2, 3, 8}) {
    CAPTURE(n);
    const size_t N = size_t(n);
    dpgen_test::check_one_to_one(
        N, N, [&](auto a, auto b) { cond_on_arm_value(a, b, n); },
        [&](auto a, auto adj, auto seed) { cond_on_arm_value_adjoint(a, adj, seed, n); },
        [&](auto a, auto d, auto b, auto bd) { cond_on_arm_value_tangent(a, d, b, bd, n); });
    forward_forms(
        n, n, [&](auto a, auto b) { cond_on_arm_value(a, b, n); },
        [&](auto a, auto b) { cond_on_arm_value_parallel_forward(a, b, n); },
        [&](auto a, auto d, auto b, auto bd) { cond_on_arm_value_tangent(a, d, b, bd, n); });
    const Vec a = wavy(n, 0.5), seed = wavy(n, 1.4);
    Vec adj = filled(n, 0.0);
    cond_on_arm_value_adjoint(a.data(), adj.data(), seed.data(), n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {N, N};
    p.out_sizes = {N, N};
    p.forward = [&](auto in, auto out) {
      std::copy(in[1], in[1] + N, out[0]);
      damp_by_right(in[0], out[0], out[1], n);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      Vec u_adj(seed[0], seed[0] + N);
      damp_by_right_adjoint(in[0], adj[0], in[1], u_adj.data(), seed[1], n);
      for (size_t i = 0; i < N; ++i)
        adj[1][i] += u_adj[i];
    };
    p.tangent = [&](auto in, auto dir, auto out, auto od) {
      std::copy(in[1], in[1] + N, out[0]);
      std::copy(dir[1], dir[1] + N, od[0]);
      damp_by_right_tangent(in[0], dir[0], out[0], od[0], out[1], od[1], n);
    };
    dpgen_test::check_adjoint(p);
    // exactly n values: the kernel and the tangent's primal bit for bit
    const Vec u0 = wavy(n, 2.1), d = wavy(n, 0.7);
    Vec u = u0, f = filled(n, std::nan("")), ut = u0, ft = f, ud = d, fd = f;
    damp_by_right(a.data(), u.data(), f.data(), n);
    damp_by_right_tangent(a.data(), d.data(), ut.data(), ud.data(), ft.data(), fd.data(), n);
    CHECK(same_values(u, ut));
    CHECK(same_values(f, ft));
  }
}
