// member_functor (tests/styles/): a functor's member kernel and a free kernel
// running a functor temporary, both through a user's parallel-for.
#include "support/adjoint_check.hpp"

#include "include/member_classes.hpp"
#include "member_functor_adjoint.hpp"
#include "member_functor_tangent.hpp"

DPGEN_KERNEL void smooth_free(DPGEN_IN grid::View2D<const double> u,
                              DPGEN_IN grid::View2D<const double> w,
                              DPGEN_OUT grid::View2D<double> out, double dt);

TEST_CASE("styles: member_functor") {
  for (auto [nx, ny] : {std::pair{3, 3}, {5, 4}, {2, 6}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t n = size_t(nx) * size_t(ny);
    auto cv = [&](const double* p) { return grid::View2D<const double>{p, nx, ny}; };
    auto mv = [&](const double* p) { return grid::View2D<double>{const_cast<double*>(p), nx, ny}; };
    dpgen_test::Problem<double> p;
    p.in_sizes = {n, n};
    p.out_sizes = {n};
    p.forward = [&](auto in, auto out) {
      Smoother2D{cv(in[0]), cv(in[1]), mv(out[0]), 0.3}.run();
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      const Smoother2D self{cv(in[0]), cv(in[1]), mv(nullptr), 0.3};
      Smoother2D_run_adjoint(self, mv(adj[0]), mv(adj[1]), mv(seed[0]));
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      const Smoother2D self{cv(in[0]), cv(in[1]), mv(out[0]), 0.3};
      Smoother2D_run_tangent(self, cv(d[0]), cv(d[1]), mv(dout[0]));
    };
    dpgen_test::check_adjoint(p);

    dpgen_test::Problem<double> q = p;
    q.forward = [&](auto in, auto out) { smooth_free(cv(in[0]), cv(in[1]), mv(out[0]), 0.6); };
    q.adjoint = [&](auto in, auto adj, auto seed) {
      smooth_free_adjoint(cv(in[0]), mv(adj[0]), cv(in[1]), mv(adj[1]), mv(seed[0]), 0.6);
    };
    q.tangent = [&](auto in, auto d, auto out, auto dout) {
      smooth_free_tangent(cv(in[0]), cv(d[0]), cv(in[1]), cv(d[1]), mv(out[0]), mv(dout[0]), 0.6);
    };
    dpgen_test::check_adjoint(q);
  }
}
