// view_laplace2d (tests/styles/): views by value over the checker's flat arrays.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "view_laplace2d_adjoint.hpp"
#include "view_laplace2d_tangent.hpp"

DPGEN_KERNEL void view_laplace2d(DPGEN_IN grid::View2D<const double> u,
                                 DPGEN_OUT grid::View2D<double> v, const grid::Spacing& h,
                                 double kappa);
DPGEN_KERNEL void view_periodic_upwind(DPGEN_IN grid::View2D<const double> q,
                                       DPGEN_OUT grid::View2D<double> qn, double cx, double cy);

TEST_CASE("styles: view_laplace2d") {
  const grid::Spacing h{0.5, 0.25};
  for (auto [nx, ny] : {std::pair{3, 3}, {4, 5}, {7, 6}, {2, 4}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t n = size_t(nx) * size_t(ny);
    auto cv = [&](const double* p) { return grid::View2D<const double>{p, nx, ny}; };
    auto mv = [&](double* p) { return grid::View2D<double>{p, nx, ny}; };
    dpgen_test::Problem<double> p;
    p.in_sizes = {n};
    p.out_sizes = {n};
    p.forward = [&](auto in, auto out) { view_laplace2d(cv(in[0]), mv(out[0]), h, 0.3); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      view_laplace2d_adjoint(cv(in[0]), mv(adj[0]), mv(const_cast<double*>(seed[0])), h, 0.3);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      view_laplace2d_tangent(cv(in[0]), cv(dir[0]), mv(out[0]), mv(outd[0]), h, 0.3);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: view_periodic_upwind") {
  for (auto [nx, ny] : {std::pair{1, 1}, {2, 3}, {5, 4}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t n = size_t(nx) * size_t(ny);
    auto cv = [&](const double* p) { return grid::View2D<const double>{p, nx, ny}; };
    auto mv = [&](double* p) { return grid::View2D<double>{p, nx, ny}; };
    dpgen_test::Problem<double> p;
    p.in_sizes = {n};
    p.out_sizes = {n};
    p.forward = [&](auto in, auto out) { view_periodic_upwind(cv(in[0]), mv(out[0]), 0.3, 0.2); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      view_periodic_upwind_adjoint(cv(in[0]), mv(adj[0]), mv(const_cast<double*>(seed[0])), 0.3,
                                   0.2);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      view_periodic_upwind_tangent(cv(in[0]), cv(dir[0]), mv(out[0]), mv(outd[0]), 0.3, 0.2);
    };
    dpgen_test::check_adjoint(p);
  }
}
