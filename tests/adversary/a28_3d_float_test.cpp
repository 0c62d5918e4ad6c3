#include "support/adjoint_check.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include "a28_3d_float_adjoint.hpp"
#include "a28_3d_float_tangent.hpp"

DPGEN_KERNEL void a28_3d_float(DPGEN_IN const float* u, DPGEN_OUT float* o, int nx, int ny, int nz);
TEST_CASE("adversary: a28_3d_float") {
  for (int nx : {1, 3, 4}) for (int ny : {2, 3}) for (int nz : {3, 5}) {
    int n = nx;
    CAPTURE(n);
    dpgen_test::Problem<float> p;
    p.in_sizes = {size_t(nx*ny*nz)};
    p.out_sizes = {size_t(nx*ny*nz)};
    p.forward = [&](auto in, auto out) { a28_3d_float(in[0], out[0], nx, ny, nz); };
    p.adjoint = [&](auto in, auto adj, auto seed) { a28_3d_float_adjoint(in[0], adj[0], seed[0], nx, ny, nz); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { a28_3d_float_tangent(in[0], dir[0], out[0], outd[0], nx, ny, nz); };
    dpgen_test::check_adjoint(p);
  }
}
