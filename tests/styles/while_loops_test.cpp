// while_loops (tests/styles/): `while` loops that count, read as their for loops: stepped at
// the end of the body (`i++`, `++i`, `i += 2`, `--k`) or counted down by the condition
// (`i-- > 1`, unsigned; `i--`, `k-- >= 1`, `--m >= 0`, `0 < j--`, `p-- != 0`), nested, with a sum read after its loop, and with line buffers whose
// rows follow the `while` loops around their uses.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "while_loops_adjoint.hpp"
#include "while_loops_tangent.hpp"

#include <cstddef>

DPGEN_KERNEL void while_heat1d(DPGEN_IN const double* u, DPGEN_OUT double* u_new, int n, double r);
DPGEN_KERNEL void while_countdown(DPGEN_IN const double* u, DPGEN_OUT double* v, std::size_t n,
                                  double s);
DPGEN_KERNEL void while_pairs(DPGEN_IN const double* u, DPGEN_OUT double* v, int n);
DPGEN_KERNEL void while_laplace2d(DPGEN_IN const double* u, DPGEN_OUT double* out, int nx, int ny,
                                  double h);
DPGEN_KERNEL void while_energy(DPGEN_IN const double* u, DPGEN_OUT double* e, int n);
DPGEN_KERNEL void while_resid(DPGEN_IN const double* u, DPGEN_IN const double* v,
                              DPGEN_OUT double* r, int n1, int n2, int n3);
DPGEN_KERNEL void while_paren_steps(DPGEN_IN const double* u, DPGEN_OUT double* v,
                                    DPGEN_OUT double* w, int n);
DPGEN_KERNEL void while_running_index(DPGEN_IN const double* u, DPGEN_OUT double* out, int nx,
                                      int ny);
DPGEN_KERNEL void while_two_counters(DPGEN_IN const double* u, DPGEN_OUT double* v, int n);
DPGEN_KERNEL void while_assign_steps(DPGEN_IN const double* u, DPGEN_OUT double* v,
                                     DPGEN_OUT double* w, DPGEN_OUT double* x, int n);
DPGEN_KERNEL void while_countdown_forms(DPGEN_IN const double* u, DPGEN_OUT double* a,
                                        DPGEN_OUT double* b, DPGEN_OUT double* c,
                                        DPGEN_OUT double* d, DPGEN_OUT double* e,
                                        DPGEN_OUT double* f, int n, std::size_t nu);

TEST_CASE("styles: while_loops, heat1d") {
  for (int n : {1, 2, 3, 4, 17, 8300}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.linear = true;
    p.forward = [&](auto in, auto out) { while_heat1d(in[0], out[0], n, 0.3); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      while_heat1d_adjoint(in[0], adj[0], seed[0], n, 0.3);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      while_heat1d_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n, 0.3);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      while_heat1d_tangent(in[0], dir[0], out[0], outd[0], n, 0.3);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: while_loops, countdown") {
  for (std::size_t n : {0, 1, 2, 5, 300}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {n};
    p.out_sizes = {n};
    p.forward = [&](auto in, auto out) { while_countdown(in[0], out[0], n, 0.7); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      while_countdown_adjoint(in[0], adj[0], seed[0], n, 0.7);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      while_countdown_tangent(in[0], dir[0], out[0], outd[0], n, 0.7);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: while_loops, pairs") {
  for (int n : {0, 1, 2, 3, 8, 9, 301}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { while_pairs(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      while_pairs_adjoint(in[0], adj[0], seed[0], n);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      while_pairs_tangent(in[0], dir[0], out[0], outd[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: while_loops, laplace2d") {
  for (auto [nx, ny] : {std::pair{1, 1}, {3, 3}, {4, 7}, {9, 5}, {100, 90}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t cells = size_t(nx) * size_t(ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {cells};
    p.out_sizes = {cells};
    p.forward = [&](auto in, auto out) { while_laplace2d(in[0], out[0], nx, ny, 0.5); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      while_laplace2d_adjoint(in[0], adj[0], seed[0], nx, ny, 0.5);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      while_laplace2d_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], nx, ny,
                                      0.5);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      while_laplace2d_tangent(in[0], dir[0], out[0], outd[0], nx, ny, 0.5);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: while_loops, energy") {
  for (int n : {0, 1, 2, 33}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {1};
    p.forward = [&](auto in, auto out) { while_energy(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      while_energy_adjoint(in[0], adj[0], seed[0], n);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      while_energy_tangent(in[0], dir[0], out[0], outd[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: while_loops, resid with line buffers") {
  for (auto [n1, n2, n3] : {std::tuple{3, 3, 3}, {5, 4, 3}, {7, 6, 5}, {130, 4, 3}}) {
    CAPTURE(n1);
    CAPTURE(n2);
    CAPTURE(n3);
    const size_t cells = size_t(n1) * size_t(n2) * size_t(n3);
    dpgen_test::Problem<double> p;
    p.in_sizes = {cells, cells};
    p.out_sizes = {cells};
    p.forward = [&](auto in, auto out) { while_resid(in[0], in[1], out[0], n1, n2, n3); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      while_resid_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n1, n2, n3);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      while_resid_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], n1, n2, n3);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: while_loops, steps in parentheses and by a macro") {
  for (int n : {0, 1, 2, 5, 64}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n), size_t(n)};
    p.forward = [&](auto in, auto out) { while_paren_steps(in[0], out[0], out[1], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      while_paren_steps_adjoint(in[0], adj[0], seed[0], seed[1], n);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      while_paren_steps_tangent(in[0], dir[0], out[0], outd[0], out[1], outd[1], n);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: while_loops, a running index through a nest of while loops") {
  for (auto [nx, ny] : {std::pair{1, 1}, {2, 3}, {3, 3}, {5, 4}, {70, 9}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t cells = size_t(nx) * size_t(ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {cells};
    p.out_sizes = {cells};
    p.forward = [&](auto in, auto out) { while_running_index(in[0], out[0], nx, ny); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      while_running_index_adjoint(in[0], adj[0], seed[0], nx, ny);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      while_running_index_tangent(in[0], dir[0], out[0], outd[0], nx, ny);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: while_loops, two counters stepped at the end") {
  for (int n : {0, 1, 2, 3, 40}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { while_two_counters(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      while_two_counters_adjoint(in[0], adj[0], seed[0], n);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      while_two_counters_tangent(in[0], dir[0], out[0], outd[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: while_loops, steps written out (`++i; ++j;`, `k = k + 1`, `m = m + 2`)") {
  for (int n : {0, 1, 2, 3, 8, 41}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n), size_t(n), size_t(n)};
    p.forward = [&](auto in, auto out) { while_assign_steps(in[0], out[0], out[1], out[2], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      while_assign_steps_adjoint(in[0], adj[0], seed[0], seed[1], seed[2], n);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      while_assign_steps_tangent(in[0], dir[0], out[0], outd[0], out[1], outd[1], out[2], outd[2],
                                 n);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: while_loops, counted down by `i--`, `k-- >= 1`, `--m >= 0`, `0 < j--`, `p-- != 0`") {
  for (int n : {0, 1, 2, 3, 8, 41}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n), size_t(n), size_t(n), size_t(n), size_t(n), size_t(n)};
    p.forward = [&](auto in, auto out) {
      while_countdown_forms(in[0], out[0], out[1], out[2], out[3], out[4], out[5], n, n);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      while_countdown_forms_adjoint(in[0], adj[0], seed[0], seed[1], seed[2], seed[3], seed[4],
                                    seed[5], n, n);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      while_countdown_forms_tangent(in[0], dir[0], out[0], outd[0], out[1], outd[1], out[2],
                                    outd[2], out[3], outd[3], out[4], outd[4], out[5], outd[5],
                                    n, n);
    };
    dpgen_test::check_adjoint(p);
  }
}
