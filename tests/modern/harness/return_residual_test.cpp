#include "corpus_check.hpp"

#include "return_residual.cpp"
#include "return_residual_adjoint.hpp"
#if CORPUS_TANGENT
#include "return_residual_tangent.hpp"
#endif

using namespace corpus;

TEST_CASE("modern: residual") {
  for (int n : {1, 2, 3, 9}) {
    Problem<double> p;
    p.in_sizes = {size_t(n), size_t(n)};
    p.out_sizes = {size_t(n), 1}; // r, then the returned value
    p.forward = [&](auto in, auto out) { out[1][0] = residual(in[0], in[1], out[0], n, 2.0); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      residual_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n, 2.0, seed[1][0]);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      out[1][0] = residual_tangent(in[0], d[0], in[1], d[1], out[0], dout[0], n, 2.0, dout[1][0]);
    };
#endif
    check_adjoint(p);
  }
}
