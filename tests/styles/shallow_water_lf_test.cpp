// shallow_water_lf (tests/styles/): function-scope temporaries (OpenMP
// private), C89 counter, omp pragma; nonlinear (h kept in [1, 2]).
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "shallow_water_lf_adjoint.hpp"
#include "shallow_water_lf_tangent.hpp"

DPGEN_KERNEL void shallow_water_lf(DPGEN_IN const double* h, DPGEN_IN const double* hu,
                                   DPGEN_OUT double* h_new, DPGEN_OUT double* hu_new, int n,
                                   double dt_dx, double g);

TEST_CASE("styles: shallow_water_lf") {
  for (int n : {1, 2, 3, 6, 20}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n), size_t(n)};
    p.out_sizes = {size_t(n), size_t(n)};
    p.in_ranges = {{1.0, 2.0}, {-0.5, 0.5}};
    p.forward = [&](auto in, auto out) {
      shallow_water_lf(in[0], in[1], out[0], out[1], n, 0.1, 9.81);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      shallow_water_lf_adjoint(in[0], adj[0], in[1], adj[1], seed[0], seed[1], n, 0.1, 9.81);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      shallow_water_lf_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], seed[1], out_n[1], n, 0.1, 9.81);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      shallow_water_lf_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], out[1], outd[1], n, 0.1, 9.81);
    };
    dpgen_test::check_adjoint(p);
  }
}
