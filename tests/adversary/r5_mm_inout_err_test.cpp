#include "support/adjoint_check.hpp"
#include "styles/styles_support.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#include "r5_mm_inout_err_adjoint.hpp"
#include "r5_mm_inout_err_tangent.hpp"

DPGEN_KERNEL void r5_mm_inout_err(DPGEN_INOUT double* err, DPGEN_IN const double* r, int n);
TEST_CASE("adversary: r5_mm_inout_err") {
  for (int n : {0, 1, 2, 3, 4, 7, 16}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(1), size_t(n)};
    p.out_sizes = {size_t(1)};
    p.forward = [&](auto in, auto out) { std::copy(in[0], in[0] + size_t(1), out[0]); r5_mm_inout_err(out[0], in[1], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { std::vector<double> t0(seed[0], seed[0] + size_t(1)); r5_mm_inout_err_adjoint(in[0], t0.data(), in[1], adj[1], n); for (size_t z = 0; z < t0.size(); ++z) adj[0][z] += t0[z]; };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { std::copy(in[0], in[0] + size_t(1), out[0]); std::copy(dir[0], dir[0] + size_t(1), outd[0]); r5_mm_inout_err_tangent(out[0], outd[0], in[1], dir[1], n); };
    dpgen_test::check_adjoint(p);
  }
}
