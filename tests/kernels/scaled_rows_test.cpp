// scaled_rows (tests/kernels/): reads that drop a counter (c[i], nu[0]) and
// an unmarked constant array.
#include "support/adjoint_check.hpp"

#include "scaled_rows_adjoint.hpp"
#include "scaled_rows_tangent.hpp"
#include "test_kernels.hpp"

#include <type_traits>

// The unmarked `mask` stays a plain const input, without an adjoint.
static_assert(std::is_same_v<decltype(&scaled_rows_adjoint),
                             void (*)(const double*, double*, const double*, double*,
                                      const double*, double*, const double*, const double*, int,
                                      int)>);

TEST_CASE("scaled_rows adjoint") {
  for (auto [nx, ny] : {std::pair{1, 1}, {3, 4}, {8, 5}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    size_t n = size_t(nx * ny);
    std::vector<double> mask(n);
    for (size_t i = 0; i < n; ++i)
      mask[i] = 0.5 + 0.25 * double(i % 3);
    dpgen_test::Problem<double> p;
    p.in_sizes = {n, size_t(nx), 1};
    p.out_sizes = {n};
    p.forward = [&](auto in, auto out) {
      scaled_rows(in[0], in[1], in[2], mask.data(), out[0], nx, ny);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      scaled_rows_adjoint(in[0], adj[0], in[1], adj[1], in[2], adj[2], mask.data(), seed[0], nx,
                          ny);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      scaled_rows_tangent(in[0], dir[0], in[1], dir[1], in[2], dir[2], mask.data(), out[0], outd[0], nx, ny);
    };
    dpgen_test::check_adjoint(p);
  }
}
