// enum_params (tests/styles/): an enum class parameter from a header, by value
// and by const reference. Each kind: adjoint and tangent against the
// checker's differences, v[0] by hand.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "enum_params_adjoint.hpp"
#include "enum_params_kernels.hpp"
#include "enum_params_tangent.hpp"

TEST_CASE("styles: enum_class_bc") {
  for (Bc bc : {Bc::Zero, Bc::Copy, Bc::Flip}) {
    for (int n : {2, 3, 7}) {
      CAPTURE(int(bc));
      CAPTURE(n);
      const size_t N = size_t(n);
      dpgen_test::check_one_to_one(
          N, N, [&](auto u, auto v) { enum_class_bc(u, v, n, bc); },
          [&](auto u, auto adj, auto seed) { enum_class_bc_adjoint(u, adj, seed, n, bc); },
          [&](auto u, auto d, auto v, auto vd) { enum_class_bc_tangent(u, d, v, vd, n, bc); });
    }
    const double u[2] = {2.0, 3.0};
    double v[2] = {0.0, 0.0};
    enum_class_bc(u, v, 2, bc);
    CHECK(v[0] == (bc == Bc::Zero ? 0.0 : bc == Bc::Copy ? 6.0 : -6.0));
  }
}

TEST_CASE("styles: enum_ref_bc") {
  for (Bc bc : {Bc::Zero, Bc::Copy, Bc::Flip}) {
    for (int n : {1, 2, 5}) {
      CAPTURE(int(bc));
      CAPTURE(n);
      const size_t N = size_t(n);
      const Bc& ref = bc;
      dpgen_test::check_one_to_one(
          N, N, [&](auto u, auto v) { enum_ref_bc(u, v, n, ref); },
          [&](auto u, auto adj, auto seed) { enum_ref_bc_adjoint(u, adj, seed, n, ref); },
          [&](auto u, auto d, auto v, auto vd) { enum_ref_bc_tangent(u, d, v, vd, n, ref); });
    }
    const double u[1] = {3.0};
    double v[1] = {1.0};
    enum_ref_bc(u, v, 1, bc);
    CHECK(v[0] == (bc == Bc::Zero ? 0.0 : bc == Bc::Copy ? 3.0 : -9.0));
  }
}

TEST_CASE("styles: enum_member_bc, EdgeSolver::run") {
  for (Bc bc : {Bc::Zero, Bc::Copy, Bc::Flip}) {
    for (int n : {0, 1, 2, 5}) {
      CAPTURE(int(bc));
      CAPTURE(n);
      const size_t N = size_t(n);
      const BcParams p{0.25, bc};
      dpgen_test::check_one_to_one(
          N, N, [&](auto u, auto v) { enum_member_bc(u, v, n, p); },
          [&](auto u, auto adj, auto seed) { enum_member_bc_adjoint(u, adj, seed, n, p); },
          [&](auto u, auto d, auto v, auto vd) { enum_member_bc_tangent(u, d, v, vd, n, p); });
      dpgen_test::Problem<double> q;
      q.in_sizes = {N};
      q.out_sizes = {N};
      q.forward = [&](auto in, auto out) { EdgeSolver(n, bc, in[0], out[0]).run(); };
      q.adjoint = [&](auto in, auto adj, auto seed) {
        EdgeSolver_run_adjoint(EdgeSolver(n, bc, in[0], nullptr), adj[0], seed[0]);
      };
      q.tangent = [&](auto in, auto d, auto out, auto dout) {
        EdgeSolver s(n, bc, in[0], out[0]);
        EdgeSolver_run_tangent(s, d[0], dout[0]);
      };
      dpgen_test::check_adjoint(q);
    }
    // by hand: u = 2, 3, 4
    const double u[3] = {2.0, 3.0, 4.0};
    double v[3] = {0.0, 0.0, 0.0};
    EdgeSolver(3, bc, u, v).run();
    CHECK(v[0] == (bc == Bc::Zero ? 0.0 : 4.0));
    CHECK(v[1] == 9.0);
    enum_member_bc(u, v, 3, BcParams{0.5, bc});
    CHECK(v[2] == (bc == Bc::Flip ? -2.0 : 8.0));
  }
}
