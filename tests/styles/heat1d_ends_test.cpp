// heat1d_ends (tests/styles/): end stores outside the loop, no guard. n == 1
// makes the two end stores overwrite the same cell: a correct adjoint counts
// only the last one.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "heat1d_ends_adjoint.hpp"
#include "heat1d_ends_tangent.hpp"

DPGEN_KERNEL void heat1d_ends(DPGEN_IN const double* t, DPGEN_IN const double* k,
                              DPGEN_OUT double* t_new, int n, double r);

TEST_CASE("styles: heat1d_ends") {
  for (int n : {1, 2, 3, 5, 16}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n), size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { heat1d_ends(in[0], in[1], out[0], n, 0.25); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      heat1d_ends_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n, 0.25);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      heat1d_ends_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], n, 0.25);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      heat1d_ends_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], n, 0.25);
    };
    dpgen_test::check_adjoint(p);
  }
}
