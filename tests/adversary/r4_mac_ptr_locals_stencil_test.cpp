#include "support/adjoint_check.hpp"
#include "styles/styles_support.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#define IDX(i, j) ((i) - (x_min - 1) + ((j) - (x_min - 1)) * (x_max - x_min + 3))
#include "r4_mac_ptr_locals_stencil_adjoint.hpp"
#include "r4_mac_ptr_locals_stencil_tangent.hpp"

DPGEN_KERNEL void r4_mac_ptr_locals_stencil(const int* xmin, const int* xmax, DPGEN_IN const double* u,
                                            DPGEN_OUT double* v);
TEST_CASE("adversary: r4_mac_ptr_locals_stencil") {
  for (int n : {1, 2, 3, 5}) {
    int lo = 2, hi = lo + n - 1; const int* xmin = &lo; const int* xmax = &hi;
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t((n+2)*(n+2))};
    p.out_sizes = {size_t((n+2)*(n+2))};
    p.forward = [&](auto in, auto out) { r4_mac_ptr_locals_stencil(xmin, xmax, in[0], out[0]); };
    p.adjoint = [&](auto in, auto adj, auto seed) { r4_mac_ptr_locals_stencil_adjoint(xmin, xmax, in[0], adj[0], seed[0]); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { r4_mac_ptr_locals_stencil_tangent(xmin, xmax, in[0], dir[0], out[0], outd[0]); };
    dpgen_test::check_adjoint(p);
  }
}
