// view_field1d (tests/styles/): a deep-const field class; its adjoint and the
// tangent's outputs by non-const reference.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "view_field1d_adjoint.hpp"
#include "view_field1d_tangent.hpp"

DPGEN_KERNEL void view_field1d(DPGEN_IN const grid::Field& a, DPGEN_OUT grid::Field& b, double c);

TEST_CASE("styles: view_field1d") {
  for (int n : {2, 3, 4, 17}) {
    CAPTURE(n);
    auto field = [&](const double* p) { return grid::Field(const_cast<double*>(p), n); };
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) {
      const grid::Field a = field(in[0]);
      grid::Field b = field(out[0]);
      view_field1d(a, b, 0.7);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      grid::Field a_adj = field(adj[0]), b_adj = field(seed[0]);
      view_field1d_adjoint(field(in[0]), a_adj, b_adj, 0.7);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      grid::Field b = field(out[0]), b_dot = field(outd[0]);
      view_field1d_tangent(field(in[0]), field(dir[0]), b, b_dot, 0.7);
    };
    dpgen_test::check_adjoint(p);
  }
}
