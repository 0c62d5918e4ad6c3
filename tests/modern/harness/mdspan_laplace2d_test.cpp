#include "corpus_check.hpp"

#include "mdspan_laplace2d.cpp"
#include "mdspan_laplace2d_adjoint.hpp"
#if CORPUS_TANGENT
#include "mdspan_laplace2d_tangent.hpp"
#endif

using namespace corpus;

TEST_CASE("modern: laplace2d") {
  for (auto [ny, nx] : {std::pair{1, 1}, {3, 3}, {5, 8}, {9, 4}}) {
    const size_t N = size_t(nx) * size_t(ny);
    Problem<double> p;
    p.in_sizes = {N};
    p.out_sizes = {N};
    p.linear = true;
    p.forward = [&](auto in, auto out) {
      laplace2d(grid_t(mut(in[0]), ny, nx), grid_t(out[0], ny, nx), 3.0);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      laplace2d_adjoint(grid_t(mut(in[0]), ny, nx), grid_t(adj[0], ny, nx),
                        grid_t(mut(seed[0]), ny, nx), 3.0);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      laplace2d_tangent(grid_t(mut(in[0]), ny, nx), grid_t(mut(d[0]), ny, nx),
                        grid_t(out[0], ny, nx), grid_t(dout[0], ny, nx), 3.0);
    };
#endif
    check_adjoint(p);
  }
}
