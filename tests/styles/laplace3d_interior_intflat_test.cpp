// laplace3d_interior_intflat (tests/styles/): interior-only 3D, int flat index.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "laplace3d_interior_intflat_adjoint.hpp"
#include "laplace3d_interior_intflat_tangent.hpp"

#include <tuple>

DPGEN_KERNEL void laplace3d_interior_intflat(DPGEN_IN const double* p, DPGEN_OUT double* lap,
                                             int nx, int ny, int nz, double inv_h2);

TEST_CASE("styles: laplace3d_interior_intflat") {
  for (auto [nx, ny, nz] : {std::tuple{1, 1, 1}, {2, 2, 2}, {3, 3, 3}, {4, 3, 5}, {6, 5, 4}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    CAPTURE(nz);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(nx * ny * nz)};
    p.out_sizes = {size_t(nx * ny * nz)};
    p.linear = true;
    p.forward = [&](auto in, auto out) { laplace3d_interior_intflat(in[0], out[0], nx, ny, nz, 4.0); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      laplace3d_interior_intflat_adjoint(in[0], adj[0], seed[0], nx, ny, nz, 4.0);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      laplace3d_interior_intflat_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], nx, ny, nz, 4.0);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      laplace3d_interior_intflat_tangent(in[0], dir[0], out[0], outd[0], nx, ny, nz, 4.0);
    };
    dpgen_test::check_adjoint(p);
  }
}
