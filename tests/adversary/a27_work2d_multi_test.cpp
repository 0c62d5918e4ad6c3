#include "support/adjoint_check.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include "a27_work2d_multi_adjoint.hpp"
#include "a27_work2d_multi_tangent.hpp"

DPGEN_KERNEL void a27_work2d_multi(DPGEN_IN const double* q, DPGEN_OUT double* fx, DPGEN_OUT double* fy,
                                   DPGEN_OUT double* qn, int nx, int ny);
TEST_CASE("adversary: a27_work2d_multi") {
  for (int nx : {1, 2, 3, 5}) for (int ny : {1, 2, 3, 4}) {
    int n = nx * ny;
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(nx*ny)};
    p.out_sizes = {size_t(nx*ny), size_t(nx*ny), size_t(nx*ny)};
    p.forward = [&](auto in, auto out) { a27_work2d_multi(in[0], out[0], out[1], out[2], nx, ny); };
    p.adjoint = [&](auto in, auto adj, auto seed) { a27_work2d_multi_adjoint(in[0], adj[0], seed[0], seed[1], seed[2], nx, ny); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { a27_work2d_multi_tangent(in[0], dir[0], out[0], outd[0], out[1], outd[1], out[2], outd[2], nx, ny); };
    dpgen_test::check_adjoint(p);
  }
}
