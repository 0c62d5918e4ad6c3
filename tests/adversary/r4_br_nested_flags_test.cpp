#include "support/adjoint_check.hpp"
#include "styles/styles_support.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include "r4_br_nested_flags_adjoint.hpp"
#include "r4_br_nested_flags_tangent.hpp"

DPGEN_KERNEL void r4_br_nested_flags(DPGEN_IN const double* a, DPGEN_OUT double* u, int n, int f1, int f2);
TEST_CASE("adversary: r4_br_nested_flags") {
  for (int f1 : {0, 1}) for (int f2 : {0, 1}) for (int n : {0, 1, 3, 6}) {
    CAPTURE(f1); CAPTURE(f2);
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { r4_br_nested_flags(in[0], out[0], n, f1, f2); };
    p.adjoint = [&](auto in, auto adj, auto seed) { r4_br_nested_flags_adjoint(in[0], adj[0], seed[0], n, f1, f2); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { r4_br_nested_flags_tangent(in[0], dir[0], out[0], outd[0], n, f1, f2); };
    dpgen_test::check_adjoint(p);
  }
}
