// restrict2d_rowptr (tests/styles/): `double**` row pointers, stride-2 reads.
// Assumption: the adjoint takes row pointers too, rows disjoint:
//   restrict2d_rowptr_adjoint(double** fine, double** fine_adj,
//                             <double** or const double* const*> coarse_adj, int, int)
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "restrict2d_rowptr_adjoint.hpp"
#include "styles_support.hpp"

#include <tuple>

DPGEN_KERNEL void restrict2d_rowptr(DPGEN_IN double** fine, DPGEN_OUT double** coarse, int ncx,
                                    int ncy);

TEST_CASE("styles: restrict2d_rowptr") {
  for (auto [ncx, ncy] : {std::tuple{1, 1}, {2, 2}, {3, 3}, {4, 3}, {5, 6}}) {
    CAPTURE(ncx);
    CAPTURE(ncy);
    size_t nfx = size_t(2 * ncx - 1), nfy = size_t(2 * ncy - 1);
    dpgen_test::Problem<double> p;
    p.in_sizes = {nfx * nfy};
    p.out_sizes = {size_t(ncx * ncy)};
    p.linear = true;
    p.forward = [&](auto in, auto out) {
      auto f = styles::rows(in[0], nfy, nfx);
      auto c = styles::rows(out[0], size_t(ncy), size_t(ncx));
      restrict2d_rowptr(f.data(), c.data(), ncx, ncy);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      auto f = styles::rows(in[0], nfy, nfx);
      auto fa = styles::rows(adj[0], nfy, nfx);
      auto ca = styles::rows(seed[0], size_t(ncy), size_t(ncx));
      restrict2d_rowptr_adjoint(f.data(), fa.data(), ca.data(), ncx, ncy);
    };
    dpgen_test::check_adjoint(p);
  }
}
