// spelled_sums (tests/styles/): sums into outputs spelled `x = x + e`. Adjoint
// and tangent against the checker's differences and the dot-product test; the
// tangent's values and the parallel forward (printed from dpgen's IR) equal
// the kernel's bit for bit, so the chains are added in the user's order.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "same_bits.hpp"
#include "spelled_sums_adjoint.hpp"
#include "spelled_sums_kernels.hpp"
#include "spelled_sums_tangent.hpp"

#include <cstring>
#include <utility>
#include <vector>

TEST_CASE("styles: dot_spelled, two_sums_c89, helper_adds, store_then_add") {
  for (int n : {1, 2, 5, 33}) {
    CAPTURE(n);
    const size_t N = size_t(n);
    dpgen_test::Problem<double> dot;
    dot.in_sizes = {N, N};
    dot.out_sizes = {1};
    dot.forward = [&](auto in, auto out) { dot_spelled(in[0], in[1], out[0], n); };
    dot.adjoint = [&](auto in, auto adj, auto seed) {
      dot_spelled_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n);
    };
    dot.tangent = [&](auto in, auto d, auto out, auto dout) {
      dot_spelled_tangent(in[0], d[0], in[1], d[1], out[0], dout[0], n);
    };
    dpgen_test::check_adjoint(dot);

    dpgen_test::Problem<double> two;
    two.in_sizes = {N};
    two.out_sizes = {1, 1};
    two.forward = [&](auto in, auto out) { two_sums_c89(in[0], out[0], out[1], n); };
    two.adjoint = [&](auto in, auto adj, auto seed) {
      two_sums_c89_adjoint(in[0], adj[0], seed[0], seed[1], n);
    };
    two.tangent = [&](auto in, auto d, auto out, auto dout) {
      two_sums_c89_tangent(in[0], d[0], out[0], dout[0], out[1], dout[1], n);
    };
    dpgen_test::check_adjoint(two);

    dpgen_test::Problem<double> helper;
    helper.in_sizes = {N};
    helper.out_sizes = {N};
    helper.forward = [&](auto in, auto out) { helper_adds(in[0], out[0], n); };
    helper.adjoint = [&](auto in, auto adj, auto seed) {
      helper_adds_adjoint(in[0], adj[0], seed[0], n);
    };
    helper.tangent = [&](auto in, auto d, auto out, auto dout) {
      helper_adds_tangent(in[0], d[0], out[0], dout[0], n);
    };
    dpgen_test::check_adjoint(helper);

    dpgen_test::Problem<double> back;
    back.in_sizes = {N, N};
    back.out_sizes = {N};
    back.forward = [&](auto in, auto out) { store_then_add(in[0], in[1], out[0], n); };
    back.adjoint = [&](auto in, auto adj, auto seed) {
      store_then_add_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n);
    };
    back.tangent = [&](auto in, auto d, auto out, auto dout) {
      store_then_add_tangent(in[0], d[0], in[1], d[1], out[0], dout[0], n);
    };
    dpgen_test::check_adjoint(back);
  }
}

TEST_CASE("styles: rowsum_spelled, the chain in the kernel's order") {
  for (auto [nx, ny] : {std::pair{1, 1}, {2, 3}, {9, 4}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t n = size_t(nx) * size_t(ny), Y = size_t(ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {n};
    p.out_sizes = {Y};
    p.forward = [&](auto in, auto out) { rowsum_spelled(in[0], out[0], nx, ny); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      rowsum_spelled_adjoint(in[0], adj[0], seed[0], nx, ny);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      rowsum_spelled_tangent(in[0], d[0], out[0], dout[0], nx, ny);
    };
    dpgen_test::check_adjoint(p);

    // Magnitudes apart: summed in another grouping, the rows would round otherwise.
    const std::vector<double> a = dpgen_test::wavy(n, 0.4, 3.0), da = dpgen_test::wavy(n, 2.0);
    std::vector<double> ref(Y), tan(Y), dtan(Y);
    rowsum_spelled(a.data(), ref.data(), nx, ny);
    rowsum_spelled_tangent(a.data(), da.data(), tan.data(), dtan.data(), nx, ny);
    CHECK(dpgen_test::same_values(ref, tan));
    dpgen_test::same_bits(
        n, Y, [&](const double* in, double* out) { rowsum_spelled(in, out, nx, ny); },
        [&](const double* in, double* out) { rowsum_spelled_parallel_forward(in, out, nx, ny); });
  }
}

TEST_CASE("styles: column_sums_float") {
  for (auto [nx, ny] : {std::pair{1, 1}, {3, 2}, {7, 5}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t n = size_t(nx) * size_t(ny), X = size_t(nx), Y = size_t(ny);
    dpgen_test::Problem<float> p;
    p.in_sizes = {n, Y};
    p.out_sizes = {X};
    p.forward = [&](auto in, auto out) { column_sums_float(in[0], in[1], out[0], nx, ny); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      column_sums_float_adjoint(in[0], adj[0], in[1], adj[1], seed[0], nx, ny);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      column_sums_float_tangent(in[0], d[0], in[1], d[1], out[0], dout[0], nx, ny);
    };
    dpgen_test::check_adjoint(p);

    const std::vector<double> wave = dpgen_test::wavy(n, 0.3, 2.0);
    std::vector<float> a(n), w(Y), da(n, 1.0f), dw(Y, 0.5f);
    for (size_t k = 0; k < n; ++k)
      a[k] = float(wave[k]);
    for (size_t j = 0; j < Y; ++j)
      w[j] = 1.0f + 0.37f * float(j);
    std::vector<float> ref(X), par(X), tan(X), dtan(X);
    column_sums_float(a.data(), w.data(), ref.data(), nx, ny);
    column_sums_float_parallel_forward(a.data(), w.data(), par.data(), nx, ny);
    column_sums_float_tangent(a.data(), da.data(), w.data(), dw.data(), tan.data(), dtan.data(), nx,
                              ny);
    CHECK(std::memcmp(ref.data(), par.data(), sizeof(float) * X) == 0);
    CHECK(std::memcmp(ref.data(), tan.data(), sizeof(float) * X) == 0);
  }
}

TEST_CASE("styles: view_row_sums") {
  for (auto [nx, ny] : {std::pair{2, 1}, {3, 4}, {6, 3}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t n = size_t(nx) * size_t(ny);
    auto cv = [&](const double* p, int cols) { return grid::View2D<const double>{p, cols, ny}; };
    auto mv = [&](double* p, int cols) { return grid::View2D<double>{p, cols, ny}; };
    auto sv = [&](const double* p) { return mv(const_cast<double*>(p), 1); };
    dpgen_test::Problem<double> p;
    p.in_sizes = {n};
    p.out_sizes = {size_t(nx - 1) * size_t(ny), size_t(ny)};
    p.forward = [&](auto in, auto out) {
      view_row_sums(cv(in[0], nx), mv(out[0], nx - 1), mv(out[1], 1));
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      view_row_sums_adjoint(cv(in[0], nx), mv(adj[0], nx), mv(const_cast<double*>(seed[0]), nx - 1),
                            sv(seed[1]));
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      view_row_sums_tangent(cv(in[0], nx), cv(d[0], nx), mv(out[0], nx - 1), mv(dout[0], nx - 1),
                            mv(out[1], 1), mv(dout[1], 1));
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: column_sums_mixed, double terms into float sums rounded once") {
  for (auto [nx, ny] : {std::pair{1, 1}, {4, 3}, {8, 6}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t n = size_t(nx) * size_t(ny), X = size_t(nx), Y = size_t(ny);
    dpgen_test::Problem<float> p;
    p.in_sizes = {n};
    p.out_sizes = {X, 1, Y};
    p.forward = [&](auto in, auto out) {
      column_sums_mixed(in[0], out[0], out[1], out[2], nx, ny);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      column_sums_mixed_adjoint(in[0], adj[0], seed[0], seed[1], seed[2], nx, ny);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      column_sums_mixed_tangent(in[0], d[0], out[0], dout[0], out[1], dout[1], out[2], dout[2], nx,
                                ny);
    };
    dpgen_test::check_adjoint(p);

    // The tangent's values are the kernel's, bit for bit (with each term rounded to float
    // before it is added, as the generator did before, `total` and `mean` differ here).
    const std::vector<double> wave = dpgen_test::wavy(n, 0.9, 2.0);
    std::vector<float> a(n), da(n, 1.0f);
    for (size_t k = 0; k < n; ++k)
      a[k] = float(wave[k]);
    std::vector<float> out(X), total(1), mean(Y), tout(X), ttotal(1), tmean(Y), d1(X), d2(1), d3(Y);
    column_sums_mixed(a.data(), out.data(), total.data(), mean.data(), nx, ny);
    column_sums_mixed_tangent(a.data(), da.data(), tout.data(), d1.data(), ttotal.data(), d2.data(),
                              tmean.data(), d3.data(), nx, ny);
    CHECK(std::memcmp(out.data(), tout.data(), sizeof(float) * X) == 0);
    CHECK(std::memcmp(total.data(), ttotal.data(), sizeof(float)) == 0);
    CHECK(std::memcmp(mean.data(), tmean.data(), sizeof(float) * Y) == 0);
  }
}

TEST_CASE("styles: local_sum_chains, local sums spelled as chains") {
  for (auto [nx, ny] : {std::pair{1, 1}, {4, 3}, {9, 5}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t n = size_t(nx) * size_t(ny), Y = size_t(ny);
    dpgen_test::Problem<float> p;
    p.in_sizes = {n};
    p.out_sizes = {1, Y};
    p.forward = [&](auto in, auto out) { local_sum_chains(in[0], out[0], out[1], nx, ny); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      local_sum_chains_adjoint(in[0], adj[0], seed[0], seed[1], nx, ny);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      local_sum_chains_tangent(in[0], d[0], out[0], dout[0], out[1], dout[1], nx, ny);
    };
    dpgen_test::check_adjoint(p);

    // The tangent's values are the kernel's, bit for bit (the float row sums rounded once per
    // update, from the double sum of their terms).
    const std::vector<double> wave = dpgen_test::wavy(n, 0.8, 1.5);
    std::vector<float> a(n), da(n, 1.0f);
    for (size_t k = 0; k < n; ++k)
      a[k] = float(wave[k]);
    float e = 0.0f, te = 0.0f, de = 0.0f;
    std::vector<float> rows(Y), trows(Y), drows(Y);
    local_sum_chains(a.data(), &e, rows.data(), nx, ny);
    local_sum_chains_tangent(a.data(), da.data(), &te, &de, trows.data(), drows.data(), nx, ny);
    CHECK(std::memcmp(&e, &te, sizeof(float)) == 0);
    CHECK(std::memcmp(rows.data(), trows.data(), sizeof(float) * Y) == 0);
  }
}

TEST_CASE("styles: mid_chain_sums, the sum in the middle of its chain, and cast") {
  for (auto [nx, ny] : {std::pair{1, 1}, {4, 3}, {7, 5}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t n = size_t(nx) * size_t(ny), X = size_t(nx);
    dpgen_test::Problem<float> p;
    p.in_sizes = {n, n};
    p.out_sizes = {1, X};
    p.forward = [&](auto in, auto out) { mid_chain_sums(in[0], in[1], out[0], out[1], nx, ny); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      mid_chain_sums_adjoint(in[0], adj[0], in[1], adj[1], seed[0], seed[1], nx, ny);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      mid_chain_sums_tangent(in[0], d[0], in[1], d[1], out[0], dout[0], out[1], dout[1], nx, ny);
    };
    dpgen_test::check_adjoint(p);

    // The tangent's values are the kernel's, bit for bit: each chain added in C++'s order, in
    // double, and rounded to float once per update.
    const std::vector<double> wa = dpgen_test::wavy(n, 0.8, 1.5),
                              wb = dpgen_test::wavy(n, 1.3, 0.7);
    std::vector<float> a(n), b(n), d(n, 1.0f);
    for (size_t k = 0; k < n; ++k) {
      a[k] = float(wa[k]);
      b[k] = float(wb[k]);
    }
    float t = 0.0f, tt = 0.0f, dt = 0.0f;
    std::vector<float> cols(X), tcols(X), dcols(X);
    mid_chain_sums(a.data(), b.data(), &t, cols.data(), nx, ny);
    mid_chain_sums_tangent(a.data(), d.data(), b.data(), d.data(), &tt, &dt, tcols.data(),
                           dcols.data(), nx, ny);
    CHECK(std::memcmp(&t, &tt, sizeof(float)) == 0);
    CHECK(std::memcmp(cols.data(), tcols.data(), sizeof(float) * X) == 0);
  }
}
