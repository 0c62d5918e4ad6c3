// int_minmax (tests/kernels/): integer min/max in indices, a row index
// (2 * jc + dj) * nx.
#include "support/adjoint_check.hpp"

#include "int_minmax_adjoint.hpp"
#include "int_minmax_tangent.hpp"
#include "test_kernels.hpp"

TEST_CASE("clamped_neighbour adjoint") {
  for (int n : {0, 1, 2, 7}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { clamped_neighbour(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      clamped_neighbour_adjoint(in[0], adj[0], seed[0], n);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      clamped_neighbour_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      clamped_neighbour_tangent(in[0], dir[0], out[0], outd[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("prolong_rows adjoint") {
  for (auto [nx, ncy] : {std::pair{1, 1}, {3, 2}, {4, 3}}) {
    CAPTURE(nx);
    CAPTURE(ncy);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(nx * ncy)};
    p.out_sizes = {size_t(2 * nx * ncy)};
    p.linear = true;
    p.forward = [&](auto in, auto out) { prolong_rows(in[0], out[0], nx, ncy); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      prolong_rows_adjoint(in[0], adj[0], seed[0], nx, ncy);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      prolong_rows_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], nx, ncy);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      prolong_rows_tangent(in[0], dir[0], out[0], outd[0], nx, ncy);
    };
    dpgen_test::check_adjoint(p);
  }
}
