#include "support/adjoint_check.hpp"
#include "styles/styles_support.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include "r4_rp_mixed_flat_adjoint.hpp"
#include "r4_rp_mixed_flat_tangent.hpp"

DPGEN_KERNEL void r4_rp_mixed_flat(DPGEN_IN double** a, DPGEN_IN const double* w, DPGEN_OUT double* r,
                                   int n, int m);
TEST_CASE("adversary: r4_rp_mixed_flat") {
  for (auto [n, m] : {std::pair{1, 2}, {1, 3}, {3, 2}, {2, 4}, {4, 3}, {5, 6}}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(m) * size_t(n), size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { auto ri0 = styles::rows(in[0], size_t(m), size_t(n)); r4_rp_mixed_flat(ri0.data(), in[1], out[0], n, m); };
    p.adjoint = [&](auto in, auto adj, auto seed) { auto ri0 = styles::rows(in[0], size_t(m), size_t(n)); auto ai0 = styles::rows(adj[0], size_t(m), size_t(n)); r4_rp_mixed_flat_adjoint(ri0.data(), ai0.data(), in[1], adj[1], seed[0], n, m); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { auto ri0 = styles::rows(in[0], size_t(m), size_t(n)); auto di0 = styles::rows(dir[0], size_t(m), size_t(n)); r4_rp_mixed_flat_tangent(ri0.data(), di0.data(), in[1], dir[1], out[0], outd[0], n, m); };
    dpgen_test::check_adjoint(p);
  }
}
