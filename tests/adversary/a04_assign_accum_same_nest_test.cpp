#include "support/adjoint_check.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include "a04_assign_accum_same_nest_adjoint.hpp"
#include "a04_assign_accum_same_nest_tangent.hpp"

DPGEN_KERNEL void a04_assign_accum_same_nest(DPGEN_IN const double* a, DPGEN_OUT double* u,
                                             DPGEN_OUT double* loss, int n);
TEST_CASE("adversary: a04_assign_accum_same_nest") {
  for (int n : {0, 1, 2, 3, 4, 7, 16}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n), size_t(1)};
    p.forward = [&](auto in, auto out) { a04_assign_accum_same_nest(in[0], out[0], out[1], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { a04_assign_accum_same_nest_adjoint(in[0], adj[0], seed[0], seed[1], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { a04_assign_accum_same_nest_tangent(in[0], dir[0], out[0], outd[0], out[1], outd[1], n); };
    dpgen_test::check_adjoint(p);
  }
}
