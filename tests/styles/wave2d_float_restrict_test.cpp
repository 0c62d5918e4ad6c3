// wave2d_float_restrict (tests/styles/): float, __restrict__; bilinear;
// float tolerances.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "wave2d_float_restrict_adjoint.hpp"
#include "wave2d_float_restrict_tangent.hpp"

#include <tuple>

DPGEN_KERNEL void wave2d_float_restrict(DPGEN_IN const float* __restrict__ u,
                                        DPGEN_IN const float* __restrict__ u_prev,
                                        DPGEN_IN const float* __restrict__ c2,
                                        DPGEN_OUT float* __restrict__ u_next, int nx, int ny,
                                        float dt2_h2);

TEST_CASE("styles: wave2d_float_restrict") {
  for (auto [nx, ny] : {std::tuple{1, 1}, {2, 4}, {3, 3}, {6, 5}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    size_t n = size_t(nx * ny);
    dpgen_test::Problem<float> p;
    p.in_sizes = {n, n, n};
    p.out_sizes = {n};
    p.in_ranges = {{-1.0, 1.0}, {-1.0, 1.0}, {0.2, 1.0}};
    p.forward = [&](auto in, auto out) {
      wave2d_float_restrict(in[0], in[1], in[2], out[0], nx, ny, 0.2f);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      wave2d_float_restrict_adjoint(in[0], adj[0], in[1], adj[1], in[2], adj[2], seed[0], nx, ny,
                                    0.2f);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      wave2d_float_restrict_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], in[2], in_n[2], adj[2], in_n[2], seed[0], out_n[0], nx, ny, 0.2f);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      wave2d_float_restrict_tangent(in[0], dir[0], in[1], dir[1], in[2], dir[2], out[0], outd[0], nx, ny, 0.2f);
    };
    dpgen_test::check_adjoint(p);
  }
}
