// ghost_rows_rowptr (tests/styles/): a `double**` array read at constant rows
// (issue 20, defect 1). Row pointers in the adjoint, as in
// restrict2d_rowptr_test.cpp.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "ghost_rows_rowptr_adjoint.hpp"
#include "styles_support.hpp"

#include <tuple>

DPGEN_KERNEL void ghost_rows_rowptr(DPGEN_IN double** a, DPGEN_OUT double** b, int nx, int ny,
                                    int ng);

TEST_CASE("styles: ghost_rows_rowptr") {
  for (auto [nx, ny, ng] : {std::tuple{1, 1, 1}, {3, 4, 1}, {4, 6, 2}, {5, 3, 0}, {2, 5, 5}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    CAPTURE(ng);
    size_t X = size_t(nx), Y = size_t(ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {X * Y};
    p.out_sizes = {X * Y};
    p.forward = [&](auto in, auto out) {
      auto a = styles::rows(in[0], Y, X);
      auto b = styles::rows(out[0], Y, X);
      ghost_rows_rowptr(a.data(), b.data(), nx, ny, ng);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      auto a = styles::rows(in[0], Y, X);
      auto aa = styles::rows(adj[0], Y, X);
      auto bs = styles::rows(seed[0], Y, X);
      ghost_rows_rowptr_adjoint(a.data(), aa.data(), bs.data(), nx, ny, ng);
    };
    dpgen_test::check_adjoint(p);
  }
}
