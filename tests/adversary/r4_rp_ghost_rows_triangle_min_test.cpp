#include "support/adjoint_check.hpp"
#include "styles/styles_support.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#include "r4_rp_ghost_rows_triangle_min_adjoint.hpp"
#include "r4_rp_ghost_rows_triangle_min_tangent.hpp"

DPGEN_KERNEL void r4_rp_ghost_rows_triangle_min(DPGEN_IN double** a, DPGEN_OUT double** b, int n, int m);
TEST_CASE("adversary: r4_rp_ghost_rows_triangle_min") {
  for (auto [n, m] : {std::pair{1, 2}, {3, 3}, {4, 5}}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(m) * size_t(n)};
    p.out_sizes = {size_t(m) * size_t(n)};
    p.forward = [&](auto in, auto out) { auto ri0 = styles::rows(in[0], size_t(m), size_t(n)); auto ro0 = styles::rows(out[0], size_t(m), size_t(n)); r4_rp_ghost_rows_triangle_min(ri0.data(), ro0.data(), n, m); };
    p.adjoint = [&](auto in, auto adj, auto seed) { auto ri0 = styles::rows(in[0], size_t(m), size_t(n)); auto ai0 = styles::rows(adj[0], size_t(m), size_t(n)); auto so0 = styles::rows(seed[0], size_t(m), size_t(n)); r4_rp_ghost_rows_triangle_min_adjoint(ri0.data(), ai0.data(), so0.data(), n, m); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { auto ri0 = styles::rows(in[0], size_t(m), size_t(n)); auto di0 = styles::rows(dir[0], size_t(m), size_t(n)); auto ro0 = styles::rows(out[0], size_t(m), size_t(n)); auto do0 = styles::rows(outd[0], size_t(m), size_t(n)); r4_rp_ghost_rows_triangle_min_tangent(ri0.data(), di0.data(), ro0.data(), do0.data(), n, m); };
    dpgen_test::check_adjoint(p);
  }
}
