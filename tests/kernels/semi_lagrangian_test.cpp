// semi_lagrangian (tests/kernels/): data-dependent reads, scatter adjoint.
#include "support/adjoint_check.hpp"

#include "semi_lagrangian_adjoint.hpp"
#include "semi_lagrangian_tangent.hpp"
#include "test_kernels.hpp"

TEST_CASE("semi_lagrangian adjoint (scatter form)") {
  for (int n : {1, 2, 5, 32}) {
    CAPTURE(n);
    const double dt = 0.7, dx = 0.5; // traces back up to ~1.4 cells
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n), size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { semi_lagrangian(in[0], in[1], out[0], n, dt, dx); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      semi_lagrangian_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n, dt, dx);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      semi_lagrangian_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], n, dt, dx);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      semi_lagrangian_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], n, dt, dx);
    };
    dpgen_test::check_adjoint(p);
  }
}
