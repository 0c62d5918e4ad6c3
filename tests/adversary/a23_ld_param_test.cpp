#include "support/adjoint_check.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include "a23_ld_param_adjoint.hpp"
#include "a23_ld_param_tangent.hpp"

DPGEN_KERNEL void a23_ld_param(DPGEN_IN const double* a, DPGEN_OUT double* o, int nx, int ny, int ld);
TEST_CASE("adversary: a23_ld_param") {
  for (int nx : {1, 2, 4}) for (int ny : {1, 2, 3}) for (int ld : {nx, nx + 1}) {
    int n = nx;
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(ld*ny+nx)};
    p.out_sizes = {size_t(ld*ny+nx)};
    p.forward = [&](auto in, auto out) { a23_ld_param(in[0], out[0], nx, ny, ld); };
    p.adjoint = [&](auto in, auto adj, auto seed) { a23_ld_param_adjoint(in[0], adj[0], seed[0], nx, ny, ld); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { a23_ld_param_tangent(in[0], dir[0], out[0], outd[0], nx, ny, ld); };
    dpgen_test::check_adjoint(p);
  }
  {
    std::vector<double> a(64, 1.0), aa(64, 0.0), s(64, 1.0);
    CHECK_THROWS_AS(a23_ld_param_adjoint(a.data(), aa.data(), s.data(), 4, 3, 3), std::invalid_argument);
  }
}
