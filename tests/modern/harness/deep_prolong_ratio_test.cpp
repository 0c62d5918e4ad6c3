#include "corpus_check.hpp"

#include "deep_prolong_ratio.cpp"
#include "deep_prolong_ratio_adjoint.hpp"
#if CORPUS_TANGENT
#include "deep_prolong_ratio_tangent.hpp"
#endif

using namespace corpus;

TEST_CASE("modern: prolong_pc2d") {
  for (auto [nc, cx, cy, r] : {std::array{1, 1, 1, 1}, {2, 2, 3, 2}, {1, 3, 2, 4}}) {
    Problem<double> p;
    p.in_sizes = {size_t(nc * cx * cy)};
    p.out_sizes = {size_t(nc * cx * cy * r * r)};
    p.linear = true;
    p.forward = [&](auto in, auto out) { prolong_pc2d(in[0], out[0], nc, cx, cy, r); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      prolong_pc2d_adjoint(in[0], adj[0], seed[0], nc, cx, cy, r);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      prolong_pc2d_tangent(in[0], d[0], out[0], dout[0], nc, cx, cy, r);
    };
#endif
    check_adjoint(p);
  }
}
