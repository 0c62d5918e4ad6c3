// pointer_locals (tests/styles/): each kernel's adjoint and tangent against the checker's
// differences and the dot-product test on small grids; on grids of 8192 cells and more the
// parallel forward and the tangent's primal against the kernel bit for bit, on 1 and 2
// threads. The old generator refused every kernel of the file.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "entry_checks.hpp"
#include "pointer_locals_adjoint.hpp"
#include "pointer_locals_kernels.hpp"
#include "pointer_locals_tangent.hpp"

#include <cstddef>
#include <stdexcept>
#include <vector>

using dpgen_test::check_large;
using dpgen_test::check_small;

TEST_CASE("styles: row pointers (2D)") {
  const int sizes[][2] = {{2, 1}, {2, 3}, {3, 3}, {5, 4}, {7, 2}};
  for (const auto& s : sizes) {
    const int nx = s[0], ny = s[1];
    CAPTURE(nx);
    CAPTURE(ny);
    const double inv_h2 = 0.7;
    const size_t cells = size_t(nx) * size_t(ny);
    check_small(DPGEN_TEST_GRID_ENTRY(rows_in_out, nx, ny));
    check_small(DPGEN_TEST_ENTRY(laplace_rows, cells, cells, nx, ny, inv_h2));
    check_small(DPGEN_TEST_GRID_ENTRY(deref_sums, nx, ny));
    check_small(DPGEN_TEST_GRID_ENTRY(helper_rows, nx, ny));
    check_small(DPGEN_TEST_GRID_ENTRY(c_casts, nx, ny));
    check_small(DPGEN_TEST_GRID_ENTRY(ref_neighbours, nx, ny));
  }
  const int nx = 128, ny = 80; // 10240 cells: the nests run on every thread
  const double inv_h2 = 1.3;
  check_large(DPGEN_TEST_GRID_ENTRY(rows_in_out, nx, ny));
  check_large(DPGEN_TEST_ENTRY(laplace_rows, nx * ny, nx * ny, nx, ny, inv_h2));
  check_large(DPGEN_TEST_GRID_ENTRY(deref_sums, nx, ny));
  check_large(DPGEN_TEST_GRID_ENTRY(helper_rows, nx, ny));
  check_large(DPGEN_TEST_GRID_ENTRY(c_casts, nx, ny));
  check_large(DPGEN_TEST_GRID_ENTRY(ref_neighbours, nx, ny));
  // One column: a row's first and last cells are one element, stored twice: the adjoint
  // says so at run time.
  std::vector<double> a(3, 0.5), adj(3, 0.0), seed(3, 1.0);
  CHECK_THROWS_AS(helper_rows_adjoint(a.data(), adj.data(), seed.data(), 1, 3),
                  std::invalid_argument);
}

TEST_CASE("styles: plane and row pointers (3D), a sum through a pointer, shifted bases") {
  dpgen_test::for_3d_grids([](int nx, int ny, int nz, bool large) {
    const size_t cells = size_t(nx) * size_t(ny) * size_t(nz);
    (large ? check_large : check_small)(DPGEN_TEST_ENTRY(planes_rows, cells, cells, nx, ny, nz));
  });
  for (int n : {0, 1, 2, 7, 9000}) {
    CAPTURE(n);
    const size_t N = size_t(n), M = n > 0 ? N - 1 : 0;
    (n < 9000 ? check_small : check_large)(DPGEN_TEST_ENTRY(shifted_base, N, M, n));
    if (n < 9000) // (a sum: no parallel forward)
      dpgen_test::check_one_to_one(
          N, 1, [&](auto a, auto e) { total_through_pointer(a, e, n); },
          [&](auto a, auto adj, auto seed) { total_through_pointer_adjoint(a, adj, seed, n); },
          [&](auto a, auto d, auto e, auto ed) { total_through_pointer_tangent(a, d, e, ed, n); });
  }
}

TEST_CASE("styles: a lambda reading captured row pointers") {
  const int sizes[][2] = {{1, 1}, {3, 2}, {6, 5}};
  for (const auto& s : sizes) {
    const int nx = s[0], ny = s[1];
    CAPTURE(nx);
    const size_t cells = size_t(nx) * size_t(ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {cells, cells};
    p.out_sizes = {cells};
    p.forward = [&](auto in, auto out) { lambda_rows(in[0], in[1], out[0], nx, ny); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      lambda_rows_adjoint(in[0], adj[0], in[1], adj[1], seed[0], nx, ny);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      lambda_rows_tangent(in[0], d[0], in[1], d[1], out[0], dout[0], nx, ny);
    };
    dpgen_test::check_adjoint(p);
  }
}
