#include "support/adjoint_check.hpp"
#include "styles/styles_support.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#include "r5_ip_cyclic_shift_adjoint.hpp"
#include "r5_ip_cyclic_shift_tangent.hpp"

DPGEN_KERNEL void r5_ip_cyclic_shift(DPGEN_INOUT double* u, DPGEN_OUT double* w, int n);
TEST_CASE("adversary: r5_ip_cyclic_shift") {
  for (int n : {0, 1, 2, 3, 4, 7, 16}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n), size_t(n)};
    p.forward = [&](auto in, auto out) { std::copy(in[0], in[0] + size_t(n), out[0]); r5_ip_cyclic_shift(out[0], out[1], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { std::vector<double> t0(seed[0], seed[0] + size_t(n)); r5_ip_cyclic_shift_adjoint(in[0], t0.data(), seed[1], n); for (size_t z = 0; z < t0.size(); ++z) adj[0][z] += t0[z]; };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { std::copy(in[0], in[0] + size_t(n), out[0]); std::copy(dir[0], dir[0] + size_t(n), outd[0]); r5_ip_cyclic_shift_tangent(out[0], outd[0], out[1], outd[1], n); };
    dpgen_test::check_adjoint(p);
  }
}
