// pow2_bits (tests/styles/): adjoint and tangent of stores at `(j << lg) | i`.
#include "support/adjoint_check.hpp"

#include "pow2_bits_adjoint.hpp"
#include "pow2_bits_kernels.hpp"
#include "pow2_bits_tangent.hpp"

TEST_CASE("styles: pow2_transpose_scale, pow2_cube") {
  for (int lg : {0, 1, 2}) {
    CAPTURE(lg);
    const size_t n = size_t(1) << lg;
    dpgen_test::Problem<double> p;
    p.in_sizes = {n * n};
    p.out_sizes = {n * n};
    p.forward = [&](auto in, auto out) { pow2_transpose_scale(in[0], out[0], lg); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      pow2_transpose_scale_adjoint(in[0], adj[0], seed[0], lg);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      pow2_transpose_scale_tangent(in[0], d[0], out[0], dout[0], lg);
    };
    dpgen_test::check_adjoint(p);

    dpgen_test::Problem<double> q;
    q.in_sizes = {n * n * n};
    q.out_sizes = {n * n * n};
    q.forward = [&](auto in, auto out) { pow2_cube(in[0], out[0], lg); };
    q.adjoint = [&](auto in, auto adj, auto seed) { pow2_cube_adjoint(in[0], adj[0], seed[0], lg); };
    q.tangent = [&](auto in, auto d, auto out, auto dout) {
      pow2_cube_tangent(in[0], d[0], out[0], dout[0], lg);
    };
    dpgen_test::check_adjoint(q);
  }
}

TEST_CASE("styles: pow2_guarded") {
  for (int lg : {-1, 0, 1, 2, 16}) {
    CAPTURE(lg);
    const size_t n = lg >= 0 && lg <= 15 ? size_t(1) << lg : 0;
    dpgen_test::Problem<double> p;
    p.in_sizes = {n * n};
    p.out_sizes = {n * n};
    p.forward = [&](auto in, auto out) { pow2_guarded(in[0], out[0], lg); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      pow2_guarded_adjoint(in[0], adj[0], seed[0], lg);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      pow2_guarded_tangent(in[0], d[0], out[0], dout[0], lg);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: blocks8") {
  for (int m : {1, 3}) {
    CAPTURE(m);
    const size_t N = 8 * size_t(m);
    dpgen_test::Problem<double> p;
    p.in_sizes = {N};
    p.out_sizes = {N};
    p.forward = [&](auto in, auto out) { blocks8(in[0], out[0], m); };
    p.adjoint = [&](auto in, auto adj, auto seed) { blocks8_adjoint(in[0], adj[0], seed[0], m); };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      blocks8_tangent(in[0], d[0], out[0], dout[0], m);
    };
    dpgen_test::check_adjoint(p);
  }
}
