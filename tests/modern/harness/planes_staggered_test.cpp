#include "corpus_check.hpp"

#include "planes_staggered.cpp"
#include "planes_staggered_adjoint.hpp"
#if CORPUS_TANGENT
#include "planes_staggered_tangent.hpp"
#endif

using namespace corpus;

TEST_CASE("modern: mac_divergence") {
  for (auto [nx, ny] : {std::pair{1, 1}, {4, 3}}) {
    Problem<double> p;
    p.in_sizes = {size_t(2 * (nx + 1) * (ny + 1))};
    p.out_sizes = {size_t(nx * ny)};
    p.linear = true;
    p.forward = [&](auto in, auto out) { mac_divergence(in[0], out[0], nx, ny, 2.0); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      mac_divergence_adjoint(in[0], adj[0], seed[0], nx, ny, 2.0);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      mac_divergence_tangent(in[0], d[0], out[0], dout[0], nx, ny, 2.0);
    };
#endif
    check_adjoint(p);
  }
}

TEST_CASE("modern: mac_gradient") {
  for (auto [nx, ny] : {std::pair{1, 1}, {4, 3}, {2, 5}}) {
    Problem<double> p;
    p.in_sizes = {size_t(nx * ny)};
    p.out_sizes = {size_t(2 * (nx + 1) * (ny + 1))};
    p.linear = true;
    p.forward = [&](auto in, auto out) { mac_gradient(in[0], out[0], nx, ny, 2.0); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      mac_gradient_adjoint(in[0], adj[0], seed[0], nx, ny, 2.0);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      mac_gradient_tangent(in[0], d[0], out[0], dout[0], nx, ny, 2.0);
    };
#endif
    check_adjoint(p);
  }
}
