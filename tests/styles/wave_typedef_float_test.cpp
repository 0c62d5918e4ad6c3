// wave_typedef_float (tests/styles/): `typedef float FLOAT;`, float; linear.
#include "wave_typedef_float_adjoint.hpp"
#include "wave_typedef_float_tangent.hpp"

#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"

DPGEN_KERNEL void wave_typedef_float(DPGEN_IN const float* u, DPGEN_IN const float* u_prev,
                                     DPGEN_OUT float* u_next, int n, float c2);

TEST_CASE("styles: wave_typedef_float") {
  for (int n : {1, 2, 3, 16}) {
    CAPTURE(n);
    dpgen_test::Problem<float> p;
    p.in_sizes = {size_t(n), size_t(n)};
    p.out_sizes = {size_t(n)};
    p.linear = true;
    p.forward = [&](auto in, auto out) { wave_typedef_float(in[0], in[1], out[0], n, 0.3f); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      wave_typedef_float_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n, 0.3f);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      wave_typedef_float_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], n, 0.3f);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      wave_typedef_float_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], n, 0.3f);
    };
    dpgen_test::check_adjoint(p);
  }
}
