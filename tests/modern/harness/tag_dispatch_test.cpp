#include "corpus_check.hpp"

#include "tag_dispatch.cpp"
#include "tag_dispatch_adjoint.hpp"
#if CORPUS_TANGENT
#include "tag_dispatch_tangent.hpp"
#endif

using namespace corpus;

template <class Dir> void check_sweep() {
  for (auto [nx, ny] : {std::pair{1, 1}, {3, 4}, {6, 3}}) {
    const size_t N = size_t(nx * ny);
    Problem<double> p;
    p.in_sizes = {N};
    p.out_sizes = {N};
    p.linear = true;
    p.forward = [&](auto in, auto out) { sweep(in[0], out[0], nx, ny, 0.3, Dir{}); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      sweep_adjoint(in[0], adj[0], seed[0], nx, ny, 0.3, Dir{});
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      sweep_tangent(in[0], d[0], out[0], dout[0], nx, ny, 0.3, Dir{});
    };
#endif
    check_adjoint(p);
  }
}

TEST_CASE("modern: sweep(XDir)") { check_sweep<XDir>(); }
TEST_CASE("modern: sweep(YDir)") { check_sweep<YDir>(); }
