#include "corpus_check.hpp"

#include "deep_components.cpp"
#include "deep_components_adjoint.hpp"
#if CORPUS_TANGENT
#include "deep_components_tangent.hpp"
#endif

using namespace corpus;

TEST_CASE("modern: component_laplacian") {
  for (auto [nc, nz, ny, nx] : {std::array{1, 1, 1, 1}, {2, 3, 3, 3}, {3, 4, 3, 5}}) {
    const size_t N = size_t(nc * nz * ny * nx);
    Problem<double> p;
    p.in_sizes = {N};
    p.out_sizes = {N};
    p.linear = true;
    p.forward = [&](auto in, auto out) { component_laplacian(in[0], out[0], nc, nz, ny, nx, 0.5); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      component_laplacian_adjoint(in[0], adj[0], seed[0], nc, nz, ny, nx, 0.5);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      component_laplacian_tangent(in[0], d[0], out[0], dout[0], nc, nz, ny, nx, 0.5);
    };
#endif
    check_adjoint(p);
  }
}
