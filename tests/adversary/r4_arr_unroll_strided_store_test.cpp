#include "support/adjoint_check.hpp"
#include "styles/styles_support.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include <array>
#include <cmath>
#include "r4_arr_unroll_strided_store_adjoint.hpp"
#include "r4_arr_unroll_strided_store_tangent.hpp"

DPGEN_KERNEL void r4_arr_unroll_strided_store(DPGEN_IN const double* u, DPGEN_OUT double* out, int n);
TEST_CASE("adversary: r4_arr_unroll_strided_store") {
  for (int n : {0, 1, 2, 3, 4, 7, 16}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n+4)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { r4_arr_unroll_strided_store(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { r4_arr_unroll_strided_store_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { r4_arr_unroll_strided_store_tangent(in[0], dir[0], out[0], outd[0], n); };
    dpgen_test::check_adjoint(p);
  }
}
