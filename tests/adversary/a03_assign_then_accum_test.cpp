#include "support/adjoint_check.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include "a03_assign_then_accum_adjoint.hpp"
#include "a03_assign_then_accum_tangent.hpp"

DPGEN_KERNEL void a03_assign_then_accum(DPGEN_IN const double* a, DPGEN_IN const double* s,
                                        DPGEN_OUT double* r, int n);
TEST_CASE("adversary: a03_assign_then_accum") {
  for (int n : {0, 1, 2, 3, 4, 7, 16}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n), size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { a03_assign_then_accum(in[0], in[1], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { a03_assign_then_accum_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { a03_assign_then_accum_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], n); };
    dpgen_test::check_adjoint(p);
  }
}
