#include "support/adjoint_check.hpp"
#include "styles/styles_support.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#include "r5_mm_out_elem_param_index_adjoint.hpp"
#include "r5_mm_out_elem_param_index_tangent.hpp"

DPGEN_KERNEL void r5_mm_out_elem_param_index(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, int k);
TEST_CASE("adversary: r5_mm_out_elem_param_index") {
  for (int k : {0, 2}) for (int n : {0, 1, 2, 5}) {
    CAPTURE(k);
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(3)};
    p.forward = [&](auto in, auto out) { r5_mm_out_elem_param_index(in[0], out[0], n, k); };
    p.adjoint = [&](auto in, auto adj, auto seed) { r5_mm_out_elem_param_index_adjoint(in[0], adj[0], seed[0], n, k); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { r5_mm_out_elem_param_index_tangent(in[0], dir[0], out[0], outd[0], n, k); };
    dpgen_test::check_adjoint(p);
  }
}
