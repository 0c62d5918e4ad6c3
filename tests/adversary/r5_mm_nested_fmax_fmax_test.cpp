#include "support/adjoint_check.hpp"
#include "styles/styles_support.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#include "r5_mm_nested_fmax_fmax_adjoint.hpp"
#include "r5_mm_nested_fmax_fmax_tangent.hpp"

DPGEN_KERNEL void r5_mm_nested_fmax_fmax(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n);
TEST_CASE("adversary: r5_mm_nested_fmax_fmax") {
  for (int n : {0, 1, 2, 3, 4, 7, 16}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n), size_t(n)};
    p.out_sizes = {size_t(1)};
    p.forward = [&](auto in, auto out) { r5_mm_nested_fmax_fmax(in[0], in[1], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { r5_mm_nested_fmax_fmax_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { r5_mm_nested_fmax_fmax_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], n); };
    dpgen_test::check_adjoint(p);
  }
}
