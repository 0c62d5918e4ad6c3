// twin_limiter_kernels (tests/styles/): two identical kernels with a helper.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "twin_limiter_kernels_adjoint.hpp"

DPGEN_KERNEL void limit_rho(DPGEN_IN const double* q, DPGEN_OUT double* dq, int n, double w);
DPGEN_KERNEL void limit_mom(DPGEN_IN const double* q, DPGEN_OUT double* dq, int n, double w);

TEST_CASE("styles: twin_limiter_kernels") {
  for (int n : {1, 2, 3, 13}) {
    CAPTURE(n);
    for (int which = 0; which < 2; ++which) {
      CAPTURE(which);
      dpgen_test::Problem<double> p;
      p.in_sizes = {size_t(n)};
      p.out_sizes = {size_t(n)};
      p.forward = [&](auto in, auto out) { (which ? limit_mom : limit_rho)(in[0], out[0], n, 0.5); };
      p.adjoint = [&](auto in, auto adj, auto seed) {
        (which ? limit_mom_adjoint : limit_rho_adjoint)(in[0], adj[0], seed[0], n, 0.5);
      };
      dpgen_test::check_adjoint(p);
    }
  }
}
