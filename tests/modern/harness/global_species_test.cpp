#include "corpus_check.hpp"

#include "global_species.cpp"
#include "global_species_adjoint.hpp"
#if CORPUS_TANGENT
#include "global_species_tangent.hpp"
#endif

extern double* g_diff_adj;
__attribute__((weak)) double* g_diff_adj = nullptr;
#if CORPUS_TANGENT
extern double* g_diff_dot;
__attribute__((weak)) double* g_diff_dot = nullptr;
#endif

using namespace corpus;

TEST_CASE("modern: species_rhs") {
  for (int n : {1, 3, 8}) {
    auto set = [&](const double* d) {
      for (int s = 0; s < NSPEC; ++s)
        g_diff[s] = d[s];
    };
    Problem<double> p;
    p.in_sizes = {size_t(NSPEC * n), size_t(NSPEC)};
    p.out_sizes = {size_t(NSPEC * n)};
    p.forward = [&](auto in, auto out) {
      set(in[1]);
      species_rhs(in[0], out[0], n, 2.0);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      set(in[1]);
      g_diff_adj = adj[1];
      species_rhs_adjoint(in[0], adj[0], seed[0], n, 2.0);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      set(in[1]);
      g_diff_dot = mut(d[1]);
      species_rhs_tangent(in[0], d[0], out[0], dout[0], n, 2.0);
    };
#endif
    check_adjoint(p);
  }
}
