#include "support/adjoint_check.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include "a16_countdown_adjoint.hpp"
#include "a16_countdown_tangent.hpp"

DPGEN_KERNEL void a16_countdown(DPGEN_IN const double* a, DPGEN_OUT double* o, DPGEN_OUT double* p, int n);
TEST_CASE("adversary: a16_countdown") {
  for (int n : {0, 1, 2, 3, 4, 7, 16}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n), size_t(n)};
    p.forward = [&](auto in, auto out) { a16_countdown(in[0], out[0], out[1], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { a16_countdown_adjoint(in[0], adj[0], seed[0], seed[1], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { a16_countdown_tangent(in[0], dir[0], out[0], outd[0], out[1], outd[1], n); };
    dpgen_test::check_adjoint(p);
  }
}
