#include "corpus_check.hpp"

#include "window_boxfilter.cpp"
#include "window_boxfilter_adjoint.hpp"
#if CORPUS_TANGENT
#include "window_boxfilter_tangent.hpp"
#endif

using namespace corpus;

TEST_CASE("modern: box_filter") {
  for (auto [n, d] : {std::pair{1, 0}, {5, 1}, {4, 2}, {13, 3}}) {
    Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.linear = true;
    p.forward = [&](auto in, auto out) { box_filter(in[0], out[0], n, d); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      box_filter_adjoint(in[0], adj[0], seed[0], n, d);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto dd, auto out, auto dout) {
      box_filter_tangent(in[0], dd[0], out[0], dout[0], n, d);
    };
#endif
    check_adjoint(p);
  }
}
