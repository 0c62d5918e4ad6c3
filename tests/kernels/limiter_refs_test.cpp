// limiter_refs (tests/kernels/limiter_refs.cpp): void helpers with reference
// out-parameters (a branch inside) and one that stores into an output.
#include "support/adjoint_check.hpp"

#include "limiter_refs_adjoint.hpp"
#include "limiter_refs_kernels.hpp"
#include "limiter_refs_tangent.hpp"

TEST_CASE("limiter_refs adjoint (void helpers: reference out-parameters, a store)") {
  for (double c : {0.7, -0.4})
    for (int n : {0, 3, 4, 5, 12}) {
      CAPTURE(n);
      CAPTURE(c);
      dpgen_test::Problem<double> p;
      p.in_sizes = {size_t(n)};
      p.out_sizes = {size_t(n)};
      p.forward = [&](auto in, auto out) { limiter_refs(in[0], out[0], n, c); };
      p.adjoint = [&](auto in, auto adj, auto seed) {
        limiter_refs_adjoint(in[0], adj[0], seed[0], n, c);
      };
      p.tangent = [&](auto in, auto dir, auto out, auto od) {
        limiter_refs_tangent(in[0], dir[0], out[0], od[0], n, c);
      };
      p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
        limiter_refs_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n, c);
      };
      dpgen_test::check_adjoint(p);
    }
}
