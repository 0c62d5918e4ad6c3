// grad_staggered_rowptr (tests/styles/): `double**`, two nests, staggered.
// Assumption as in restrict2d_rowptr_test.cpp: row pointers in the adjoint.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "grad_staggered_rowptr_adjoint.hpp"
#include "styles_support.hpp"

#include <tuple>

DPGEN_KERNEL void grad_staggered_rowptr(DPGEN_IN double** p, DPGEN_OUT double** gx,
                                        DPGEN_OUT double** gy, int nx, int ny, double inv_h);

TEST_CASE("styles: grad_staggered_rowptr") {
  for (auto [nx, ny] : {std::tuple{1, 1}, {1, 3}, {2, 2}, {4, 3}, {7, 5}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    size_t X = size_t(nx), Y = size_t(ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {X * Y};
    p.out_sizes = {Y * (X + 1), (Y + 1) * X};
    p.linear = true;
    p.forward = [&](auto in, auto out) {
      auto pr = styles::rows(in[0], Y, X);
      auto gx = styles::rows(out[0], Y, X + 1);
      auto gy = styles::rows(out[1], Y + 1, X);
      grad_staggered_rowptr(pr.data(), gx.data(), gy.data(), nx, ny, 3.0);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      auto pr = styles::rows(in[0], Y, X);
      auto pa = styles::rows(adj[0], Y, X);
      auto gx = styles::rows(seed[0], Y, X + 1);
      auto gy = styles::rows(seed[1], Y + 1, X);
      grad_staggered_rowptr_adjoint(pr.data(), pa.data(), gx.data(), gy.data(), nx, ny, 3.0);
    };
    dpgen_test::check_adjoint(p);
  }
}
