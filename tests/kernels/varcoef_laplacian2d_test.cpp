// varcoef_laplacian2d (tests/kernels/): div(k grad p), bilinear in (kc, p).
#include "support/adjoint_check.hpp"

#include "test_kernels.hpp"
#include "varcoef_laplacian2d_adjoint.hpp"
#include "varcoef_laplacian2d_tangent.hpp"

TEST_CASE("varcoef_laplacian2d adjoint") {
  for (auto [nx, ny] : {std::pair{2, 2}, {3, 3}, {4, 6}, {12, 9}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    size_t n = size_t(nx * ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {n, n};
    p.in_ranges = {{0.5, 2.0}, {-1.0, 1.0}};
    p.out_sizes = {n};
    p.forward = [&](auto in, auto out) { varcoef_laplacian2d(in[0], in[1], out[0], nx, ny, 0.3); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      varcoef_laplacian2d_adjoint(in[0], adj[0], in[1], adj[1], seed[0], nx, ny, 0.3);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      varcoef_laplacian2d_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], nx, ny, 0.3);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      varcoef_laplacian2d_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], nx, ny, 0.3);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("varcoef_laplacian2d adjoint in p alone is linear") {
  const int nx = 7, ny = 6;
  size_t n = size_t(nx * ny);
  std::vector<double> kc(n);
  for (size_t i = 0; i < n; ++i)
    kc[i] = 1.0 + 0.5 * std::sin(double(i));
  dpgen_test::Problem<double> p;
  p.in_sizes = {n};
  p.out_sizes = {n};
  p.linear = true;
  p.forward = [&](auto in, auto out) { varcoef_laplacian2d(kc.data(), in[0], out[0], nx, ny, 0.3); };
  p.adjoint = [&](auto in, auto adj, auto seed) {
    std::vector<double> kc_adj(n, 0.0);
    varcoef_laplacian2d_adjoint(kc.data(), kc_adj.data(), in[0], adj[0], seed[0], nx, ny, 0.3);
  };
  dpgen_test::check_adjoint(p);
}
