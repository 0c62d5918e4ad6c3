#include "corpus_check.hpp"

#include "bitops_redblack.cpp"
#include "bitops_redblack_adjoint.hpp"
#if CORPUS_TANGENT
#include "bitops_redblack_tangent.hpp"
#endif

using namespace corpus;

TEST_CASE("modern: rb_half_sweep") {
  for (auto [nx, ny] : {std::pair{1, 1}, {3, 3}, {6, 5}})
    for (int color : {0, 1}) {
      const size_t N = size_t(nx * ny);
      std::vector<double> f(N);
      for (size_t c = 0; c < N; ++c)
        f[c] = 0.1 * double(c % 5);
      Problem<double> p;
      p.in_sizes = {N};
      p.out_sizes = {N};
      p.linear = true;
      p.forward = [&](auto in, auto out) {
        rb_half_sweep(in[0], f.data(), out[0], nx, ny, color, 0.5);
      };
      p.adjoint = [&](auto in, auto adj, auto seed) {
        rb_half_sweep_adjoint(in[0], adj[0], f.data(), seed[0], nx, ny, color, 0.5);
      };
#if CORPUS_TANGENT
      p.tangent = [&](auto in, auto d, auto out, auto dout) {
        rb_half_sweep_tangent(in[0], d[0], f.data(), out[0], dout[0], nx, ny, color, 0.5);
      };
#endif
      check_adjoint(p);
    }
}
