// edge_rows_rowptr (tests/styles/): stores and reads of `double**` arrays at
// constant rows (issue 20, defect 1). Row pointers in the adjoint, as in
// restrict2d_rowptr_test.cpp.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "edge_rows_rowptr_adjoint.hpp"
#include "styles_support.hpp"

#include <tuple>

DPGEN_KERNEL void edge_rows_rowptr(DPGEN_IN double** a, DPGEN_OUT double** e, int nx, int ny,
                                   double inv_h);

TEST_CASE("styles: edge_rows_rowptr") {
  for (auto [nx, ny] : {std::tuple{1, 2}, {3, 2}, {4, 5}, {6, 3}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    size_t X = size_t(nx), Y = size_t(ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {X * Y};
    p.out_sizes = {2 * X};
    p.forward = [&](auto in, auto out) {
      auto a = styles::rows(in[0], Y, X);
      auto e = styles::rows(out[0], 2, X);
      edge_rows_rowptr(a.data(), e.data(), nx, ny, 0.5);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      auto a = styles::rows(in[0], Y, X);
      auto aa = styles::rows(adj[0], Y, X);
      auto es = styles::rows(seed[0], 2, X);
      edge_rows_rowptr_adjoint(a.data(), aa.data(), es.data(), nx, ny, 0.5);
    };
    dpgen_test::check_adjoint(p);
  }
}
