// advect_minmod_helper (tests/styles/): static inline helper with early
// returns; piecewise linear.
#include "support/adjoint_check.hpp"

#include "advect_minmod_helper_adjoint.hpp"
#include "advect_minmod_helper_tangent.hpp"
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void advect_minmod_helper(DPGEN_IN const double* q, DPGEN_OUT double* q_new, int n,
                                       double c);

TEST_CASE("styles: advect_minmod_helper") {
  for (int n : {1, 3, 4, 9, 27}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { advect_minmod_helper(in[0], out[0], n, 0.4); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      advect_minmod_helper_adjoint(in[0], adj[0], seed[0], n, 0.4);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      advect_minmod_helper_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n, 0.4);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      advect_minmod_helper_tangent(in[0], dir[0], out[0], outd[0], n, 0.4);
    };
    dpgen_test::check_adjoint(p);
  }
}
