#include "support/adjoint_check.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include "a20_half_minmax_adjoint.hpp"
#include "a20_half_minmax_tangent.hpp"

DPGEN_KERNEL void a20_half_minmax(DPGEN_IN const double* a, DPGEN_OUT double* o, int n);
TEST_CASE("adversary: a20_half_minmax") {
  for (int n : {0, 1, 2, 3, 4, 7, 16}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { a20_half_minmax(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { a20_half_minmax_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { a20_half_minmax_tangent(in[0], dir[0], out[0], outd[0], n); };
    dpgen_test::check_adjoint(p);
  }
}
