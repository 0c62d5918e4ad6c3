// parity_loops (tests/styles/): loops stepping by 2 whose start moves with
// the row, and a constant strided loop that is unrolled (issue 20).
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "parity_loops_adjoint.hpp"
#include "parity_loops_kernels.hpp"
#include "parity_loops_tangent.hpp"

#include <tuple>

TEST_CASE("styles: rb_red_sweep") {
  for (auto [nx, ny] : {std::tuple{3, 3}, {4, 5}, {7, 6}, {2, 8}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    size_t N = size_t(nx) * size_t(ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {N, N};
    p.out_sizes = {N};
    p.forward = [&](auto in, auto out) { rb_red_sweep(in[0], in[1], out[0], nx, ny, 0.1); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      rb_red_sweep_adjoint(in[0], adj[0], in[1], adj[1], seed[0], nx, ny, 0.1);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      rb_red_sweep_tangent(in[0], d[0], in[1], d[1], out[0], dout[0], nx, ny, 0.1);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: strided_from_row, even_weights") {
  for (int n : {1, 2, 5, 8}) {
    CAPTURE(n);
    size_t N = size_t(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {N};
    p.out_sizes = {N * N};
    p.forward = [&](auto in, auto out) { strided_from_row(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      strided_from_row_adjoint(in[0], adj[0], seed[0], n);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      strided_from_row_tangent(in[0], d[0], out[0], dout[0], n);
    };
    dpgen_test::check_adjoint(p);

    dpgen_test::Problem<double> q;
    q.in_sizes = {N + 5};
    q.out_sizes = {N};
    q.forward = [&](auto in, auto out) { even_weights(in[0], out[0], n); };
    q.adjoint = [&](auto in, auto adj, auto seed) { even_weights_adjoint(in[0], adj[0], seed[0], n); };
    q.tangent = [&](auto in, auto d, auto out, auto dout) {
      even_weights_tangent(in[0], d[0], out[0], dout[0], n);
    };
    dpgen_test::check_adjoint(q);
  }
}

TEST_CASE("styles: ring_parity") {
  for (int n : {3, 4, 9}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { ring_parity(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { ring_parity_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      ring_parity_tangent(in[0], d[0], out[0], dout[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
