#include "corpus_check.hpp"

#include "window_correlate.cpp"
#include "window_correlate_adjoint.hpp"
#if CORPUS_TANGENT
#include "window_correlate_tangent.hpp"
#endif

using namespace corpus;

TEST_CASE("modern: correlate1d") {
  for (auto [n, d] : {std::pair{1, 0}, {1, 2}, {6, 1}, {11, 3}}) {
    Problem<double> p;
    p.in_sizes = {size_t(n), size_t(2 * d + 1)};
    p.in_ranges = {{-1, 1}, {-0.5, 0.5}};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { correlate1d(in[0], in[1], out[0], n, d); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      correlate1d_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n, d);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto dd, auto out, auto dout) {
      correlate1d_tangent(in[0], dd[0], in[1], dd[1], out[0], dout[0], n, d);
    };
#endif
    check_adjoint(p);
  }
}
