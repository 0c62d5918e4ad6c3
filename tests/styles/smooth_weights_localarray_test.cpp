// smooth_weights_localarray (tests/styles/): `const double w[3]`, inner tap
// loop; linear.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "smooth_weights_localarray_adjoint.hpp"
#include "smooth_weights_localarray_tangent.hpp"

DPGEN_KERNEL void smooth_weights_localarray(DPGEN_IN const double* a, DPGEN_OUT double* out,
                                            int n);

TEST_CASE("styles: smooth_weights_localarray") {
  for (int n : {1, 2, 3, 6, 30}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.linear = true;
    p.forward = [&](auto in, auto out) { smooth_weights_localarray(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      smooth_weights_localarray_adjoint(in[0], adj[0], seed[0], n);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      smooth_weights_localarray_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      smooth_weights_localarray_tangent(in[0], dir[0], out[0], outd[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
