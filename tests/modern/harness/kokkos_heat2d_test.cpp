#include "corpus_check.hpp"

#include "kokkos_heat2d.cpp"
#include "kokkos_heat2d_adjoint.hpp"
#if CORPUS_TANGENT
#include "kokkos_heat2d_tangent.hpp"
#endif

using namespace corpus;
using V2 = Kokkos::View<double**>;

TEST_CASE("modern: heat2d_step") {
  for (auto [nx, ny] : {std::pair{1, 1}, {3, 3}, {7, 5}, {4, 9}}) {
    const size_t N = size_t(nx) * size_t(ny);
    Problem<double> p;
    p.in_sizes = {N};
    p.out_sizes = {N};
    p.linear = true;
    p.forward = [&](auto in, auto out) {
      heat2d_step(V2(mut(in[0]), nx, ny), V2(out[0], nx, ny), 0.2);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      heat2d_step_adjoint(V2(mut(in[0]), nx, ny), V2(adj[0], nx, ny), V2(mut(seed[0]), nx, ny),
                          0.2);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      heat2d_step_tangent(V2(mut(in[0]), nx, ny), V2(mut(d[0]), nx, ny), V2(out[0], nx, ny),
                          V2(dout[0], nx, ny), 0.2);
    };
#endif
    check_adjoint(p);
  }
}
