// view_branches (tests/styles/): views read in branches. Adjoint and tangent
// against the checker's differences, values by hand (the old generator read
// the wrong element there).
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "view_branches_adjoint.hpp"
#include "view_branches_kernels.hpp"
#include "view_branches_tangent.hpp"

TEST_CASE("styles: view_left_in_branch, view_upwind_arms") {
  for (auto [nx, ny] : {std::pair{1, 1}, {3, 1}, {3, 4}, {5, 2}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t n = size_t(nx) * size_t(ny);
    auto cv = [&](const double* p) { return grid::View2D<const double>{p, nx, ny}; };
    auto mv = [&](double* p) { return grid::View2D<double>{p, nx, ny}; };
    dpgen_test::Problem<double> p;
    p.in_sizes = {n};
    p.out_sizes = {n};
    p.forward = [&](auto in, auto out) { view_left_in_branch(cv(in[0]), mv(out[0])); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      view_left_in_branch_adjoint(cv(in[0]), mv(adj[0]), mv(const_cast<double*>(seed[0])));
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      view_left_in_branch_tangent(cv(in[0]), cv(dir[0]), mv(out[0]), mv(outd[0]));
    };
    dpgen_test::check_adjoint(p);
    for (int kind : {0, 1}) {
      CAPTURE(kind);
      dpgen_test::Problem<double> p2;
      p2.in_sizes = {n, n};
      p2.out_sizes = {n};
      p2.forward = [&](auto in, auto out) {
        view_upwind_arms(cv(in[0]), cv(in[1]), mv(out[0]), kind);
      };
      p2.adjoint = [&](auto in, auto adj, auto seed) {
        view_upwind_arms_adjoint(cv(in[0]), mv(adj[0]), cv(in[1]), mv(adj[1]),
                                 mv(const_cast<double*>(seed[0])), kind);
      };
      p2.tangent = [&](auto in, auto dir, auto out, auto outd) {
        view_upwind_arms_tangent(cv(in[0]), cv(dir[0]), cv(in[1]), cv(dir[1]), mv(out[0]),
                                 mv(outd[0]), kind);
      };
      dpgen_test::check_adjoint(p2);
    }
  }
  // by hand: one row 1, 2, 3: r = 0, 2 * 1, 3 * 2; the adjoint of seed (0, 0, 1)
  const double q[3] = {1.0, 2.0, 3.0};
  double r[3] = {7.0, 7.0, 7.0}, q_adj[3] = {0.0, 0.0, 0.0}, seed[3] = {0.0, 0.0, 1.0};
  view_left_in_branch({q, 3, 1}, {r, 3, 1});
  CHECK(r[0] == 0.0);
  CHECK(r[1] == 2.0);
  CHECK(r[2] == 6.0);
  view_left_in_branch_adjoint({q, 3, 1}, {q_adj, 3, 1}, {seed, 3, 1});
  CHECK(q_adj[0] == 0.0);
  CHECK(q_adj[1] == 3.0);
  CHECK(q_adj[2] == 2.0);
}
