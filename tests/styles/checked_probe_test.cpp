// checked_probe (tests/styles/): the checked entry points of kernels whose
// reach depends on the data. Every array is exactly as long as the test says
// (std::vector, so the sanitizer build sees any access past it): where the data
// keeps the kernel inside a short array, the checked adjoint runs and equals
// the raw one; where the data reaches past it, it throws std::invalid_argument
// naming the array and the element, and writes no adjoint. The adjoints
// themselves are checked against differences and the tangent.
#include "support/adjoint_check.hpp"
#include "support/thrown.hpp"

#include "checked_probe_adjoint.hpp"
#include "checked_probe_kernels.hpp"
#include "checked_probe_tangent.hpp"
#include "same_bits.hpp"

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using dpgen_test::thrown;

bool all_zero(const std::vector<double>& v) {
  for (double x : v)
    if (x != 0.0)
      return false;
  return true;
}

bool has(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

} // namespace

TEST_CASE("checked probe: gather through an index array") {
  const int n = 7;
  const size_t N = size_t(n);
  std::vector<int> idx = {3, 0, 6, 2, 2, 5, 1};
  dpgen_test::check_one_to_one(
      N, N, [&](auto a, auto out) { gather_by_index(a, idx.data(), out, n); },
      [&](auto a, auto adj, auto seed) { gather_by_index_adjoint(a, adj, idx.data(), seed, n); },
      [&](auto a, auto d, auto out, auto od) {
        gather_by_index_tangent(a, d, idx.data(), out, od, n);
      });
  const std::vector<double> a = dpgen_test::wavy(N, 0.3), seed = dpgen_test::wavy(N, 0.8);
  std::vector<double> raw(N, 0.0), checked(N, 0.0);
  gather_by_index_adjoint(a.data(), raw.data(), idx.data(), seed.data(), n);
  gather_by_index_adjoint_checked(a.data(), N, checked.data(), N, idx.data(), N, seed.data(), N, n);
  CHECK(checked == raw);
  // An index past the end of `a` (7 elements): thrown before any adjoint is written.
  idx[4] = 9;
  std::vector<double> adj(N, 0.0);
  std::string m = thrown([&] {
    gather_by_index_adjoint_checked(a.data(), N, adj.data(), N, idx.data(), N, seed.data(), N, n);
  });
  CHECK(has(m, "gather_by_index_adjoint_checked: 'a' has 7 elements, but the kernel touches "
               "element 9 (n = 7)"));
  CHECK(all_zero(adj));
  idx[4] = -1;
  m = thrown([&] {
    gather_by_index_adjoint_checked(a.data(), N, adj.data(), N, idx.data(), N, seed.data(), N, n);
  });
  CHECK(has(m, "touches element -1"));
  CHECK(all_zero(adj));
  // The index array itself is read at 0..n-1, bounded from the loop: too short, the usual message.
  idx[4] = 2;
  m = thrown([&] {
    gather_by_index_adjoint_checked(a.data(), N, adj.data(), N, idx.data(), N - 1, seed.data(), N,
                                    n);
  });
  CHECK(has(m, "'idx' has 6 elements, but the kernel touches elements 0 to 6"));
  // An inactive input (null adjoint of size 0) is still checked through its values.
  std::vector<int> far = {0, 1, 2, 3, 4, 5, 8};
  m = thrown([&] {
    gather_by_index_adjoint_checked(a.data(), N, nullptr, 0, far.data(), N, seed.data(), N, n);
  });
  CHECK(has(m, "'a' has 7 elements, but the kernel touches element 8"));
}

TEST_CASE("checked probe: a read one cell over where a mask says so") {
  for (int n : {1, 2, 5}) {
    CAPTURE(n);
    const size_t N = size_t(n);
    std::vector<double> mask = dpgen_test::wavy(N, 0.4);
    // Exactly n + 1 values of a: the adjoint against differences, whatever the mask.
    dpgen_test::Problem<double> p;
    p.in_sizes = {N + 1};
    p.out_sizes = {N};
    p.forward = [&](auto in, auto out) { masked_shift(in[0], mask.data(), out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      masked_shift_adjoint(in[0], adj[0], mask.data(), nullptr, seed[0], n);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto od) {
      std::vector<double> md(N, 0.0);
      masked_shift_tangent(in[0], dir[0], mask.data(), md.data(), out[0], od[0], n);
    };
    dpgen_test::check_adjoint(p);
    // `a` of n values: enough while the last cell's mask is off.
    const std::vector<double> a = dpgen_test::wavy(N, 0.2), seed = dpgen_test::wavy(N, 0.6);
    mask[N - 1] = -1.0;
    std::vector<double> raw(N, 0.0), checked(N, 0.0);
    masked_shift_adjoint(a.data(), raw.data(), mask.data(), nullptr, seed.data(), n);
    masked_shift_adjoint_checked(a.data(), N, checked.data(), N, mask.data(), N, nullptr, 0,
                                 seed.data(), N, n);
    CHECK(checked == raw);
    mask[N - 1] = 1.0;
    std::vector<double> adj(N, 0.0);
    std::string m = thrown([&] {
      masked_shift_adjoint_checked(a.data(), N, adj.data(), N, mask.data(), N, nullptr, 0,
                                   seed.data(), N, n);
    });
    CHECK(has(m, "masked_shift_adjoint_checked: 'a' has " + std::to_string(n) +
                     " elements, but the kernel touches element " + std::to_string(n)));
    CHECK(all_zero(adj));
    // A short mask: read at every cell, so the probe stops at its end.
    m = thrown([&] {
      masked_shift_adjoint_checked(a.data(), N, adj.data(), N, mask.data(), N - 1, nullptr, 0,
                                   seed.data(), N, n);
    });
    CHECK(has(m, "'mask' has " + std::to_string(n - 1) + " elements"));
    CHECK(all_zero(adj));
  }
}

TEST_CASE("checked probe: a clamped departure point (C89)") {
  const int n = 9;
  const size_t N = size_t(n);
  const double dt = 0.7;
  // Velocities whose departure points stay in 0..n-2 need q[0..n-1]; pushing
  // left only (large positive velocities), x clamps to 0 and q[0..1] suffice.
  std::vector<double> vel = dpgen_test::wavy(N, 0.5);
  dpgen_test::Problem<double> p;
  p.in_sizes = {N + 1};
  p.out_sizes = {N};
  p.forward = [&](auto in, auto out) { departure_c89(in[0], vel.data(), out[0], n, dt); };
  p.adjoint = [&](auto in, auto adj, auto seed) {
    departure_c89_adjoint(in[0], adj[0], vel.data(), nullptr, seed[0], n, dt);
  };
  p.tangent = [&](auto in, auto dir, auto out, auto od) {
    std::vector<double> vd(N, 0.0);
    departure_c89_tangent(in[0], dir[0], vel.data(), vd.data(), out[0], od[0], n, dt);
  };
  dpgen_test::check_adjoint(p);
  std::vector<double> left(N, 1.0e3);
  const std::vector<double> q2 = {0.25, 0.5}, seed = dpgen_test::wavy(N, 0.1);
  std::vector<double> raw(2, 0.0), checked(2, 0.0), vraw(N, 0.0), vchecked(N, 0.0);
  departure_c89_adjoint(q2.data(), raw.data(), left.data(), vraw.data(), seed.data(), n, dt);
  departure_c89_adjoint_checked(q2.data(), 2, checked.data(), 2, left.data(), N, vchecked.data(), N,
                                seed.data(), N, n, dt);
  CHECK(checked == raw);
  CHECK(vchecked == vraw);
  // At rest, cell i reads q[i] and q[i + 1]: q[n] is one past n values.
  const std::vector<double> rest(N, 0.0), q = dpgen_test::wavy(N, 0.3);
  std::vector<double> adj(N, 0.0);
  std::string m = thrown([&] {
    departure_c89_adjoint_checked(q.data(), N, adj.data(), N, rest.data(), N, nullptr, 0,
                                  seed.data(), N, n, dt);
  });
  CHECK(has(m, "'q' has 9 elements, but the kernel touches element 9 (n = 9)"));
  CHECK(all_zero(adj));
  // The adjoint of q shorter than q: named on its own.
  std::vector<double> q_long = dpgen_test::wavy(N + 1, 0.3), short_adj(N, 0.0);
  m = thrown([&] {
    departure_c89_adjoint_checked(q_long.data(), N + 1, short_adj.data(), N, rest.data(), N,
                                  nullptr, 0, seed.data(), N, n, dt);
  });
  CHECK(has(m, "'q_adj' has 9 elements, but the kernel touches element 9"));
  CHECK(all_zero(short_adj));
}

TEST_CASE("checked probe: an upwind choice that reads a[-1] where the flow comes from the left") {
  const int n = 6;
  const size_t N = size_t(n);
  // a has one ghost cell on the right only: a[0..n]. With u >= 0 at cell 0
  // the kernel never reads a[-1]; with u[0] < 0 it would.
  std::vector<double> u = {0.5, -0.3, 0.2, -0.1, 0.4, 0.3};
  const std::vector<double> a = dpgen_test::wavy(N + 1, 0.2), seed = dpgen_test::wavy(N, 0.9);
  std::vector<double> raw(N + 1, 0.0), checked(N + 1, 0.0), uraw(N, 0.0), uchecked(N, 0.0);
  upwind_from_zero_adjoint(a.data(), raw.data(), u.data(), uraw.data(), seed.data(), n, 0.4);
  upwind_from_zero_adjoint_checked(a.data(), N + 1, checked.data(), N + 1, u.data(), N,
                                   uchecked.data(), N, seed.data(), N, n, 0.4);
  CHECK(checked == raw);
  CHECK(uchecked == uraw);
  u[0] = -0.5;
  std::vector<double> adj(N + 1, 0.0), uadj(N, 0.0);
  std::string m = thrown([&] {
    upwind_from_zero_adjoint_checked(a.data(), N + 1, adj.data(), N + 1, u.data(), N, uadj.data(),
                                     N, seed.data(), N, n, 0.4);
  });
  CHECK(has(m, "upwind_from_zero_adjoint_checked: 'a' has 7 elements, but the kernel touches "
               "element -1 (n = 6)"));
  CHECK(all_zero(adj));
  CHECK(all_zero(uadj));
  // The right end: u[n - 1] > 0 reads a[n], and a of n values does not have it.
  u[0] = 0.5;
  m = thrown([&] {
    upwind_from_zero_adjoint_checked(a.data(), N, adj.data(), N, u.data(), N, uadj.data(), N,
                                     seed.data(), N, n, 0.4);
  });
  CHECK(has(m, "'a' has 6 elements, but the kernel touches element 6"));
}

TEST_CASE("checked probe: an accumulator over cells above a threshold") {
  const int nx = 5, ny = 3;
  const size_t N = size_t(nx * ny);
  const double t = 0.2;
  dpgen_test::Problem<double> p;
  p.in_sizes = {N + 1};
  p.out_sizes = {size_t(ny)};
  p.forward = [&](auto in, auto out) { thresholded_row_sums(in[0], out[0], nx, ny, t); };
  p.adjoint = [&](auto in, auto adj, auto seed) {
    thresholded_row_sums_adjoint(in[0], adj[0], seed[0], nx, ny, t);
  };
  p.tangent = [&](auto in, auto dir, auto out, auto od) {
    thresholded_row_sums_tangent(in[0], dir[0], out[0], od[0], nx, ny, t);
  };
  dpgen_test::check_adjoint(p);
  // a of nx * ny values: enough while the last cell is at or below the threshold.
  std::vector<double> a = dpgen_test::wavy(N, 0.7);
  a[N - 1] = -1.0;
  const std::vector<double> seed = {0.3, -0.7, 1.1};
  std::vector<double> raw(N, 0.0), checked(N, 0.0);
  thresholded_row_sums_adjoint(a.data(), raw.data(), seed.data(), nx, ny, t);
  thresholded_row_sums_adjoint_checked(a.data(), N, checked.data(), N, seed.data(), 3, nx, ny, t);
  CHECK(checked == raw);
  a[N - 1] = 1.0;
  std::vector<double> adj(N, 0.0);
  std::string m = thrown([&] {
    thresholded_row_sums_adjoint_checked(a.data(), N, adj.data(), N, seed.data(), 3, nx, ny, t);
  });
  CHECK(has(m, "'a' has 15 elements, but the kernel touches element 15 (nx = 5, ny = 3)"));
  CHECK(all_zero(adj));
  // The seed of the sums is bounded from the loop: too short, the usual message.
  m = thrown([&] {
    thresholded_row_sums_adjoint_checked(a.data(), N + 1, adj.data(), N + 1, seed.data(), 2, nx, ny,
                                         t);
  });
  CHECK(has(m, "'s_adj' has 2 elements, but the kernel touches elements 0 to 2"));
}

TEST_CASE("checked probe: an empty array the data reaches; a global table") {
  // An empty std::vector's data() is null: still an array of 0 elements.
  const int n = 3;
  std::vector<int> idx = {0, 0, 0};
  const std::vector<double> seed = {1.0, 2.0, 3.0};
  std::vector<double> adj(3, 0.0);
  std::string m = thrown([&] {
    gather_by_index_adjoint_checked(nullptr, 0, adj.data(), 3, idx.data(), 3, seed.data(), 3, n);
  });
  CHECK(has(m, "'a' has 0 elements"));
  CHECK(all_zero(adj));
  // weights4 has 4 elements (its type says so): n = 5 reads weights4[4].
  const std::vector<double> a = dpgen_test::wavy(5, 0.1), s5 = dpgen_test::wavy(5, 0.4);
  std::vector<double> a5(5, 0.0), raw(4, 0.0), checked(4, 0.0);
  m = thrown([&] { global_weights_adjoint_checked(a.data(), 5, a5.data(), 5, s5.data(), 5, 5); });
  CHECK(has(m, "global_weights_adjoint_checked: 'weights4' has 4 elements, but the kernel touches "
               "elements 0 to 4 (n = 5)"));
  CHECK(all_zero(a5));
  global_weights_adjoint(a.data(), raw.data(), s5.data(), 4);
  global_weights_adjoint_checked(a.data(), 4, checked.data(), 4, s5.data(), 4, 4);
  CHECK(checked == raw);
}

TEST_CASE("checked probe: a shift in cells computed from a real local") {
  const int n = 4;
  const double h = 0.5;
  const std::vector<double> shift = {1.0}; // 2 cells: a[2] .. a[5]
  const std::vector<double> a = dpgen_test::wavy(6, 0.1), seed = dpgen_test::wavy(n, 0.4);
  std::vector<double> raw(6, 0.0), checked(6, 0.0);
  shift_by_distance_adjoint(a.data(), raw.data(), shift.data(), seed.data(), n, h);
  shift_by_distance_adjoint_checked(a.data(), 6, checked.data(), 6, shift.data(), 1, seed.data(), n,
                                    n, h);
  CHECK(checked == raw);
  CHECK(raw[5] == 2.0 * seed[3]);
  // a has 5 elements: the kernel reads a[5].
  std::vector<double> a5(5, 0.0);
  std::string m = thrown([&] {
    shift_by_distance_adjoint_checked(a.data(), 5, a5.data(), 5, shift.data(), 1, seed.data(), n, n,
                                      h);
  });
  CHECK(has(m, "'a' has 5 elements, but the kernel touches elements 2 to 5"));
  CHECK(all_zero(a5));
  // shift is empty: its element 0 is not read.
  m = thrown([&] {
    shift_by_distance_adjoint_checked(a.data(), 6, checked.data(), 6, shift.data(), 0, seed.data(),
                                      n, n, h);
  });
  CHECK(has(m, "'shift' has 0 elements, but the kernel touches element 0"));
}

TEST_CASE("checked probe: global arrays read at a material index") {
  const int n = 5;
  const std::vector<double> a = dpgen_test::wavy(n, 0.1), seed = dpgen_test::wavy(n, 0.4);
  std::vector<int> material = {0, 2, 1, 2, 0};
  std::vector<double> raw(n, 0.0), checked(n, 0.0), rate_raw(3, 0.0), rate_checked(3, 0.0);
  g_rate_adj = rate_raw.data();
  rate_by_material_adjoint(a.data(), raw.data(), material.data(), seed.data(), n);
  g_rate_adj = rate_checked.data();
  rate_by_material_adjoint_checked(a.data(), n, checked.data(), n, material.data(), n, seed.data(),
                                   n, n);
  CHECK(checked == raw);
  CHECK(rate_checked == rate_raw);
  CHECK(rate_raw[1] == doctest::Approx(a[2] * 0.5 * seed[2]));
  // material 3: g_rate[3] (3 elements) and kind_weight[4] (4 elements).
  material[3] = 3;
  std::vector<double> zero(n, 0.0), rate_zero(3, 0.0);
  g_rate_adj = rate_zero.data();
  std::string m = thrown([&] {
    rate_by_material_adjoint_checked(a.data(), n, zero.data(), n, material.data(), n, seed.data(),
                                     n, n);
  });
  CHECK(has(m, "rate_by_material_adjoint_checked: 'g_rate' has 3 elements, but the kernel touches "
               "element 3 (n = 5)"));
  CHECK(all_zero(zero));
  CHECK(all_zero(rate_zero));
  // material -1 reads g_rate[-1] first.
  material[3] = -1;
  m = thrown([&] {
    rate_by_material_adjoint_checked(a.data(), n, zero.data(), n, material.data(), n, seed.data(),
                                     n, n);
  });
  CHECK(has(m, "'g_rate' has 3 elements, but the kernel touches element -1"));
  g_rate_adj = nullptr;
}
