// The adjoint checker itself (tests/support/adjoint_check.hpp) fails where it must: hand-written
// kernels with their exact adjoint pass, and the same with one defect each must fail
// (doctest::should_fail: the case passes only if a check in it fails). The sizes go past the
// generated adjoints' parallel threshold (8,192 cells), where the gradient test moves one cell
// at a time in a working copy and reuses its outputs.
#include <doctest/doctest.h>

#include "support/adjoint_check.hpp"

#include <cstddef>
#include <vector>

namespace {

// y_i = x_i^2 x_{i+1} on i < n - 1 (n inputs, n - 1 outputs); its adjoint, and `wrong_cell`
// (when below n) gets one term too few.
dpgen_test::Problem<double> product_chain(size_t n, size_t wrong_cell) {
  dpgen_test::Problem<double> p;
  p.in_sizes = {n};
  p.out_sizes = {n - 1};
  p.forward = [n](auto in, auto out) {
    for (size_t i = 0; i + 1 < n; ++i)
      out[0][i] = in[0][i] * in[0][i] * in[0][i + 1];
  };
  p.adjoint = [n, wrong_cell](auto in, auto adj, auto seed) {
    const double* x = in[0];
    for (size_t i = 0; i < n; ++i) {
      double g = 0.0;
      if (i + 1 < n)
        g += 2.0 * x[i] * x[i + 1] * seed[0][i];
      if (i > 0 && i != wrong_cell)
        g += x[i - 1] * x[i - 1] * seed[0][i - 1];
      adj[0][i] += g;
    }
  };
  return p;
}

} // namespace

TEST_CASE("checker: an exact adjoint passes, at sizes past the parallel threshold") {
  for (size_t n : {2, 17, 8300}) {
    CAPTURE(n);
    dpgen_test::check_adjoint(product_chain(n, n));
  }
}

TEST_CASE("checker: an adjoint wrong in its last cell fails" * doctest::should_fail()) {
  dpgen_test::check_adjoint(product_chain(8300, 8299));
}

TEST_CASE("checker: an adjoint wrong in one middle cell fails" * doctest::should_fail()) {
  dpgen_test::check_adjoint(product_chain(8300, 4100));
}

TEST_CASE("checker: a forward that changes its input fails" * doctest::should_fail()) {
  dpgen_test::Problem<double> p = product_chain(300, 300);
  const auto exact = p.forward;
  p.forward = [exact](auto in, auto out) {
    exact(in, out);
    const_cast<double*>(in[0])[7] += 1.0; // (a kernel with DPGEN_IN data it writes)
  };
  dpgen_test::check_adjoint(p);
}

TEST_CASE("checker: a forward that writes past its output fails" * doctest::should_fail()) {
  dpgen_test::Problem<double> p = product_chain(300, 300);
  const auto exact = p.forward;
  p.forward = [exact](auto in, auto out) {
    exact(in, out);
    out[0][299] = 1.0; // one past the 299 outputs: into the guard cells
  };
  dpgen_test::check_adjoint(p);
}
