#include "corpus_check.hpp"

#include "bitops_transfer.cpp"
#include "bitops_transfer_adjoint.hpp"
#if CORPUS_TANGENT
#include "bitops_transfer_tangent.hpp"
#endif

using namespace corpus;

TEST_CASE("modern: restrict_fw") {
  for (int nc : {2, 3, 9}) {
    const int nf = 2 * nc - 1;
    Problem<double> p;
    p.in_sizes = {size_t(nf)};
    p.out_sizes = {size_t(nc)};
    p.linear = true;
    p.forward = [&](auto in, auto out) { restrict_fw(in[0], out[0], nc); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      restrict_fw_adjoint(in[0], adj[0], seed[0], nc);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      restrict_fw_tangent(in[0], d[0], out[0], dout[0], nc);
    };
#endif
    check_adjoint(p);
  }
}

TEST_CASE("modern: prolong_bits") {
  for (int nc : {1, 2, 3, 8}) {
    const int nf = 2 * nc - 1;
    Problem<double> p;
    p.in_sizes = {size_t(nc)};
    p.out_sizes = {size_t(nf)};
    p.linear = true;
    p.forward = [&](auto in, auto out) { prolong_bits(in[0], out[0], nf); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      prolong_bits_adjoint(in[0], adj[0], seed[0], nf);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      prolong_bits_tangent(in[0], d[0], out[0], dout[0], nf);
    };
#endif
    check_adjoint(p);
  }
}
