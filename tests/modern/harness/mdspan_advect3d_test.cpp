#include "corpus_check.hpp"

#include "mdspan_advect3d.cpp"
#include "mdspan_advect3d_adjoint.hpp"
#if CORPUS_TANGENT
#include "mdspan_advect3d_tangent.hpp"
#endif

using namespace corpus;

TEST_CASE("modern: advect3d_upwind") {
  for (auto [nz, ny, nx] : {std::array<size_t, 3>{1, 1, 1}, {1, 3, 1}, {2, 4, 5}, {3, 3, 2}}) {
    const size_t N = nx * ny * nz;
    auto f = [&](const double* q) { return field3<double>(mut(q), nz, ny, nx); };
    Problem<double> p;
    p.in_sizes = {N, N, N};
    p.out_sizes = {N};
    p.forward = [&](auto in, auto out) {
      advect3d_upwind(f(in[0]), f(in[1]), f(in[2]), f(out[0]), 0.3);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      advect3d_upwind_adjoint(f(in[0]), f(adj[0]), f(in[1]), f(adj[1]), f(in[2]), f(adj[2]),
                              f(seed[0]), 0.3);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      advect3d_upwind_tangent(f(in[0]), f(d[0]), f(in[1]), f(d[1]), f(in[2]), f(d[2]), f(out[0]),
                              f(dout[0]), 0.3);
    };
#endif
    check_adjoint(p);
  }
}
