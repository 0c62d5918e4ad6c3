#include "support/adjoint_check.hpp"
#include "styles/styles_support.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#define UP(u, l, r) ((u) > 0.0 ? (u) * (l) : (u) * (r))
#include "r5_ip_upwind_c89_macros_adjoint.hpp"
#include "r5_ip_upwind_c89_macros_tangent.hpp"

DPGEN_KERNEL void r5_ip_upwind_c89_macros(DPGEN_INOUT double* rho, DPGEN_IN const double* u, DPGEN_OUT double* flux, int n, double dt);
TEST_CASE("adversary: r5_ip_upwind_c89_macros") {
  for (int n : {0, 1, 2, 3, 4, 9}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n), size_t(n)};
    p.out_sizes = {size_t(n), size_t(n + 1)};
    p.forward = [&](auto in, auto out) { std::copy(in[0], in[0] + size_t(n), out[0]); r5_ip_upwind_c89_macros(out[0], in[1], out[1], n, 0.3); };
    p.adjoint = [&](auto in, auto adj, auto seed) { std::vector<double> t0(seed[0], seed[0] + size_t(n)); r5_ip_upwind_c89_macros_adjoint(in[0], t0.data(), in[1], adj[1], seed[1], n, 0.3); for (size_t z = 0; z < t0.size(); ++z) adj[0][z] += t0[z]; };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { std::copy(in[0], in[0] + size_t(n), out[0]); std::copy(dir[0], dir[0] + size_t(n), outd[0]); r5_ip_upwind_c89_macros_tangent(out[0], outd[0], in[1], dir[1], out[1], outd[1], n, 0.3); };
    dpgen_test::check_adjoint(p);
  }
}
