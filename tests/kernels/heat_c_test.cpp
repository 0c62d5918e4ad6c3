// heat_c (tests/kernels/heat_c.c): a C kernel with VLA 2D arrays; its adjoint
// has C linkage and flat arrays.
#include "support/adjoint_check.hpp"

#include "heat_c_adjoint.hpp"
#include "heat_c_tangent.hpp"

#include "heat_c_kernels.hpp" // the generated declaration of the C kernel

TEST_CASE("heat_c adjoint (a C kernel)") {
  for (int n : {0, 1, 2, 3, 6}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n * n), 1};
    p.out_sizes = {size_t(n * n)};
    p.forward = [&](auto in, auto out) { heat_c(n, in[0], in[1], out[0], 0.2); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      heat_c_adjoint(n, in[0], adj[0], in[1], adj[1], seed[0], 0.2);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      heat_c_adjoint_checked(n, in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], 0.2);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      heat_c_tangent(n, in[0], dir[0], in[1], dir[1], out[0], outd[0], 0.2);
    };
    dpgen_test::check_adjoint(p);
  }
}
