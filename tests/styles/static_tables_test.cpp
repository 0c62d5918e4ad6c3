// static_tables (tests/styles/): `static const double w[5]` and `static
// constexpr double gain` (constants with constant initializers: accepted as
// without `static`; a static that keeps state from call to call is rejected,
// tests/diagnostics/); nonlinear.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "static_tables_adjoint.hpp"
#include "static_tables_tangent.hpp"

DPGEN_KERNEL void static_tables(DPGEN_IN const double* a, DPGEN_OUT double* out, int n);

TEST_CASE("styles: static_tables") {
  for (int n : {1, 4, 5, 6, 30}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { static_tables(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      static_tables_adjoint(in[0], adj[0], seed[0], n);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      static_tables_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      static_tables_tangent(in[0], dir[0], out[0], outd[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
