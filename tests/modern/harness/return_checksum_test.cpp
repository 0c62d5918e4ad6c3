#include "corpus_check.hpp"

#include "return_checksum.cpp"
#include "return_checksum_adjoint.hpp"
#if CORPUS_TANGENT
#include "return_checksum_tangent.hpp"
#endif

using namespace corpus;

TEST_CASE("modern: checksum") {
  for (int n : {0, 1, 7}) {
    Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {1};
    p.forward = [&](auto in, auto out) { out[0][0] = checksum(in[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      checksum_adjoint(in[0], adj[0], n, seed[0][0]);
    };
#if CORPUS_TANGENT
    // tangent (assumed): returns the value, J v through a trailing double&
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      out[0][0] = checksum_tangent(in[0], d[0], n, dout[0][0]);
    };
#endif
    check_adjoint(p);
  }
}
