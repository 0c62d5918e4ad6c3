#include "support/adjoint_check.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include "a15_stride_param_adjoint.hpp"
#include "a15_stride_param_tangent.hpp"

DPGEN_KERNEL void a15_stride_param(DPGEN_IN const double* a, DPGEN_OUT double* o, DPGEN_OUT double* c, int n, int s);
TEST_CASE("adversary: a15_stride_param") {
  for (int n : {0, 1, 2, 3, 4, 7, 10}) for (int s = 0; s < 4; ++s) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n), size_t(n)};
    p.forward = [&](auto in, auto out) { a15_stride_param(in[0], out[0], out[1], n, s); };
    p.adjoint = [&](auto in, auto adj, auto seed) { a15_stride_param_adjoint(in[0], adj[0], seed[0], seed[1], n, s); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { a15_stride_param_tangent(in[0], dir[0], out[0], outd[0], out[1], outd[1], n, s); };
    dpgen_test::check_adjoint(p);
  }
}
