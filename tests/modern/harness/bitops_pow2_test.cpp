#include "corpus_check.hpp"

#include "bitops_pow2.cpp"
#include "bitops_pow2_adjoint.hpp"
#if CORPUS_TANGENT
#include "bitops_pow2_tangent.hpp"
#endif

using namespace corpus;

TEST_CASE("modern: periodic_laplace_pow2") {
  for (int lg : {0, 1, 2, 3}) {
    const size_t N = size_t(1) << (2 * lg);
    Problem<double> p;
    p.in_sizes = {N};
    p.out_sizes = {N};
    p.linear = true;
    p.forward = [&](auto in, auto out) { periodic_laplace_pow2(in[0], out[0], lg); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      periodic_laplace_pow2_adjoint(in[0], adj[0], seed[0], lg);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      periodic_laplace_pow2_tangent(in[0], d[0], out[0], dout[0], lg);
    };
#endif
    check_adjoint(p);
  }
}

TEST_CASE("modern: haar_pairs") {
  for (int n : {1, 2, 7, 10}) {
    Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.linear = true;
    p.forward = [&](auto in, auto out) { haar_pairs(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      haar_pairs_adjoint(in[0], adj[0], seed[0], n);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      haar_pairs_tangent(in[0], d[0], out[0], dout[0], n);
    };
#endif
    check_adjoint(p);
  }
}
