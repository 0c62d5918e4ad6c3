#include "support/adjoint_check.hpp"
#include "styles/styles_support.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include "r4_acc_per_row_read_later_nest_adjoint.hpp"
#include "r4_acc_per_row_read_later_nest_tangent.hpp"

DPGEN_KERNEL void r4_acc_per_row_read_later_nest(DPGEN_IN const double* a, DPGEN_OUT double* r,
                                                 DPGEN_OUT double* q, int n);
TEST_CASE("adversary: r4_acc_per_row_read_later_nest") {
  for (int n : {0, 1, 2, 3, 4, 7, 16}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n), size_t(n)};
    p.forward = [&](auto in, auto out) { r4_acc_per_row_read_later_nest(in[0], out[0], out[1], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { r4_acc_per_row_read_later_nest_adjoint(in[0], adj[0], seed[0], seed[1], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { r4_acc_per_row_read_later_nest_tangent(in[0], dir[0], out[0], outd[0], out[1], outd[1], n); };
    dpgen_test::check_adjoint(p);
  }
}
