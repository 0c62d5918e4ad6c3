// advect_upwind_ptrscalars (tests/styles/): n, dt, dx by pointer; piecewise
// bilinear.
#include "support/adjoint_check.hpp"

#include "advect_upwind_ptrscalars_adjoint.hpp"
#include "advect_upwind_ptrscalars_tangent.hpp"
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void advect_upwind_ptrscalars(const int* n, const double* dt, const double* dx,
                                           DPGEN_IN const double* q, DPGEN_IN const double* u,
                                           DPGEN_OUT double* q_new);

TEST_CASE("styles: advect_upwind_ptrscalars") {
  for (int n : {1, 2, 3, 8, 21}) {
    CAPTURE(n);
    const double dt = 0.02, dx = 0.1;
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n), size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) {
      advect_upwind_ptrscalars(&n, &dt, &dx, in[0], in[1], out[0]);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      advect_upwind_ptrscalars_adjoint(&n, &dt, &dx, in[0], adj[0], in[1], adj[1], seed[0]);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      advect_upwind_ptrscalars_tangent(&n, &dt, &dx, in[0], dir[0], in[1], dir[1], out[0], outd[0]);
    };
    dpgen_test::check_adjoint(p);
  }
}
