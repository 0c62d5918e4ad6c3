// loop_local_bounds (tests/styles/): each kernel's adjoint and tangent against the
// checker's differences and the dot-product test on small grids; on grids of 8192 cells
// and more (where the parallel forward and the tangent run their nests on every thread)
// the parallel forward and the tangent's primal against the kernel bit for bit, on 1 and
// 2 threads. With the generator before this test, the parallel forwards and tangents of
// five of these kernels did not compile.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "entry_checks.hpp"
#include "loop_local_bounds_adjoint.hpp"
#include "loop_local_bounds_kernels.hpp"
#include "loop_local_bounds_tangent.hpp"

#include <cstddef>
#include <stdexcept>
#include <vector>

namespace {
using dpgen_test::check_large;
using dpgen_test::check_small;
using Vec = std::vector<double>;
} // namespace

TEST_CASE("styles: row loops with local bounds (2D)") {
  const int sizes[][2] = {{2, 1}, {2, 3}, {3, 3}, {5, 4}, {7, 2}};
  for (const auto& s : sizes) {
    const int nx = s[0], ny = s[1];
    CAPTURE(nx);
    CAPTURE(ny);
    check_small(DPGEN_TEST_GRID_ENTRY(row_width_local, nx, ny));
    check_small(DPGEN_TEST_GRID_ENTRY(c89_interior, nx, ny));
    check_small(DPGEN_TEST_GRID_ENTRY(pfor_in_loop, nx, ny));
    check_small(DPGEN_TEST_GRID_ENTRY(helper_row_loop, nx, ny));
    check_small(DPGEN_TEST_GRID_ENTRY(lambda_row_loop, nx, ny));
  }
  // One column: the first and last cells of a row are one element, stored twice, and the
  // adjoints of the kernels that store them apart say so at run time.
  for (int ny : {1, 3}) {
    Vec a(size_t(ny), 0.5), adj(size_t(ny), 0.0), seed(size_t(ny), 1.0);
    CHECK_THROWS_AS(c89_interior_adjoint(a.data(), adj.data(), seed.data(), 1, ny),
                    std::invalid_argument);
    CHECK_THROWS_AS(helper_row_loop_adjoint(a.data(), adj.data(), seed.data(), 1, ny),
                    std::invalid_argument);
    CHECK_THROWS_AS(lambda_row_loop_adjoint(a.data(), adj.data(), seed.data(), 1, ny),
                    std::invalid_argument);
    check_small(DPGEN_TEST_GRID_ENTRY(row_width_local, 1, ny));
    check_small(DPGEN_TEST_GRID_ENTRY(pfor_in_loop, 1, ny));
  }
  const int nx = 128, ny = 80; // 10240 cells: the nests run on every thread
  check_large(DPGEN_TEST_GRID_ENTRY(row_width_local, nx, ny));
  check_large(DPGEN_TEST_GRID_ENTRY(c89_interior, nx, ny));
  check_large(DPGEN_TEST_GRID_ENTRY(pfor_in_loop, nx, ny));
  check_large(DPGEN_TEST_GRID_ENTRY(helper_row_loop, nx, ny));
  check_large(DPGEN_TEST_GRID_ENTRY(lambda_row_loop, nx, ny));
}

TEST_CASE("styles: nested ParallelFor, 3D planes") {
  for (int n : {0, 1, 2, 5, 96}) {
    CAPTURE(n);
    const size_t cells = size_t(n) * size_t(n);
    (n < 96 ? check_small : check_large)(DPGEN_TEST_ENTRY(pfor_nested, cells, cells, n));
  }
  dpgen_test::for_3d_grids([](int nx, int ny, int nz, bool large) {
    const size_t cells = size_t(nx) * size_t(ny) * size_t(nz);
    (large ? check_large : check_small)(DPGEN_TEST_ENTRY(planes_3d, cells, cells, nx, ny, nz));
  });
}

TEST_CASE("styles: a bound read from the data, named in the row loop") {
  for (int w : {0, 2, 9}) {
    CAPTURE(w);
    const int width[1] = {w};
    for (int nx : {1, 4}) {
      const int ny = 3;
      const size_t cells = size_t(nx) * size_t(ny);
      check_small(DPGEN_TEST_ENTRY(width_from_data, cells, cells, width, nx, ny));
    }
    const int nx = 128, ny = 80;
    check_large(DPGEN_TEST_ENTRY(width_from_data, size_t(nx * ny), size_t(nx * ny), width, nx, ny));
  }
}
