// end_columns (tests/styles/): end columns next to an interior nest in one row
// loop (issue 20); nx = 1 (both ends the same element) is refused on entry.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "end_columns_adjoint.hpp"
#include "end_columns_kernels.hpp"
#include "end_columns_tangent.hpp"

#include <stdexcept>
#include <tuple>
#include <vector>

TEST_CASE("styles: end_columns") {
  for (auto [nx, ny] : {std::tuple{2, 1}, {3, 4}, {8, 3}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    size_t N = size_t(nx) * size_t(ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {N};
    p.out_sizes = {N};
    p.forward = [&](auto in, auto out) { end_columns(in[0], out[0], nx, ny, 0.2); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      end_columns_adjoint(in[0], adj[0], seed[0], nx, ny, 0.2);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      end_columns_tangent(in[0], d[0], out[0], dout[0], nx, ny, 0.2);
    };
    dpgen_test::check_adjoint(p);
  }
  std::vector<double> u(3, 1.0), ua(3, 0.0), seed(3, 1.0);
  CHECK_THROWS_AS(end_columns_adjoint(u.data(), ua.data(), seed.data(), 1, 3, 0.2),
                  std::invalid_argument);
}
