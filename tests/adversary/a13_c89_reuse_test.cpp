#include "support/adjoint_check.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include "a13_c89_reuse_adjoint.hpp"
#include "a13_c89_reuse_tangent.hpp"

DPGEN_KERNEL void a13_c89_reuse(DPGEN_IN const double* a, DPGEN_OUT double* w, DPGEN_OUT double* o, int n);
TEST_CASE("adversary: a13_c89_reuse") {
  for (int n : {0, 1, 2, 3, 4, 7, 16}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n), size_t(n)};
    p.forward = [&](auto in, auto out) { a13_c89_reuse(in[0], out[0], out[1], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { a13_c89_reuse_adjoint(in[0], adj[0], seed[0], seed[1], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { a13_c89_reuse_tangent(in[0], dir[0], out[0], outd[0], out[1], outd[1], n); };
    dpgen_test::check_adjoint(p);
  }
}
