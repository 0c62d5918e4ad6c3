// The examples' kernels (examples/kernels/): same checks as every kernel.
#include "support/adjoint_check.hpp"

#include "advect_self_semi_lagrangian_adjoint.hpp"
#include "advect_self_semi_lagrangian_tangent.hpp"
#include "diffuse_explicit_adjoint.hpp"
#include "diffuse_explicit_tangent.hpp"
#include "example_kernels.hpp"
#include "mac_divergence_periodic_adjoint.hpp"
#include "mac_divergence_periodic_tangent.hpp"
#include "mac_subtract_gradient_adjoint.hpp"
#include "mac_subtract_gradient_tangent.hpp"
#include "neg_laplacian_periodic_adjoint.hpp"
#include "neg_laplacian_periodic_tangent.hpp"

using dpgen_test::Problem;

static const std::pair<int, int> kGrids[] = {{1, 1}, {2, 3}, {5, 4}, {12, 9}};

TEST_CASE("mac_divergence_periodic adjoint") {
  for (auto [nx, ny] : kGrids) {
    CAPTURE(nx);
    CAPTURE(ny);
    size_t n = size_t(nx * ny);
    Problem<double> p;
    p.in_sizes = {n, n};
    p.out_sizes = {n};
    p.linear = true;
    p.forward = [&](auto in, auto out) { mac_divergence_periodic(in[0], in[1], out[0], nx, ny, 0.5); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      mac_divergence_periodic_adjoint(in[0], adj[0], in[1], adj[1], seed[0], nx, ny, 0.5);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      mac_divergence_periodic_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], nx, ny, 0.5);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      mac_divergence_periodic_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], nx, ny, 0.5);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("neg_laplacian_periodic adjoint") {
  for (auto [nx, ny] : kGrids) {
    CAPTURE(nx);
    CAPTURE(ny);
    size_t n = size_t(nx * ny);
    Problem<double> p;
    p.in_sizes = {n};
    p.out_sizes = {n};
    p.linear = true;
    p.forward = [&](auto in, auto out) { neg_laplacian_periodic(in[0], out[0], nx, ny, 0.5); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      neg_laplacian_periodic_adjoint(in[0], adj[0], seed[0], nx, ny, 0.5);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      neg_laplacian_periodic_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], nx, ny, 0.5);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      neg_laplacian_periodic_tangent(in[0], dir[0], out[0], outd[0], nx, ny, 0.5);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("mac_subtract_gradient adjoint") {
  for (auto [nx, ny] : kGrids) {
    CAPTURE(nx);
    CAPTURE(ny);
    size_t n = size_t(nx * ny);
    Problem<double> p;
    p.in_sizes = {n, n, n};
    p.out_sizes = {n, n};
    p.linear = true;
    p.forward = [&](auto in, auto out) {
      mac_subtract_gradient(in[0], in[1], in[2], out[0], out[1], nx, ny, 0.5);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      mac_subtract_gradient_adjoint(in[0], adj[0], in[1], adj[1], in[2], adj[2], seed[0], seed[1],
                                    nx, ny, 0.5);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      mac_subtract_gradient_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], in[2], in_n[2], adj[2], in_n[2], seed[0], out_n[0], seed[1], out_n[1], nx, ny, 0.5);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      mac_subtract_gradient_tangent(in[0], dir[0], in[1], dir[1], in[2], dir[2], out[0], outd[0], out[1], outd[1], nx, ny, 0.5);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("diffuse_explicit adjoint") {
  for (int n : {1, 2, 3, 128}) {
    CAPTURE(n);
    Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.linear = true;
    p.forward = [&](auto in, auto out) { diffuse_explicit(in[0], out[0], n, 0.03, 0.2, 0.1); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      diffuse_explicit_adjoint(in[0], adj[0], seed[0], n, 0.03, 0.2, 0.1);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      diffuse_explicit_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n, 0.03, 0.2, 0.1);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      diffuse_explicit_tangent(in[0], dir[0], out[0], outd[0], n, 0.03, 0.2, 0.1);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("advect_self_semi_lagrangian adjoint (scatter form)") {
  for (int n : {1, 2, 7, 128}) {
    CAPTURE(n);
    const double dt = 1.0 / 32, dx = 2.0 / n;
    Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { advect_self_semi_lagrangian(in[0], out[0], n, dt, dx); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      advect_self_semi_lagrangian_adjoint(in[0], adj[0], seed[0], n, dt, dx);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      advect_self_semi_lagrangian_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n, dt, dx);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      advect_self_semi_lagrangian_tangent(in[0], dir[0], out[0], outd[0], n, dt, dx);
    };
    dpgen_test::check_adjoint(p);
  }
}
