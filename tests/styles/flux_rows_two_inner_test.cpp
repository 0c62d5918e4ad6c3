// flux_rows_two_inner (tests/styles/): two sibling inner loops with
// different bounds under one outer loop; linear.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "flux_rows_two_inner_adjoint.hpp"
#include "flux_rows_two_inner_tangent.hpp"

#include <tuple>

DPGEN_KERNEL void flux_rows_two_inner(DPGEN_IN const double* q, DPGEN_OUT double* dx_q,
                                      DPGEN_OUT double* avg, int nx, int ny);

TEST_CASE("styles: flux_rows_two_inner") {
  for (auto [nx, ny] : {std::tuple{1, 1}, {2, 2}, {3, 2}, {6, 4}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    size_t n = size_t(nx * ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {n};
    p.out_sizes = {n, n};
    p.linear = true;
    p.forward = [&](auto in, auto out) { flux_rows_two_inner(in[0], out[0], out[1], nx, ny); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      flux_rows_two_inner_adjoint(in[0], adj[0], seed[0], seed[1], nx, ny);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      flux_rows_two_inner_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], seed[1], out_n[1], nx, ny);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      flux_rows_two_inner_tangent(in[0], dir[0], out[0], outd[0], out[1], outd[1], nx, ny);
    };
    dpgen_test::check_adjoint(p);
  }
}
