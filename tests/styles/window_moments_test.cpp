// window_moments (tests/styles/): adjoint and tangent of window sums with a
// run-time half-width.
#include "support/adjoint_check.hpp"

#include "window_moments_adjoint.hpp"
#include "window_moments_kernels.hpp"
#include "window_moments_tangent.hpp"

TEST_CASE("styles: window_moments, window_column_exp") {
  for (int d : {0, 1, 2}) {
    for (int extra : {0, 3}) {
      const int nx = 2 * d + 1 + extra, ny = 2 * d + 2;
      CAPTURE(d);
      CAPTURE(nx);
      const size_t N = size_t(nx) * size_t(ny);
      dpgen_test::Problem<double> p;
      p.in_sizes = {N};
      p.out_sizes = {N};
      p.forward = [&](auto in, auto out) { window_moments(in[0], out[0], nx, ny, d); };
      p.adjoint = [&](auto in, auto adj, auto seed) {
        window_moments_adjoint(in[0], adj[0], seed[0], nx, ny, d);
      };
      p.tangent = [&](auto in, auto dd, auto out, auto dout) {
        window_moments_tangent(in[0], dd[0], out[0], dout[0], nx, ny, d);
      };
      dpgen_test::check_adjoint(p);

      dpgen_test::Problem<double> q;
      q.in_sizes = {N};
      q.out_sizes = {N};
      q.forward = [&](auto in, auto out) { window_column_exp(in[0], out[0], nx, ny, d); };
      q.adjoint = [&](auto in, auto adj, auto seed) {
        window_column_exp_adjoint(in[0], adj[0], seed[0], nx, ny, d);
      };
      q.tangent = [&](auto in, auto dd, auto out, auto dout) {
        window_column_exp_tangent(in[0], dd[0], out[0], dout[0], nx, ny, d);
      };
      dpgen_test::check_adjoint(q);
    }
  }
}
