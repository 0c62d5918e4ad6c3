#include "corpus_check.hpp"

#include "window_variance2d.cpp"
#include "window_variance2d_adjoint.hpp"
#if CORPUS_TANGENT
#include "window_variance2d_tangent.hpp"
#endif

using namespace corpus;

TEST_CASE("modern: local_variance") {
  for (auto [nx, ny, d] : {std::array{1, 1, 0}, {5, 4, 1}, {7, 7, 2}}) {
    Problem<double> p;
    p.in_sizes = {size_t(nx * ny)};
    p.out_sizes = {size_t(nx * ny)};
    p.forward = [&](auto in, auto out) { local_variance(in[0], out[0], nx, ny, d); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      local_variance_adjoint(in[0], adj[0], seed[0], nx, ny, d);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto dd, auto out, auto dout) {
      local_variance_tangent(in[0], dd[0], out[0], dout[0], nx, ny, d);
    };
#endif
    check_adjoint(p);
  }
}
