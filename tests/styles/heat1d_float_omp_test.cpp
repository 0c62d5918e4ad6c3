// heat1d_float_omp (tests/styles/): float, omp parallel for; nonlinear.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "heat1d_float_omp_adjoint.hpp"
#include "heat1d_float_omp_tangent.hpp"

DPGEN_KERNEL void heat1d_float_omp(DPGEN_IN const float* t, DPGEN_OUT float* t_new, int n,
                                   float r);

TEST_CASE("styles: heat1d_float_omp") {
  for (int n : {1, 2, 3, 10, 33}) {
    CAPTURE(n);
    dpgen_test::Problem<float> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { heat1d_float_omp(in[0], out[0], n, 0.2f); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      heat1d_float_omp_adjoint(in[0], adj[0], seed[0], n, 0.2f);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      heat1d_float_omp_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n, 0.2f);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      heat1d_float_omp_tangent(in[0], dir[0], out[0], outd[0], n, 0.2f);
    };
    dpgen_test::check_adjoint(p);
  }
}
