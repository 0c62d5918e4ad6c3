// accessor_local (tests/styles/): `const Grid2 U{u, nx}` made in the kernel
// over a DPGEN_IN array, read as U(i, j), bilinear in (u, k); accessor_ctor:
// `const Field2 U(u, nx)` through a constructor, quadratic. (What is refused:
// tests/diagnostics/accessor_local.cpp.) accessor_writes: fluxes added through a
// reference-returning accessor, an element stored and scaled; accessor_overloads: a class
// with a const and a non-const operator(), nonlinear; accessor_subscript: a span-like row's
// operator[], by reference and by value; accessor_helpers: accessors passed to helpers and a
// lambda, and a span made over a row (u + j * nx); accessor_offset: a grid accessor over
// u + nx; each by differences, the dot-product test and a cell by hand.
#include "support/adjoint_check.hpp"

#include "accessor_local_adjoint.hpp"
#include "accessor_local_tangent.hpp"
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void accessor_local(DPGEN_IN const double* u, DPGEN_IN const double* k,
                                 DPGEN_OUT double* out, int nx, int ny);
DPGEN_KERNEL void accessor_ctor(DPGEN_IN const double* u, DPGEN_OUT double* out, int nx, int ny);
DPGEN_KERNEL void accessor_writes(DPGEN_IN const double* u, DPGEN_OUT double* res,
                                  DPGEN_OUT double* v, int nx, int ny);
DPGEN_KERNEL void accessor_overloads(DPGEN_IN double* u, DPGEN_OUT double* out, int nx, int ny);
DPGEN_KERNEL void accessor_chain(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                 DPGEN_OUT double* res, int nx, int ny);
DPGEN_KERNEL void accessor_subscript(DPGEN_IN const double* u, DPGEN_OUT double* res, int n);
DPGEN_KERNEL void accessor_helpers(DPGEN_IN const double* u, DPGEN_OUT double* lap,
                                   DPGEN_OUT double* dxx, int nx, int ny);
DPGEN_KERNEL void accessor_offset(DPGEN_IN const double* u, DPGEN_OUT double* out, int nx, int ny);

TEST_CASE("styles: accessor_local") {
  for (auto [nx, ny] : {std::pair{1, 1}, {3, 3}, {4, 6}, {9, 5}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t n = size_t(nx) * size_t(ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {n, n};
    p.out_sizes = {n};
    p.forward = [&](auto in, auto out) { accessor_local(in[0], in[1], out[0], nx, ny); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      accessor_local_adjoint(in[0], adj[0], in[1], adj[1], seed[0], nx, ny);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      accessor_local_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], nx, ny);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: accessor_ctor") {
  for (auto [nx, ny] : {std::pair{1, 1}, {3, 3}, {4, 6}, {9, 5}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t n = size_t(nx) * size_t(ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {n};
    p.out_sizes = {n};
    p.forward = [&](auto in, auto out) { accessor_ctor(in[0], out[0], nx, ny); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      accessor_ctor_adjoint(in[0], adj[0], seed[0], nx, ny);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      accessor_ctor_tangent(in[0], dir[0], out[0], outd[0], nx, ny);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: accessor_writes, accessor_overloads, accessor_chain") {
  for (auto [nx, ny] : {std::pair{1, 1}, {2, 1}, {3, 3}, {4, 6}, {9, 5}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t n = size_t(nx) * size_t(ny);
    dpgen_test::Problem<double> w;
    w.in_sizes = {n};
    w.out_sizes = {n, n};
    w.forward = [&](auto in, auto out) { accessor_writes(in[0], out[0], out[1], nx, ny); };
    w.adjoint = [&](auto in, auto adj, auto seed) {
      accessor_writes_adjoint(in[0], adj[0], seed[0], seed[1], nx, ny);
    };
    w.tangent = [&](auto in, auto dir, auto out, auto outd) {
      accessor_writes_tangent(in[0], dir[0], out[0], outd[0], out[1], outd[1], nx, ny);
    };
    dpgen_test::check_adjoint(w);

    dpgen_test::Problem<double> o;
    o.in_sizes = {n};
    o.out_sizes = {n};
    o.forward = [&](auto in, auto out) {
      accessor_overloads(const_cast<double*>(in[0]), out[0], nx, ny);
    };
    o.adjoint = [&](auto in, auto adj, auto seed) {
      accessor_overloads_adjoint(in[0], adj[0], seed[0], nx, ny);
    };
    o.tangent = [&](auto in, auto dir, auto out, auto outd) {
      accessor_overloads_tangent(in[0], dir[0], out[0], outd[0], nx, ny);
    };
    dpgen_test::check_adjoint(o);

    dpgen_test::Problem<double> c;
    c.in_sizes = {n, n};
    c.out_sizes = {n};
    c.forward = [&](auto in, auto out) { accessor_chain(in[0], in[1], out[0], nx, ny); };
    c.adjoint = [&](auto in, auto adj, auto seed) {
      accessor_chain_adjoint(in[0], adj[0], in[1], adj[1], seed[0], nx, ny);
    };
    c.tangent = [&](auto in, auto dir, auto out, auto outd) {
      accessor_chain_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], nx, ny);
    };
    dpgen_test::check_adjoint(c);
  }
  // By hand, one row of three: res = (f, -f + g, -g) with f = (u1^2 - u0^2) / 2, g = (u2^2 -
  // u1^2) / 2; v = (u + 1) u. A seed on res[1] gives u0 to u0, -2 u1 to u1, u2 to u2; one on
  // v[2], 2 u2 + 1 to u2.
  const double u[3] = {0.5, -1.5, 2.0}, seed_r[3] = {0.0, 1.0, 0.0}, seed_v[3] = {0.0, 0.0, 1.0};
  double res[3], v[3], adj[3] = {0.0, 0.0, 0.0};
  accessor_writes(u, res, v, 3, 1);
  CHECK(res[1] == doctest::Approx(-0.5 * (1.5 * 1.5 - 0.25) + 0.5 * (4.0 - 1.5 * 1.5)));
  CHECK(v[2] == doctest::Approx(3.0 * 2.0));
  accessor_writes_adjoint(u, adj, seed_r, seed_v, 3, 1);
  CHECK(adj[0] == doctest::Approx(0.5));
  CHECK(adj[1] == doctest::Approx(3.0));
  CHECK(adj[2] == doctest::Approx(2.0 + (2.0 * 2.0 + 1.0)));
}

TEST_CASE("styles: accessor_subscript") {
  for (int n : {1, 2, 5, 12}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { accessor_subscript(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      accessor_subscript_adjoint(in[0], adj[0], seed[0], n);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      accessor_subscript_tangent(in[0], dir[0], out[0], outd[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
  // By hand, n = 3: res = (u0 - u0 u1, u1 + u0 u1 - u1 u2, u2 + u1 u2). A seed on res[1] gives
  // u1 to u0, 1 + u0 - u2 to u1, -u1 to u2.
  const double u[3] = {0.5, -1.5, 2.0}, seed[3] = {0.0, 1.0, 0.0};
  double res[3], adj[3] = {0.0, 0.0, 0.0};
  accessor_subscript(u, res, 3);
  CHECK(res[1] == doctest::Approx(-1.5 + 0.5 * -1.5 - (-1.5 * 2.0)));
  accessor_subscript_adjoint(u, adj, seed, 3);
  CHECK(adj[0] == doctest::Approx(-1.5));
  CHECK(adj[1] == doctest::Approx(1.0 + 0.5 - 2.0));
  CHECK(adj[2] == doctest::Approx(1.5));
}

TEST_CASE("styles: accessor_helpers") {
  for (auto [nx, ny] : {std::pair{1, 1}, {3, 3}, {4, 6}, {9, 5}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t n = size_t(nx) * size_t(ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {n};
    p.out_sizes = {n, n};
    p.forward = [&](auto in, auto out) { accessor_helpers(in[0], out[0], out[1], nx, ny); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      accessor_helpers_adjoint(in[0], adj[0], seed[0], seed[1], nx, ny);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      accessor_helpers_tangent(in[0], dir[0], out[0], outd[0], out[1], outd[1], nx, ny);
    };
    dpgen_test::check_adjoint(p);
  }
  // By hand, 3 x 3, the centre: lap = (u5 + u3 + u7 + u1 - 4 u4) (u5 - u3) / 2 and dxx[4] =
  // u5 - 2 u4 + u3 (row 1). A seed on lap[4] gives (u5 - u3) / 2 to u1 and u7, -2 (u5 - u3) to u4,
  // (L + (u5 - u3)) / 2 to u5 and (-L + (u5 - u3)) / 2 to u3, L the Laplacian.
  const double u[9] = {0.3, -0.5, 1.1, 0.7, 2.0, -1.3, 0.4, 0.9, -0.2};
  double lap[9] = {}, dxx[9] = {}, adj[9] = {}, seed_l[9] = {}, seed_d[9] = {};
  seed_l[4] = 1.0;
  accessor_helpers(u, lap, dxx, 3, 3);
  const double L = u[5] + u[3] + u[7] + u[1] - 4.0 * u[4], D = u[5] - u[3];
  CHECK(lap[4] == doctest::Approx(L * 0.5 * D));
  CHECK(dxx[4] == doctest::Approx(u[5] - 2.0 * u[4] + u[3]));
  accessor_helpers_adjoint(u, adj, seed_l, seed_d, 3, 3);
  CHECK(adj[1] == doctest::Approx(0.5 * D));
  CHECK(adj[4] == doctest::Approx(-2.0 * D));
  CHECK(adj[5] == doctest::Approx(0.5 * (D + L)));
  CHECK(adj[3] == doctest::Approx(0.5 * (D - L)));
}

TEST_CASE("styles: accessor_offset") {
  for (auto [nx, ny] : {std::pair{1, 1}, {1, 2}, {3, 3}, {5, 4}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t n = size_t(nx) * size_t(ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {n};
    p.out_sizes = {size_t(nx) * size_t(ny - 1)};
    p.forward = [&](auto in, auto out) { accessor_offset(in[0], out[0], nx, ny); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      accessor_offset_adjoint(in[0], adj[0], seed[0], nx, ny);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      accessor_offset_tangent(in[0], dir[0], out[0], outd[0], nx, ny);
    };
    dpgen_test::check_adjoint(p);
  }
  // By hand, 2 x 2: out = (u2 u0, u3 u1); a seed on out[1] gives u3 to u1 and u1 to u3.
  const double u[4] = {0.5, -1.5, 2.0, 3.0}, seed[2] = {0.0, 1.0};
  double out[2], adj[4] = {};
  accessor_offset(u, out, 2, 2);
  CHECK(out[1] == doctest::Approx(3.0 * -1.5));
  accessor_offset_adjoint(u, adj, seed, 2, 2);
  CHECK(adj[0] == 0.0);
  CHECK(adj[1] == doctest::Approx(3.0));
  CHECK(adj[2] == 0.0);
  CHECK(adj[3] == doctest::Approx(-1.5));
}
