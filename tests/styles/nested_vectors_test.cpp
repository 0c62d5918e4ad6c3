// nested_vectors (tests/styles/): kernels on std::vector<std::vector<double>>
// grids. The checker works on flat arrays, so each entry point is called on
// rows copied from them (and copied back): adjoint and tangent against the
// checker's differences; rows of the wrong length are refused with the row
// named.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "nested_vectors_adjoint.hpp"
#include "nested_vectors_kernels.hpp"
#include "nested_vectors_tangent.hpp"

#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

namespace {

using Rows = std::vector<std::vector<double>>;

Rows rows_of(const double* flat, int nx, int ny) {
  Rows r(static_cast<size_t>(ny), std::vector<double>(static_cast<size_t>(nx)));
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      r[j][i] = flat[j * nx + i];
  return r;
}

void copy_back(const Rows& r, double* flat) {
  size_t k = 0;
  for (const auto& row : r)
    for (double x : row)
      flat[k++] = x;
}

// check_one_to_one of a kernel from rows of nx by ny to rows of the same shape, called as
// fwd(u, v), adj(u, u_adj, seed), tan(u, u_dot, v, v_dot) on rows copied from the
// checker's flat arrays (and copied back).
template <typename F, typename A, typename T>
void check_rows_to_rows(int nx, int ny, F fwd, A adj, T tan) {
  const size_t n = size_t(nx) * size_t(ny);
  dpgen_test::check_one_to_one(
      n, n,
      [&](const double* u, double* v) {
        Rows vr = rows_of(v, nx, ny);
        fwd(rows_of(u, nx, ny), vr);
        copy_back(vr, v);
      },
      [&](const double* u, double* u_adj, const double* seed) {
        Rows ar = rows_of(u_adj, nx, ny);
        adj(rows_of(u, nx, ny), ar, rows_of(seed, nx, ny));
        copy_back(ar, u_adj);
      },
      [&](const double* u, const double* d, double* v, double* vd) {
        Rows vr = rows_of(v, nx, ny), vdr = rows_of(vd, nx, ny);
        tan(rows_of(u, nx, ny), rows_of(d, nx, ny), vr, vdr);
        copy_back(vr, v);
        copy_back(vdr, vd);
      });
}

} // namespace

TEST_CASE("styles: vv_stencil, vv_weighted") {
  for (auto [nx, ny] : {std::tuple{1, 1}, {3, 3}, {4, 5}, {7, 6}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t N = size_t(nx) * size_t(ny);
    check_rows_to_rows(
        nx, ny, [&](const Rows& u, Rows& v) { vv_stencil(u, v, nx, ny, 0.3); },
        [&](const Rows& u, Rows& u_adj, const Rows& seed) {
          vv_stencil_adjoint(u, u_adj, seed, nx, ny, 0.3);
        },
        [&](const Rows& u, const Rows& d, Rows& v, Rows& vd) {
          vv_stencil_tangent(u, d, v, vd, nx, ny, 0.3);
        });
    dpgen_test::Problem<double> p;
    p.in_sizes = {N, N};
    p.out_sizes = {N};
    p.forward = [&](auto in, auto out) {
      Rows vr = rows_of(out[0], nx, ny);
      vv_weighted(rows_of(in[0], nx, ny), in[1], vr, nx, ny);
      copy_back(vr, out[0]);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      Rows ar = rows_of(adj[0], nx, ny);
      vv_weighted_adjoint(rows_of(in[0], nx, ny), ar, in[1], adj[1], rows_of(seed[0], nx, ny), nx,
                          ny);
      copy_back(ar, adj[0]);
    };
    p.tangent = [&](auto in, auto d, auto out, auto od) {
      Rows vr = rows_of(out[0], nx, ny), vdr = rows_of(od[0], nx, ny);
      vv_weighted_tangent(rows_of(in[0], nx, ny), rows_of(d[0], nx, ny), in[1], d[1], vr, vdr, nx,
                          ny);
      copy_back(vr, out[0]);
      copy_back(vdr, od[0]);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: vv_row_refs, rows by reference") {
  for (auto [nx, ny] : {std::tuple{1, 1}, {3, 3}, {4, 5}, {7, 6}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    check_rows_to_rows(
        nx, ny, [&](const Rows& u, Rows& v) { vv_row_refs(u, v, nx, ny); },
        [&](const Rows& u, Rows& u_adj, const Rows& seed) {
          vv_row_refs_adjoint(u, u_adj, seed, nx, ny);
        },
        [&](const Rows& u, const Rows& d, Rows& v, Rows& vd) {
          vv_row_refs_tangent(u, d, v, vd, nx, ny);
        });
  }
  // By hand, 3 x 3 with u = 1 but u[1][1] = 2: v[1][1] = 2 (1 + 1 + 1 + 1 - 8) = -8; a seed
  // there gives (4 - 16) + 2 * (-4) ... = d/du11 of u11 (4 - 4 u11) = 4 - 8 u11 = -12, and 2
  // to each of the four neighbours.
  Rows u(3, std::vector<double>(3, 1.0)), v(3, std::vector<double>(3, 0.0));
  u[1][1] = 2.0;
  vv_row_refs(u, v, 3, 3);
  CHECK(v[1][1] == doctest::Approx(-8.0));
  Rows seed(3, std::vector<double>(3, 0.0)), adj(3, std::vector<double>(3, 0.0));
  seed[1][1] = 1.0;
  vv_row_refs_adjoint(u, adj, seed, 3, 3);
  CHECK(adj[1][1] == doctest::Approx(-12.0));
  CHECK(adj[0][1] == doctest::Approx(2.0));
  CHECK(adj[2][1] == doctest::Approx(2.0));
  CHECK(adj[1][0] == doctest::Approx(2.0));
  CHECK(adj[1][2] == doctest::Approx(2.0));
  CHECK(adj[0][0] == doctest::Approx(0.0));
}

TEST_CASE("styles: vv_rows_to_flat") {
  for (auto [nx, ny] : {std::tuple{1, 2}, {2, 1}, {5, 4}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t N = size_t(nx) * size_t(ny);
    dpgen_test::check_one_to_one(
        N, N, [&](const double* u, double* g) { vv_rows_to_flat(rows_of(u, nx, ny), g, nx); },
        [&](const double* u, double* u_adj, const double* seed) {
          Rows ar = rows_of(u_adj, nx, ny);
          vv_rows_to_flat_adjoint(rows_of(u, nx, ny), ar, seed, nx);
          copy_back(ar, u_adj);
        },
        [&](const double* u, const double* d, double* g, double* gd) {
          vv_rows_to_flat_tangent(rows_of(u, nx, ny), rows_of(d, nx, ny), g, gd, nx);
        });
  }
}

TEST_CASE("styles: nested vectors of the wrong shape are refused, row named") {
  Rows u(3, std::vector<double>(4, 1.0)), v(3, std::vector<double>(4, 0.0));
  Rows u_adj(3, std::vector<double>(4, 0.0));
  u_adj[2].resize(3);
  try {
    vv_stencil_adjoint(u, u_adj, v, 4, 3, 0.3);
    FAIL("no exception");
  } catch (const std::invalid_argument& e) {
    CHECK(std::string(e.what()).find("row 2 of u_adj has 3 elements") != std::string::npos);
  }
  Rows two_rows(2, std::vector<double>(4, 0.0));
  try {
    vv_stencil_adjoint(u, two_rows, v, 4, 3, 0.3);
    FAIL("no exception");
  } catch (const std::invalid_argument& e) {
    CHECK(std::string(e.what()).find("u_adj has 2 rows but u has 3") != std::string::npos);
  }
}
