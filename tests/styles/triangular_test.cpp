// triangular (tests/styles/): loop bounds that move with an outer counter
// (issue 20), adjoint and tangent.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "triangular_adjoint.hpp"
#include "triangular_kernels.hpp"
#include "triangular_tangent.hpp"

TEST_CASE("styles: triangular loops") {
  for (int n : {1, 2, 5, 12}) {
    CAPTURE(n);
    size_t N = size_t(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {N * N, N};
    p.out_sizes = {N};
    p.linear = false;
    p.forward = [&](auto in, auto out) { tri_lower_matvec(in[0], in[1], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      tri_lower_matvec_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      tri_lower_matvec_tangent(in[0], d[0], in[1], d[1], out[0], dout[0], n);
    };
    dpgen_test::check_adjoint(p);

    dpgen_test::Problem<double> q;
    q.in_sizes = {N};
    q.out_sizes = {N * N};
    q.forward = [&](auto in, auto out) { tri_pairs_upper(in[0], out[0], n); };
    q.adjoint = [&](auto in, auto adj, auto seed) {
      tri_pairs_upper_adjoint(in[0], adj[0], seed[0], n);
    };
    q.tangent = [&](auto in, auto d, auto out, auto dout) {
      tri_pairs_upper_tangent(in[0], d[0], out[0], dout[0], n);
    };
    dpgen_test::check_adjoint(q);

    dpgen_test::Problem<double> r;
    r.in_sizes = {N * N};
    r.out_sizes = {N};
    r.forward = [&](auto in, auto out) { tri_colsum_down(in[0], out[0], n); };
    r.adjoint = [&](auto in, auto adj, auto seed) {
      tri_colsum_down_adjoint(in[0], adj[0], seed[0], n);
    };
    r.tangent = [&](auto in, auto d, auto out, auto dout) {
      tri_colsum_down_tangent(in[0], d[0], out[0], dout[0], n);
    };
    dpgen_test::check_adjoint(r);
  }
}

TEST_CASE("styles: tri_band_window") {
  for (int n : {1, 4, 11})
    for (int w : {0, 1, 3}) {
      CAPTURE(n);
      CAPTURE(w);
      dpgen_test::Problem<double> p;
      p.in_sizes = {size_t(n)};
      p.out_sizes = {size_t(n)};
      p.forward = [&](auto in, auto out) { tri_band_window(in[0], out[0], n, w); };
      p.adjoint = [&](auto in, auto adj, auto seed) {
        tri_band_window_adjoint(in[0], adj[0], seed[0], n, w);
      };
      p.tangent = [&](auto in, auto d, auto out, auto dout) {
        tri_band_window_tangent(in[0], d[0], out[0], dout[0], n, w);
      };
      dpgen_test::check_adjoint(p);
    }
}
