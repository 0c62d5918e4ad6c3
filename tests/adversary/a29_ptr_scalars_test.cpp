#include "support/adjoint_check.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include "a29_ptr_scalars_adjoint.hpp"
#include "a29_ptr_scalars_tangent.hpp"

DPGEN_KERNEL void a29_ptr_scalars(DPGEN_IN const double* u, DPGEN_OUT double* o, const int* xmin, const int* xmax, const double* dt);
TEST_CASE("adversary: a29_ptr_scalars") {
  for (int n : {0, 1, 2, 3, 4, 7, 16}) {
    int lo = 1, hi = n; double dt = 0.3;
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n+2)};
    p.out_sizes = {size_t(n+2)};
    p.forward = [&](auto in, auto out) { a29_ptr_scalars(in[0], out[0], &lo, &hi, &dt); };
    p.adjoint = [&](auto in, auto adj, auto seed) { a29_ptr_scalars_adjoint(in[0], adj[0], seed[0], &lo, &hi, &dt); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { a29_ptr_scalars_tangent(in[0], dir[0], out[0], outd[0], &lo, &hi, &dt); };
    dpgen_test::check_adjoint(p);
  }
}
