#include "support/adjoint_check.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include "a36_cond_store_idx_min_adjoint.hpp"
#include "a36_cond_store_idx_min_tangent.hpp"

DPGEN_KERNEL void a36_cond_store_idx_min(DPGEN_IN const double* a, DPGEN_OUT double* u, int n);
TEST_CASE("adversary: a36_cond_store_idx_min") {
  for (int n : {0, 1, 2, 3, 4, 7, 16}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { a36_cond_store_idx_min(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { a36_cond_store_idx_min_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { a36_cond_store_idx_min_tangent(in[0], dir[0], out[0], outd[0], n); };
    dpgen_test::check_adjoint(p);
  }
}
