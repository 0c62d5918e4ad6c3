// smooth_then_scale (tests/styles/): two loops, same counter name, different
// bounds, shared input; bilinear.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "smooth_then_scale_adjoint.hpp"
#include "smooth_then_scale_tangent.hpp"

DPGEN_KERNEL void smooth_then_scale(DPGEN_IN const double* a, DPGEN_IN const double* s,
                                    DPGEN_OUT double* sm, DPGEN_OUT double* d, int n);

TEST_CASE("styles: smooth_then_scale") {
  for (int n : {1, 2, 3, 10}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n), size_t(n)};
    p.out_sizes = {size_t(n), size_t(n)};
    p.forward = [&](auto in, auto out) { smooth_then_scale(in[0], in[1], out[0], out[1], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      smooth_then_scale_adjoint(in[0], adj[0], in[1], adj[1], seed[0], seed[1], n);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      smooth_then_scale_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], seed[1], out_n[1], n);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      smooth_then_scale_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], out[1], outd[1], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
