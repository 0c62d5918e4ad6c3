// accumulators (tests/styles/): scalar running sums read after their loops
// (issue 20), adjoint and tangent of each on random inputs.
#include "support/adjoint_check.hpp"

#include "accumulators_adjoint.hpp"
#include "accumulators_kernels.hpp"
#include "accumulators_tangent.hpp"
#include "dpgen/annotate.hpp"

#include <tuple>

TEST_CASE("styles: acc_norm2") {
  for (int n : {1, 4, 33}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {1};
    p.forward = [&](auto in, auto out) { acc_norm2(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { acc_norm2_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      acc_norm2_tangent(in[0], d[0], out[0], dout[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: acc_rowsum, acc_rowmean_c89") {
  for (auto [nx, ny] : {std::tuple{1, 1}, {3, 5}, {17, 4}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    size_t X = size_t(nx), Y = size_t(ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {X * Y};
    p.out_sizes = {Y};
    p.forward = [&](auto in, auto out) { acc_rowsum(in[0], out[0], nx, ny); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      acc_rowsum_adjoint(in[0], adj[0], seed[0], nx, ny);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      acc_rowsum_tangent(in[0], d[0], out[0], dout[0], nx, ny);
    };
    dpgen_test::check_adjoint(p);

    std::vector<double> w(X);
    for (size_t i = 0; i < X; ++i)
      w[i] = 0.5 + 0.25 * double(i % 3);
    dpgen_test::Problem<double> q;
    q.in_sizes = {X * Y};
    q.out_sizes = {Y};
    q.linear = true;
    q.forward = [&](auto in, auto out) { acc_rowmean_c89(in[0], w.data(), out[0], nx, ny); };
    q.adjoint = [&](auto in, auto adj, auto seed) {
      acc_rowmean_c89_adjoint(in[0], adj[0], w.data(), seed[0], nx, ny);
    };
    q.tangent = [&](auto in, auto d, auto out, auto dout) {
      acc_rowmean_c89_tangent(in[0], d[0], w.data(), out[0], dout[0], nx, ny);
    };
    dpgen_test::check_adjoint(q);
  }
}

TEST_CASE("styles: acc_dot_float") {
  for (int n : {1, 7, 40}) {
    CAPTURE(n);
    dpgen_test::Problem<float> p;
    p.in_sizes = {size_t(n), size_t(n)};
    p.out_sizes = {1};
    p.forward = [&](auto in, auto out) { acc_dot_float(in[0], in[1], out[0], n, 0.5f); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      acc_dot_float_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n, 0.5f);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      acc_dot_float_tangent(in[0], d[0], in[1], d[1], out[0], dout[0], n, 0.5f);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: acc_normalize, acc_two_sums") {
  for (int n : {1, 2, 9, 64}) {
    CAPTURE(n);
    size_t N = size_t(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {N};
    p.out_sizes = {N};
    p.forward = [&](auto in, auto out) { acc_normalize(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      acc_normalize_adjoint(in[0], adj[0], seed[0], n);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      acc_normalize_tangent(in[0], d[0], out[0], dout[0], n);
    };
    dpgen_test::check_adjoint(p);

    dpgen_test::Problem<double> q;
    q.in_sizes = {N, N};
    q.out_sizes = {2};
    q.forward = [&](auto in, auto out) { acc_two_sums(in[0], in[1], out[0], n); };
    q.adjoint = [&](auto in, auto adj, auto seed) {
      acc_two_sums_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n);
    };
    q.tangent = [&](auto in, auto d, auto out, auto dout) {
      acc_two_sums_tangent(in[0], d[0], in[1], d[1], out[0], dout[0], n);
    };
    dpgen_test::check_adjoint(q);
  }
}

TEST_CASE("styles: acc_column") {
  for (auto [nx, ny, nz] : {std::tuple{1, 1, 1}, {3, 2, 4}, {5, 4, 3}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    CAPTURE(nz);
    size_t X = size_t(nx), Y = size_t(ny), Z = size_t(nz);
    dpgen_test::Problem<double> p;
    p.in_sizes = {X * Y * Z};
    p.out_sizes = {X * Y};
    p.forward = [&](auto in, auto out) { acc_column(in[0], out[0], nx, ny, nz); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      acc_column_adjoint(in[0], adj[0], seed[0], nx, ny, nz);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      acc_column_tangent(in[0], d[0], out[0], dout[0], nx, ny, nz);
    };
    dpgen_test::check_adjoint(p);
  }
}
