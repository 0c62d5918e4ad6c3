#include "support/adjoint_check.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include "a05_outer_zero_accum_adjoint.hpp"
#include "a05_outer_zero_accum_tangent.hpp"

DPGEN_KERNEL void a05_outer_zero_accum(DPGEN_IN const double* a, DPGEN_OUT double* o,
                                       DPGEN_OUT double* q, int n, int m);
TEST_CASE("adversary: a05_outer_zero_accum") {
  for (int n : {1, 2, 3, 5}) for (int m : {1, 2, 4}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n*m)};
    p.out_sizes = {size_t(n), size_t(n)};
    p.forward = [&](auto in, auto out) { a05_outer_zero_accum(in[0], out[0], out[1], n, m); };
    p.adjoint = [&](auto in, auto adj, auto seed) { a05_outer_zero_accum_adjoint(in[0], adj[0], seed[0], seed[1], n, m); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { a05_outer_zero_accum_tangent(in[0], dir[0], out[0], outd[0], out[1], outd[1], n, m); };
    dpgen_test::check_adjoint(p);
  }
}
