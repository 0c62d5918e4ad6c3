#include "corpus_check.hpp"

#include "kokkos_varcoef3d.cpp"
#include "kokkos_varcoef3d_adjoint.hpp"
#if CORPUS_TANGENT
#include "kokkos_varcoef3d_tangent.hpp"
#endif

using namespace corpus;
using V3 = Kokkos::View<double***>;

TEST_CASE("modern: varcoef_apply") {
  for (auto [a, b, c] : {std::array{1, 1, 1}, {3, 3, 3}, {5, 4, 3}}) {
    const size_t N = size_t(a) * size_t(b) * size_t(c);
    Problem<double> p;
    p.in_sizes = {N, N};
    p.in_ranges = {{0.5, 2.0}, {-1, 1}};
    p.out_sizes = {N};
    p.forward = [&](auto in, auto out) {
      varcoef_apply(V3(mut(in[0]), a, b, c), V3(mut(in[1]), a, b, c), V3(out[0], a, b, c), 1.7);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      varcoef_apply_adjoint(V3(mut(in[0]), a, b, c), V3(adj[0], a, b, c), V3(mut(in[1]), a, b, c),
                            V3(adj[1], a, b, c), V3(mut(seed[0]), a, b, c), 1.7);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      varcoef_apply_tangent(V3(mut(in[0]), a, b, c), V3(mut(d[0]), a, b, c),
                            V3(mut(in[1]), a, b, c), V3(mut(d[1]), a, b, c), V3(out[0], a, b, c),
                            V3(dout[0], a, b, c), 1.7);
    };
#endif
    check_adjoint(p);
  }
}
