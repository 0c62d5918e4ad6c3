// viscosity_linebuffer (tests/styles/): per-iteration local arrays
// `double v[5]`, `double d[4]` filled by inner loops; nonlinear (|x| x).
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "viscosity_linebuffer_adjoint.hpp"
#include "viscosity_linebuffer_tangent.hpp"

DPGEN_KERNEL void viscosity_linebuffer(DPGEN_IN const double* q, DPGEN_OUT double* out, int n,
                                       double eps);

TEST_CASE("styles: viscosity_linebuffer") {
  for (int n : {1, 4, 5, 6, 22}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { viscosity_linebuffer(in[0], out[0], n, 0.3); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      viscosity_linebuffer_adjoint(in[0], adj[0], seed[0], n, 0.3);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      viscosity_linebuffer_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n, 0.3);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      viscosity_linebuffer_tangent(in[0], dir[0], out[0], outd[0], n, 0.3);
    };
    dpgen_test::check_adjoint(p);
  }
}
