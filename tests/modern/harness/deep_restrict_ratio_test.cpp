#include "corpus_check.hpp"

#include "deep_restrict_ratio.cpp"
#include "deep_restrict_ratio_adjoint.hpp"
#if CORPUS_TANGENT
#include "deep_restrict_ratio_tangent.hpp"
#endif

using namespace corpus;

TEST_CASE("modern: restrict_avg3d") {
  for (auto [cx, cy, cz, r] : {std::array{1, 1, 1, 1}, {2, 1, 2, 2}, {3, 2, 1, 3}}) {
    Problem<double> p;
    p.in_sizes = {size_t(cx * cy * cz * r * r * r)};
    p.out_sizes = {size_t(cx * cy * cz)};
    p.linear = true;
    p.forward = [&](auto in, auto out) { restrict_avg3d(in[0], out[0], cx, cy, cz, r); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      restrict_avg3d_adjoint(in[0], adj[0], seed[0], cx, cy, cz, r);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      restrict_avg3d_tangent(in[0], d[0], out[0], dout[0], cx, cy, cz, r);
    };
#endif
    check_adjoint(p);
  }
}
