#include "support/adjoint_check.hpp"
#include "styles/styles_support.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#include "r5_pin_k_k_2d_adjoint.hpp"
#include "r5_pin_k_k_2d_tangent.hpp"

DPGEN_KERNEL void r5_pin_k_k_2d(DPGEN_IN const double* a, DPGEN_OUT double* out, int nx, int ny, int k);
TEST_CASE("adversary: r5_pin_k_k_2d") {
  for (int k : {0, 1, 3}) for (auto [n, m] : {std::pair{0, 0}, {1, 1}, {2, 3}, {4, 4}}) {
    CAPTURE(k);
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n*m)};
    p.out_sizes = {size_t(1)};
    p.forward = [&](auto in, auto out) { r5_pin_k_k_2d(in[0], out[0], n, m, k); };
    p.adjoint = [&](auto in, auto adj, auto seed) { r5_pin_k_k_2d_adjoint(in[0], adj[0], seed[0], n, m, k); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { r5_pin_k_k_2d_tangent(in[0], dir[0], out[0], outd[0], n, m, k); };
    dpgen_test::check_adjoint(p);
  }
}
