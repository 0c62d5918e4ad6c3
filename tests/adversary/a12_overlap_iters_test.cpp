#include "support/adjoint_check.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include "a12_overlap_iters_adjoint.hpp"
#include "a12_overlap_iters_tangent.hpp"

DPGEN_KERNEL void a12_overlap_iters(DPGEN_IN const double* a, DPGEN_OUT double* u, int n);
TEST_CASE("adversary: a12_overlap_iters") {
  for (int n : {0, 1, 2, 3, 4, 7, 16}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { a12_overlap_iters(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { a12_overlap_iters_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { a12_overlap_iters_tangent(in[0], dir[0], out[0], outd[0], n); };
    dpgen_test::check_adjoint(p);
  }
}
