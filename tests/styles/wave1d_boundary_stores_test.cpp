// wave1d_boundary_stores (tests/styles/): guard + stores at u[0]/u[n-1]
// outside the interior loop; linear.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "wave1d_boundary_stores_adjoint.hpp"
#include "wave1d_boundary_stores_tangent.hpp"

DPGEN_KERNEL void wave1d_boundary_stores(DPGEN_IN const double* u, DPGEN_IN const double* u_prev,
                                         DPGEN_OUT double* u_next, int n, double c2);

TEST_CASE("styles: wave1d_boundary_stores") {
  for (int n : {1, 2, 3, 4, 12}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n), size_t(n)};
    p.out_sizes = {size_t(n)};
    p.linear = true;
    p.forward = [&](auto in, auto out) { wave1d_boundary_stores(in[0], in[1], out[0], n, 0.36); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      wave1d_boundary_stores_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n, 0.36);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      wave1d_boundary_stores_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], n, 0.36);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      wave1d_boundary_stores_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], n, 0.36);
    };
    dpgen_test::check_adjoint(p);
  }
}
