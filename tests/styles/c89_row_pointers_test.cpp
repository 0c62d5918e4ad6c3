// c89_row_pointers (tests/styles/): row pointers declared with no value and assigned at the
// top of each loop body (C89); differences, the dot-product test, the tangent, the checked
// entry point, and the parallel forward bit for bit against the kernel.
#include "same_bits.hpp"
#include "support/adjoint_check.hpp"

#include "c89_row_pointers_adjoint.hpp"
#include "c89_row_pointers_tangent.hpp"
#include "dpgen/annotate.hpp"

#include <tuple>
#include <vector>

DPGEN_KERNEL void laplace2d_c89_rows(DPGEN_IN const double* u, DPGEN_OUT double* lap, int nx,
                                     int ny, double inv_h2);
DPGEN_KERNEL void advect3d_c89_planes(DPGEN_IN const double* q, DPGEN_IN const double* w,
                                      DPGEN_OUT double* flux, int nx, int ny, int nz);
DPGEN_KERNEL void two_rows_helper(DPGEN_IN const double* a, DPGEN_OUT double* top,
                                  DPGEN_OUT double* bottom, int nx, int ny);
DPGEN_KERNEL void mix_rows_repointed(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                     DPGEN_OUT double* out, DPGEN_OUT double* out2, int nx, int ny);

namespace {

// The parallel forward against the kernel, bit for bit, on outputs that start equal.
template <typename Kernel, typename Parallel>
void same_forward(size_t n_out, size_t n_outs, Kernel kernel, Parallel parallel) {
  std::vector<std::vector<double>> a(n_outs, std::vector<double>(n_out, 0.25)), b = a;
  kernel(a);
  parallel(b);
  CHECK(a == b);
}

} // namespace

TEST_CASE("styles: laplace2d_c89_rows") {
  for (auto [nx, ny] : {std::tuple{1, 1}, {3, 3}, {4, 2}, {6, 5}, {9, 7}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t n = size_t(nx * ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {n};
    p.out_sizes = {n};
    p.linear = true;
    p.forward = [&](auto in, auto out) { laplace2d_c89_rows(in[0], out[0], nx, ny, 4.0); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      laplace2d_c89_rows_adjoint(in[0], adj[0], seed[0], nx, ny, 4.0);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      laplace2d_c89_rows_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], nx, ny,
                                         4.0);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      laplace2d_c89_rows_tangent(in[0], dir[0], out[0], outd[0], nx, ny, 4.0);
    };
    dpgen_test::check_adjoint(p);
  }
  const int nx = 130, ny = 90;
  const std::vector<double> u = dpgen_test::wavy(size_t(nx * ny), 0.3);
  same_forward(
      size_t(nx * ny), 1, [&](auto& o) { laplace2d_c89_rows(u.data(), o[0].data(), nx, ny, 2.0); },
      [&](auto& o) { laplace2d_c89_rows_parallel_forward(u.data(), o[0].data(), nx, ny, 2.0); });
}

TEST_CASE("styles: advect3d_c89_planes") {
  for (auto [nx, ny, nz] : {std::tuple{1, 1, 1}, {2, 1, 2}, {3, 2, 3}, {4, 3, 4}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    CAPTURE(nz);
    const size_t n = size_t(nx * ny * nz);
    dpgen_test::Problem<double> p;
    p.in_sizes = {n, n};
    p.out_sizes = {n};
    p.forward = [&](auto in, auto out) { advect3d_c89_planes(in[0], in[1], out[0], nx, ny, nz); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      advect3d_c89_planes_adjoint(in[0], adj[0], in[1], adj[1], seed[0], nx, ny, nz);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      advect3d_c89_planes_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1],
                                          in_n[1], seed[0], out_n[0], nx, ny, nz);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      advect3d_c89_planes_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], nx, ny, nz);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: two_rows_helper") {
  for (auto [nx, ny] : {std::tuple{1, 1}, {3, 1}, {4, 3}, {8, 5}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(nx * ny)};
    p.out_sizes = {size_t(nx), size_t(nx)};
    p.forward = [&](auto in, auto out) { two_rows_helper(in[0], out[0], out[1], nx, ny); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      two_rows_helper_adjoint(in[0], adj[0], seed[0], seed[1], nx, ny);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      two_rows_helper_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], seed[1],
                                      out_n[1], nx, ny);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      two_rows_helper_tangent(in[0], dir[0], out[0], outd[0], out[1], outd[1], nx, ny);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: mix_rows_repointed") {
  for (auto [nx, ny] : {std::tuple{1, 1}, {2, 3}, {5, 4}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t n = size_t(nx * ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {n, n};
    p.out_sizes = {n, n};
    p.forward = [&](auto in, auto out) {
      mix_rows_repointed(in[0], in[1], out[0], out[1], nx, ny);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      mix_rows_repointed_adjoint(in[0], adj[0], in[1], adj[1], seed[0], seed[1], nx, ny);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      mix_rows_repointed_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1],
                                         in_n[1], seed[0], out_n[0], seed[1], out_n[1], nx, ny);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      mix_rows_repointed_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], out[1], outd[1], nx,
                                 ny);
    };
    dpgen_test::check_adjoint(p);
  }
}
