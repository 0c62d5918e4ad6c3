// ptr_scalars (tests/adversary/): bounds and a coefficient passed by pointer,
// copied into locals; reads a[x_min - 1 .. x_max + 1].
#include "adv.hpp"
#include "ptr_scalars_adjoint.hpp"
#include "ptr_scalars_tangent.hpp"
void ptr_scalars(const double* a, double* out, const int* xmin, const int* xmax, const double* dt);
TEST_CASE("adversary: ptr_scalars") {
  for (auto [lo, hi] : {std::pair{1, 0}, {1, 1}, {1, 2}, {2, 2}, {3, 7}, {2, 1}}) {
    CAPTURE(lo); CAPTURE(hi);
    int xmin = lo, xmax = hi;
    double dt = 0.3;
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(hi + 2)};
    p.out_sizes = {ADV_SZ(hi >= lo ? hi - lo + 1 : 0)};
    p.forward = [&](auto in, auto out) { ptr_scalars(in[0], out[0], &xmin, &xmax, &dt); };
    p.adjoint = [&](auto in, auto adj, auto seed) { ptr_scalars_adjoint(in[0], adj[0], seed[0], &xmin, &xmax, &dt); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { ptr_scalars_tangent(in[0], dir[0], out[0], od[0], &xmin, &xmax, &dt); };
    dpgen_test::check_adjoint(p);
  }
}
