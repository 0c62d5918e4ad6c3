#include "corpus_check.hpp"

#include "deep_ratio_1d.cpp"
#include "deep_ratio_1d_adjoint.hpp"
#if CORPUS_TANGENT
#include "deep_ratio_1d_tangent.hpp"
#endif

using namespace corpus;

TEST_CASE("modern: restrict_ratio") {
  for (auto [nc, r] : {std::pair{1, 1}, {3, 2}, {4, 3}, {2, 5}}) {
    Problem<double> p;
    p.in_sizes = {size_t(nc * r)};
    p.out_sizes = {size_t(nc)};
    p.linear = true;
    p.forward = [&](auto in, auto out) { restrict_ratio(in[0], out[0], nc, r); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      restrict_ratio_adjoint(in[0], adj[0], seed[0], nc, r);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      restrict_ratio_tangent(in[0], d[0], out[0], dout[0], nc, r);
    };
#endif
    check_adjoint(p);
  }
}

TEST_CASE("modern: prolong_ratio") {
  for (auto [nc, r] : {std::pair{1, 1}, {3, 2}, {5, 3}, {4, 4}}) {
    Problem<double> p;
    p.in_sizes = {size_t(nc)};
    p.out_sizes = {size_t(nc * r)};
    p.linear = true;
    p.forward = [&](auto in, auto out) { prolong_ratio(in[0], out[0], nc, r); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      prolong_ratio_adjoint(in[0], adj[0], seed[0], nc, r);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      prolong_ratio_tangent(in[0], d[0], out[0], dout[0], nc, r);
    };
#endif
    check_adjoint(p);
  }
}
