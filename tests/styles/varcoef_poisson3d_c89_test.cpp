// varcoef_poisson3d_c89 (tests/styles/): C89, interior 3D, int flat index
// assigned to a function-scope variable; bilinear in (kappa, u).
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "varcoef_poisson3d_c89_adjoint.hpp"
#include "varcoef_poisson3d_c89_tangent.hpp"

#include <tuple>

DPGEN_KERNEL void varcoef_poisson3d_c89(DPGEN_IN const double* kappa, DPGEN_IN const double* u,
                                        DPGEN_OUT double* r, int nx, int ny, int nz);

TEST_CASE("styles: varcoef_poisson3d_c89") {
  for (auto [nx, ny, nz] : {std::tuple{1, 1, 1}, {3, 2, 3}, {3, 3, 3}, {5, 4, 4}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    CAPTURE(nz);
    size_t n = size_t(nx * ny * nz);
    dpgen_test::Problem<double> p;
    p.in_sizes = {n, n};
    p.out_sizes = {n};
    p.in_ranges = {{0.5, 2.0}, {-1.0, 1.0}};
    p.forward = [&](auto in, auto out) { varcoef_poisson3d_c89(in[0], in[1], out[0], nx, ny, nz); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      varcoef_poisson3d_c89_adjoint(in[0], adj[0], in[1], adj[1], seed[0], nx, ny, nz);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      varcoef_poisson3d_c89_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], nx, ny, nz);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      varcoef_poisson3d_c89_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], nx, ny, nz);
    };
    dpgen_test::check_adjoint(p);
  }
}
