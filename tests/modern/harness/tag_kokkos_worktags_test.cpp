#include "corpus_check.hpp"

#include "tag_kokkos_worktags.cpp"
#include "tag_kokkos_worktags_adjoint.hpp"
#if CORPUS_TANGENT
#include "tag_kokkos_worktags_tangent.hpp"
#endif

using namespace corpus;
using V2 = Kokkos::View<double**>;

TEST_CASE("modern: gradient_fluxes") {
  for (auto [nx, ny] : {std::pair{1, 1}, {4, 3}}) {
    const size_t N = size_t(nx * ny);
    auto v = [&](const double* q) { return V2(mut(q), nx, ny); };
    Problem<double> p;
    p.in_sizes = {N};
    p.out_sizes = {N, N};
    p.linear = true;
    p.forward = [&](auto in, auto out) {
      gradient_fluxes(v(in[0]), v(out[0]), v(out[1]), 0.5, 0.25);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      gradient_fluxes_adjoint(v(in[0]), v(adj[0]), v(seed[0]), v(seed[1]), 0.5, 0.25);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      gradient_fluxes_tangent(v(in[0]), v(d[0]), v(out[0]), v(dout[0]), v(out[1]), v(dout[1]), 0.5,
                              0.25);
    };
#endif
    check_adjoint(p);
  }
}
