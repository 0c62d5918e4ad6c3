#include "corpus_check.hpp"

#include "tmpl_diffuse.cpp"
#include "tmpl_diffuse_adjoint.hpp"
#if CORPUS_TANGENT
#include "tmpl_diffuse_tangent.hpp"
#endif

#ifdef CORPUS_SELFCHECK
template <class Real, class... A> void diffuse1d_adjoint(A&&...) {}
template <class Real, class... A> void diffuse1d_tangent(A&&...) {}
#endif

using namespace corpus;

template <typename Real> void check_diffuse() {
  for (int n : {1, 2, 3, 12}) {
    Problem<Real> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.linear = true;
    p.forward = [&](auto in, auto out) { diffuse1d<Real>(in[0], out[0], n, Real(0.3)); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      diffuse1d_adjoint<Real>(in[0], adj[0], seed[0], n, Real(0.3));
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      diffuse1d_tangent<Real>(in[0], d[0], out[0], dout[0], n, Real(0.3));
    };
#endif
    check_adjoint(p);
  }
}

TEST_CASE("modern: diffuse1d") {
  check_diffuse<double>();
  check_diffuse<float>();
}
