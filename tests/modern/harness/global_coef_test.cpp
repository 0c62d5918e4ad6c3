#include "corpus_check.hpp"

#include "global_coef.cpp"
#include "global_coef_adjoint.hpp"
#if CORPUS_TANGENT
#include "global_coef_tangent.hpp"
#endif

// Issue 22: the adjoint header declares `extern double* g_kappa_adj;`; where
// the generated code does not also define it, these weak definitions do.
extern double* g_kappa_adj;
extern double* g_stencil_adj;
__attribute__((weak)) double* g_kappa_adj = nullptr;
__attribute__((weak)) double* g_stencil_adj = nullptr;
#if CORPUS_TANGENT
// tangent (assumed by analogy): extern double* g_kappa_dot, g_stencil_dot
extern double* g_kappa_dot;
extern double* g_stencil_dot;
__attribute__((weak)) double* g_kappa_dot = nullptr;
__attribute__((weak)) double* g_stencil_dot = nullptr;
#endif

using namespace corpus;

TEST_CASE("modern: varcoef_smooth") {
  for (int n : {1, 3, 10}) {
    auto set_globals = [&](const double* kappa, const double* stencil) {
      g_kappa = mut(kappa);
      for (int m = 0; m < 3; ++m)
        g_stencil[m] = stencil[m];
    };
    Problem<double> p;
    p.in_sizes = {size_t(n), size_t(n), 3}; // u, then the globals g_kappa and g_stencil
    p.in_ranges = {{-1, 1}, {0.5, 1.5}, {0.1, 0.6}};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) {
      set_globals(in[1], in[2]);
      varcoef_smooth(in[0], out[0], n);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      set_globals(in[1], in[2]);
      g_kappa_adj = adj[1];
      g_stencil_adj = adj[2];
      varcoef_smooth_adjoint(in[0], adj[0], seed[0], n);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      set_globals(in[1], in[2]);
      g_kappa_dot = mut(d[1]);
      g_stencil_dot = mut(d[2]);
      varcoef_smooth_tangent(in[0], d[0], out[0], dout[0], n);
    };
#endif
    check_adjoint(p);
  }
}
