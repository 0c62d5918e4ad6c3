// accessor_local (tests/styles/): `const Grid2 U{u, nx}` made in the kernel
// over a DPGEN_IN array, read as U(i, j), bilinear in (u, k); accessor_ctor:
// `const Field2 U(u, nx)` through a constructor, quadratic. (What is refused:
// tests/diagnostics/accessor_local.cpp.)
#include "support/adjoint_check.hpp"

#include "accessor_local_adjoint.hpp"
#include "accessor_local_tangent.hpp"
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void accessor_local(DPGEN_IN const double* u, DPGEN_IN const double* k,
                                 DPGEN_OUT double* out, int nx, int ny);
DPGEN_KERNEL void accessor_ctor(DPGEN_IN const double* u, DPGEN_OUT double* out, int nx, int ny);

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
