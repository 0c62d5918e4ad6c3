#include "corpus_check.hpp"

#include "mdspan_lbm.cpp"
#include "mdspan_lbm_adjoint.hpp"
#if CORPUS_TANGENT
#include "mdspan_lbm_tangent.hpp"
#endif

using namespace corpus;

TEST_CASE("modern: lbm_collide") {
  for (auto [ny, nx] : {std::pair{1, 1}, {3, 4}}) {
    const size_t N = size_t(Q) * size_t(nx) * size_t(ny);
    auto f = [&](const double* q) { return pop_t(mut(q), Q, ny, nx); };
    Problem<double> p;
    p.in_sizes = {N};
    p.in_ranges = {{0.05, 0.2}}; // populations near equilibrium, rho > 0
    p.out_sizes = {N};
    p.forward = [&](auto in, auto out) { lbm_collide(f(in[0]), f(out[0]), 1.2); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      lbm_collide_adjoint(f(in[0]), f(adj[0]), f(seed[0]), 1.2);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      lbm_collide_tangent(f(in[0]), f(d[0]), f(out[0]), f(dout[0]), 1.2);
    };
#endif
    check_adjoint(p);
  }
}

TEST_CASE("modern: lbm_stream") {
  for (auto [ny, nx] : {std::pair{1, 1}, {2, 1}, {3, 4}, {5, 2}}) {
    const size_t N = size_t(Q) * size_t(nx) * size_t(ny);
    auto f = [&](const double* q) { return pop_t(mut(q), Q, ny, nx); };
    Problem<double> p;
    p.in_sizes = {N};
    p.out_sizes = {N};
    p.linear = true;
    p.forward = [&](auto in, auto out) { lbm_stream(f(in[0]), f(out[0])); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      lbm_stream_adjoint(f(in[0]), f(adj[0]), f(seed[0]));
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      lbm_stream_tangent(f(in[0]), f(d[0]), f(out[0]), f(dout[0]));
    };
#endif
    check_adjoint(p);
  }
}
