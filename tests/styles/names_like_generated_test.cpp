// names_like_generated (tests/styles/): user names that generated code uses
// too (issue 20, defect 2); adjoint and tangent checked on random inputs.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "names_like_generated_adjoint.hpp"
#include "names_like_generated_kernels.hpp"
#include "names_like_generated_tangent.hpp"

TEST_CASE("styles: names_like_generated") {
  for (int n : {1, 3, 8, 37}) {
    CAPTURE(n);
    size_t N = size_t(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {N};
    p.out_sizes = {N};
    p.forward = [&](auto in, auto out) { names_like_generated(in[0], out[0], n, 0.7); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      names_like_generated_adjoint(in[0], adj[0], seed[0], n, 0.7);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto dout) {
      names_like_generated_tangent(in[0], dir[0], out[0], dout[0], n, 0.7);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: names_like_generated_sl (scatter form)") {
  for (int n : {2, 5, 16}) {
    CAPTURE(n);
    size_t N = size_t(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {N, N};
    p.out_sizes = {N};
    // velocities that keep x away from integers, where floor jumps
    p.in_ranges = {{-1, 1}, {0.11, 0.37}};
    p.forward = [&](auto in, auto out) { names_like_generated_sl(in[0], in[1], out[0], n, 1.3); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      names_like_generated_sl_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n, 1.3);
    };
    dpgen_test::check_adjoint(p);
  }
}
