#include "support/adjoint_check.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include "a32_accum_twice_nests_adjoint.hpp"
#include "a32_accum_twice_nests_tangent.hpp"

DPGEN_KERNEL void a32_accum_twice_nests(DPGEN_IN const double* a, DPGEN_OUT double* r, DPGEN_OUT double* loss, int n);
TEST_CASE("adversary: a32_accum_twice_nests") {
  for (int n : {0, 1, 2, 3, 4, 7, 16}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n), size_t(1)};
    p.forward = [&](auto in, auto out) { a32_accum_twice_nests(in[0], out[0], out[1], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { a32_accum_twice_nests_adjoint(in[0], adj[0], seed[0], seed[1], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { a32_accum_twice_nests_tangent(in[0], dir[0], out[0], outd[0], out[1], outd[1], n); };
    dpgen_test::check_adjoint(p);
  }
}
