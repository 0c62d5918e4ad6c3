#include "corpus_check.hpp"

#include "tmpl_dir.cpp"
#include "tmpl_dir_adjoint.hpp"
#if CORPUS_TANGENT
#include "tmpl_dir_tangent.hpp"
#endif

#ifdef CORPUS_SELFCHECK
template <class Real, int Dir, class... A> void gradient_adjoint(A&&...) {}
template <class Real, int Dir, class... A> void gradient_tangent(A&&...) {}
#endif

using namespace corpus;

template <int Dir> void check_gradient() {
  for (auto [nx, ny] : {std::pair{1, 1}, {3, 2}, {5, 4}}) {
    const size_t N = size_t(nx) * size_t(ny);
    Problem<double> p;
    p.in_sizes = {N};
    p.out_sizes = {N};
    p.linear = true;
    p.forward = [&](auto in, auto out) { gradient<double, Dir>(in[0], out[0], nx, ny, 1.5); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      gradient_adjoint<double, Dir>(in[0], adj[0], seed[0], nx, ny, 1.5);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      gradient_tangent<double, Dir>(in[0], d[0], out[0], dout[0], nx, ny, 1.5);
    };
#endif
    check_adjoint(p);
  }
}

TEST_CASE("modern: gradient") {
  check_gradient<0>();
  check_gradient<1>();
}
