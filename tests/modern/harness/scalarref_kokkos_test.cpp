#include "corpus_check.hpp"

#include "scalarref_kokkos.cpp"
#include "scalarref_kokkos_adjoint.hpp"
#if CORPUS_TANGENT
#include "scalarref_kokkos_tangent.hpp"
#endif

using namespace corpus;
using V1 = Kokkos::View<double*>;

TEST_CASE("modern: l2_error") {
  for (int n : {0, 1, 9}) {
    std::vector<double> ex(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i)
      ex[size_t(i)] = 0.1 * i;
    const V1 u_exact(ex.data(), size_t(n));
    const double dx = 0.125;
    Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {1};
    p.forward = [&](auto in, auto out) { l2_error(V1(mut(in[0]), n), u_exact, dx, out[0][0]); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      l2_error_adjoint(V1(mut(in[0]), n), V1(adj[0], n), u_exact, dx, seed[0][0]);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      l2_error_tangent(V1(mut(in[0]), n), V1(mut(d[0]), n), u_exact, dx, out[0][0], dout[0][0]);
    };
#endif
    check_adjoint(p);
  }
}
