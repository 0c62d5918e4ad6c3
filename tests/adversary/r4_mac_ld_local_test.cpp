#include "support/adjoint_check.hpp"
#include "styles/styles_support.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#define IDX(i, j) ((i) + ng + ((j) + ng) * ld)
#include "r4_mac_ld_local_adjoint.hpp"
#include "r4_mac_ld_local_tangent.hpp"

DPGEN_KERNEL void r4_mac_ld_local(DPGEN_IN const double* u, DPGEN_OUT double* v, int n, int m);
TEST_CASE("adversary: r4_mac_ld_local") {
  for (auto [n, m] : {std::pair{1, 1}, {1, 3}, {3, 1}, {2, 2}, {4, 3}, {5, 6}}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t((n+2)*(m+2))};
    p.out_sizes = {size_t((n+2)*(m+2))};
    p.forward = [&](auto in, auto out) { r4_mac_ld_local(in[0], out[0], n, m); };
    p.adjoint = [&](auto in, auto adj, auto seed) { r4_mac_ld_local_adjoint(in[0], adj[0], seed[0], n, m); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { r4_mac_ld_local_tangent(in[0], dir[0], out[0], outd[0], n, m); };
    dpgen_test::check_adjoint(p);
  }
}
