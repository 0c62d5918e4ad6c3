// view_workarrays (tests/styles/): views as work arrays (outputs a later loop
// reads), over the checker's flat arrays: dot-product, finite-difference and
// tangent checks.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "view_workarrays_adjoint.hpp"
#include "view_workarrays_kernels.hpp"
#include "view_workarrays_tangent.hpp"

#include <tuple>
#include <vector>

TEST_CASE("styles: view_faces_then_cells") {
  for (auto [nx, ny] : {std::pair{1, 1}, {2, 3}, {6, 4}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t X = size_t(nx), Y = size_t(ny);
    // u: nx + 2 columns (a ghost each side), flux: nx + 1 faces, un: nx cells
    auto cu = [&](const double* p) { return grid::View2D<const double>{p, nx + 2, ny}; };
    auto mu = [&](double* p) { return grid::View2D<double>{p, nx + 2, ny}; };
    auto mf = [&](double* p) { return grid::View2D<double>{p, nx + 1, ny}; };
    auto mc = [&](double* p) { return grid::View2D<double>{p, nx, ny}; };
    auto seed = [](const double* s) { return const_cast<double*>(s); };
    dpgen_test::Problem<double> p;
    p.in_sizes = {(X + 2) * Y};
    p.out_sizes = {(X + 1) * Y, X * Y};
    p.forward = [&](auto in, auto out) {
      view_faces_then_cells(cu(in[0]), mf(out[0]), mc(out[1]), 0.4);
    };
    p.adjoint = [&](auto in, auto adj, auto s) {
      view_faces_then_cells_adjoint(cu(in[0]), mu(adj[0]), mf(seed(s[0])), mc(seed(s[1])), 0.4);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      view_faces_then_cells_tangent(cu(in[0]), cu(dir[0]), mf(out[0]), mf(outd[0]), mc(out[1]),
                                    mc(outd[1]), 0.4);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: field_update_energy") {
  for (int n : {1, 5, 12}) {
    CAPTURE(n);
    const size_t N = size_t(n);
    auto f = [&](const double* p) { return grid::Field(const_cast<double*>(p), n); };
    dpgen_test::Problem<double> p;
    p.in_sizes = {N, N};
    p.out_sizes = {N, 1};
    p.forward = [&](auto in, auto out) {
      grid::Field u_new = f(out[0]);
      field_update_energy(f(in[0]), f(in[1]), u_new, 0.3, out[1][0]);
    };
    p.adjoint = [&](auto in, auto adj, auto s) {
      grid::Field u_adj = f(adj[0]), dudt_adj = f(adj[1]), u_new_adj = f(s[0]);
      field_update_energy_adjoint(f(in[0]), u_adj, f(in[1]), dudt_adj, u_new_adj, 0.3, s[1][0]);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      grid::Field u_new = f(out[0]), u_new_dot = f(outd[0]);
      field_update_energy_tangent(f(in[0]), f(dir[0]), f(in[1]), f(dir[1]), u_new, u_new_dot, 0.3,
                                  out[1][0], outd[1][0]);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: fortran_smooth_then_diff") {
  for (auto [ni, nj, nk] : {std::tuple{1, 1, 1}, {4, 3, 2}, {7, 2, 3}}) {
    CAPTURE(ni);
    CAPTURE(nj);
    CAPTURE(nk);
    // every view has ghost cells i = -1 and i = ni (ilo = -1, ni + 2 per row)
    const size_t n = size_t(ni + 2) * size_t(nj) * size_t(nk);
    auto v = [&](const double* p) {
      return grid::FortranView3D{const_cast<double*>(p), -1, ni + 2, nj, nk};
    };
    std::vector<double> mask(n);
    for (size_t e = 0; e < n; ++e)
      mask[e] = (e * 7 + 3) % 5 < 3 ? 1.0 : 0.0; // the smoothed values, or zero
    dpgen_test::Problem<double> p;
    p.in_sizes = {n};
    p.out_sizes = {n, size_t(ni + 2) * size_t(nj) * size_t(nk)};
    p.forward = [&](auto in, auto out) {
      fortran_smooth_then_diff(v(in[0]), v(mask.data()), v(out[0]), v(out[1]), ni, nj, nk);
    };
    p.adjoint = [&](auto in, auto adj, auto s) {
      fortran_smooth_then_diff_adjoint(v(in[0]), v(adj[0]), v(mask.data()), v(s[0]), v(s[1]), ni,
                                       nj, nk);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      fortran_smooth_then_diff_tangent(v(in[0]), v(dir[0]), v(mask.data()), v(out[0]),
                                       v(outd[0]), v(out[1]), v(outd[1]), ni, nj, nk);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: view_bounds_from_output") {
  for (auto [nx, ny] : {std::pair{1, 1}, {3, 2}, {5, 4}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t X = size_t(nx), Y = size_t(ny);
    // u has one column more than out (u(j, i + 1) at i = nx - 1)
    auto cu = [&](const double* p) { return grid::View2D<const double>{p, nx + 1, ny}; };
    auto mu = [&](double* p) { return grid::View2D<double>{p, nx + 1, ny}; };
    auto mo = [&](const double* p) { return grid::View2D<double>{const_cast<double*>(p), nx, ny}; };
    dpgen_test::Problem<double> p;
    p.in_sizes = {(X + 1) * Y};
    p.out_sizes = {X * Y};
    p.forward = [&](auto in, auto out) { view_bounds_from_output(cu(in[0]), mo(out[0]), 0.7); };
    p.adjoint = [&](auto in, auto adj, auto s) {
      view_bounds_from_output_adjoint(cu(in[0]), mu(adj[0]), mo(s[0]), 0.7);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      view_bounds_from_output_tangent(cu(in[0]), cu(dir[0]), mo(out[0]), mo(outd[0]), 0.7);
    };
    dpgen_test::check_adjoint(p);
  }
}
