// ptr_scalar_index (tests/adversary/): an index offset read through a pointer
// inside the index expression, a[i + *off].
#include "adv.hpp"
#include "ptr_scalar_index_adjoint.hpp"
#include "ptr_scalar_index_tangent.hpp"
void ptr_scalar_index(const double* a, double* out, int n, const int* off);
TEST_CASE("adversary: ptr_scalar_index") {
  for (auto [n, o] : {std::pair{0, 0}, {1, 0}, {1, 2}, {3, 1}, {4, 0}, {5, 3}}) {
    CAPTURE(n); CAPTURE(o);
    int off = o;
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n + o)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { ptr_scalar_index(in[0], out[0], n, &off); };
    p.adjoint = [&](auto in, auto adj, auto seed) { ptr_scalar_index_adjoint(in[0], adj[0], seed[0], n, &off); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { ptr_scalar_index_tangent(in[0], dir[0], out[0], od[0], n, &off); };
    dpgen_test::check_adjoint(p);
  }
}
