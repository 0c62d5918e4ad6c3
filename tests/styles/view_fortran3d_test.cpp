// view_fortran3d (tests/styles/): column-major views with a ghost cell below
// i = 0, by const reference.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "view_fortran3d_adjoint.hpp"
#include "view_fortran3d_tangent.hpp"

DPGEN_KERNEL void view_fortran3d(DPGEN_IN const grid::FortranView3D& q,
                                 DPGEN_IN const grid::FortranView3D& vel,
                                 DPGEN_OUT const grid::FortranView3D& dq, double dt_dx);

TEST_CASE("styles: view_fortran3d") {
  // i runs over [-1, ni - 1) with ilo = -1: one ghost cell at each end
  for (auto [ni, nj, nk] : {std::tuple{3, 1, 1}, {5, 2, 3}, {8, 3, 2}, {2, 2, 2}}) {
    CAPTURE(ni);
    CAPTURE(nj);
    CAPTURE(nk);
    const size_t n = size_t(ni) * size_t(nj) * size_t(nk);
    auto view = [&](const double* p) {
      return grid::FortranView3D{const_cast<double*>(p), -1, ni, nj, nk};
    };
    dpgen_test::Problem<double> p;
    p.in_sizes = {n, n};
    p.out_sizes = {n};
    p.forward = [&](auto in, auto out) {
      view_fortran3d(view(in[0]), view(in[1]), view(out[0]), 0.2);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      view_fortran3d_adjoint(view(in[0]), view(adj[0]), view(in[1]), view(adj[1]),
                             view(seed[0]), 0.2);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      view_fortran3d_tangent(view(in[0]), view(dir[0]), view(in[1]), view(dir[1]), view(out[0]),
                             view(outd[0]), 0.2);
    };
    dpgen_test::check_adjoint(p);
  }
}
