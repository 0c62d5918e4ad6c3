// clamped_indices (tests/styles/): neighbours clamped to the grid by std::max / std::min
// (gathered piece by piece, as a conditional index) and by std::clamp (scatter form), 1D and
// 2D through locals; sizes from 1 (every neighbour clamped) past the parallel threshold.
#include "support/adjoint_check.hpp"

#include "clamped_indices_adjoint.hpp"
#include "clamped_indices_tangent.hpp"
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void clamped_smooth(DPGEN_IN const double* u, DPGEN_OUT double* v, int n);
DPGEN_KERNEL void clamped_diffusion2d(DPGEN_IN const double* u, DPGEN_OUT double* out, int nx,
                                      int ny, double k);
DPGEN_KERNEL void clamped_wide(DPGEN_IN const double* u, DPGEN_OUT double* v, int n);

TEST_CASE("styles: clamped_indices, smooth") {
  for (int n : {1, 2, 3, 5, 64, 8300}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.linear = true;
    p.forward = [&](auto in, auto out) { clamped_smooth(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      clamped_smooth_adjoint(in[0], adj[0], seed[0], n);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      clamped_smooth_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      clamped_smooth_tangent(in[0], dir[0], out[0], outd[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: clamped_indices, diffusion2d") {
  for (auto [nx, ny] : {std::pair{1, 1}, {1, 4}, {2, 2}, {5, 3}, {100, 90}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t cells = size_t(nx) * size_t(ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {cells};
    p.out_sizes = {cells};
    p.forward = [&](auto in, auto out) { clamped_diffusion2d(in[0], out[0], nx, ny, 0.2); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      clamped_diffusion2d_adjoint(in[0], adj[0], seed[0], nx, ny, 0.2);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      clamped_diffusion2d_tangent(in[0], dir[0], out[0], outd[0], nx, ny, 0.2);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: clamped_indices, wide") {
  for (int n : {1, 2, 3, 4, 7, 300}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { clamped_wide(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      clamped_wide_adjoint(in[0], adj[0], seed[0], n);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      clamped_wide_tangent(in[0], dir[0], out[0], outd[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
