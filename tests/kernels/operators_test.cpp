// The implicit-solve operators (tests/runtime/operators/): ghost reads inside
// conditional arms, periodic 2D with coefficient averaging, 2D with walls.
#include "support/adjoint_check.hpp"

#include "neg_div_k_grad_1d_adjoint.hpp"
#include "neg_div_k_grad_1d_tangent.hpp"
#include "neg_div_k_grad_periodic2d_adjoint.hpp"
#include "neg_div_k_grad_periodic2d_tangent.hpp"
#include "neg_div_k_grad_walls2d_adjoint.hpp"
#include "operators.hpp"

#include <array>

TEST_CASE("neg_div_k_grad_1d adjoint") {
  for (int n : {1, 2, 9}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n), size_t(n + 1)};
    p.in_ranges = {{-1.0, 1.0}, {0.5, 2.0}};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { neg_div_k_grad_1d(in[0], in[1], out[0], n, 0.5); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      neg_div_k_grad_1d_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n, 0.5);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      neg_div_k_grad_1d_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], n, 0.5);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      neg_div_k_grad_1d_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], n, 0.5);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("neg_div_k_grad_periodic2d adjoint") {
  for (auto [nx, ny] : {std::pair{1, 1}, {2, 3}, {6, 5}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    size_t n = size_t(nx * ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {n, n};
    p.in_ranges = {{-1.0, 1.0}, {0.5, 2.0}};
    p.out_sizes = {n};
    p.forward = [&](auto in, auto out) {
      neg_div_k_grad_periodic2d(in[0], in[1], out[0], nx, ny, 0.5);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      neg_div_k_grad_periodic2d_adjoint(in[0], adj[0], in[1], adj[1], seed[0], nx, ny, 0.5);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      neg_div_k_grad_periodic2d_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], nx, ny, 0.5);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      neg_div_k_grad_periodic2d_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], nx, ny, 0.5);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("neg_div_k_grad_walls2d adjoint") {
  // Wall weights: all Neumann, all Dirichlet, mixed.
  for (auto [nx, ny] : {std::pair{1, 1}, {2, 3}, {6, 5}})
    for (auto walls : {std::array<double, 4>{0, 0, 0, 0}, {2, 2, 2, 2}, {0, 2, 0.5, 0}}) {
      CAPTURE(nx);
      CAPTURE(ny);
      CAPTURE(walls[1]);
      size_t n = size_t(nx * ny);
      dpgen_test::Problem<double> p;
      p.in_sizes = {n, n};
      p.in_ranges = {{-1.0, 1.0}, {0.5, 2.0}};
      p.out_sizes = {n};
      p.forward = [&](auto in, auto out) {
        neg_div_k_grad_walls2d(in[0], in[1], out[0], nx, ny, 0.5, walls[0], walls[1], walls[2],
                               walls[3]);
      };
      p.adjoint = [&](auto in, auto adj, auto seed) {
        neg_div_k_grad_walls2d_adjoint(in[0], adj[0], in[1], adj[1], seed[0], nx, ny, 0.5, walls[0],
                                       walls[1], walls[2], walls[3]);
      };
      p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
        neg_div_k_grad_walls2d_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], nx, ny, 0.5, walls[0], walls[1], walls[2], walls[3]);
      };
      dpgen_test::check_adjoint(p);
    }
}
