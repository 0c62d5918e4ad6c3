#include "support/adjoint_check.hpp"
#include "styles/styles_support.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#define IDX(i, j) ((i) + (j) * ld)
#include "r4_acc_macro_locals_adjoint.hpp"
#include "r4_acc_macro_locals_tangent.hpp"

DPGEN_KERNEL void r4_acc_macro_locals(DPGEN_IN const double* a, DPGEN_OUT double* r, int n, int m);
TEST_CASE("adversary: r4_acc_macro_locals") {
  for (auto [n, m] : {std::pair{1, 1}, {1, 3}, {3, 1}, {2, 2}, {4, 3}, {5, 6}}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n*m)};
    p.out_sizes = {size_t(m)};
    p.forward = [&](auto in, auto out) { r4_acc_macro_locals(in[0], out[0], n, m); };
    p.adjoint = [&](auto in, auto adj, auto seed) { r4_acc_macro_locals_adjoint(in[0], adj[0], seed[0], n, m); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { r4_acc_macro_locals_tangent(in[0], dir[0], out[0], outd[0], n, m); };
    dpgen_test::check_adjoint(p);
  }
}
