// twin_kernels (tests/styles/): two identical kernels in one file; both
// adjoints checked, and they must agree bit for bit.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "twin_kernels_adjoint.hpp"

#include <vector>

DPGEN_KERNEL void smooth_sq_x(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, double s);
DPGEN_KERNEL void smooth_sq_y(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, double s);

TEST_CASE("styles: twin_kernels") {
  for (int n : {1, 2, 3, 11}) {
    CAPTURE(n);
    for (int which = 0; which < 2; ++which) {
      CAPTURE(which);
      dpgen_test::Problem<double> p;
      p.in_sizes = {size_t(n)};
      p.out_sizes = {size_t(n)};
      p.forward = [&](auto in, auto out) {
        (which ? smooth_sq_y : smooth_sq_x)(in[0], out[0], n, 0.2);
      };
      p.adjoint = [&](auto in, auto adj, auto seed) {
        (which ? smooth_sq_y_adjoint : smooth_sq_x_adjoint)(in[0], adj[0], seed[0], n, 0.2);
      };
      dpgen_test::check_adjoint(p);
    }
    const size_t N = static_cast<size_t>(n);
    std::vector<double> a(N), g(N), ax(N, 0.0), ay(N, 0.0);
    for (int i = 0; i < n; ++i) {
      a[size_t(i)] = 0.1 * i * i - 0.3;
      g[size_t(i)] = 1.0 - 0.07 * i;
    }
    smooth_sq_x_adjoint(a.data(), ax.data(), g.data(), n, 0.2);
    smooth_sq_y_adjoint(a.data(), ay.data(), g.data(), n, 0.2);
    CHECK(ax == ay);
  }
}
