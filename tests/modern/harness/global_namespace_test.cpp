#include "corpus_check.hpp"

#include "global_namespace.cpp"
#include "global_namespace_adjoint.hpp"
#if CORPUS_TANGENT
#include "global_namespace_tangent.hpp"
#endif

namespace model {
extern double* source_adj;
__attribute__((weak)) double* source_adj = nullptr;
#if CORPUS_TANGENT
extern double* source_dot;
__attribute__((weak)) double* source_dot = nullptr;
#endif
} // namespace model

using namespace corpus;

TEST_CASE("modern: forced_decay") {
  for (int n : {1, 6}) {
    const size_t N = size_t(model::nmodes * n);
    Problem<double> p;
    p.in_sizes = {N, N}; // q, then the global model::source
    p.out_sizes = {N};
    p.forward = [&](auto in, auto out) {
      model::source = mut(in[1]);
      forced_decay(in[0], out[0], n, 0.3);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      model::source = mut(in[1]);
      model::source_adj = adj[1];
      forced_decay_adjoint(in[0], adj[0], seed[0], n, 0.3);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      model::source = mut(in[1]);
      model::source_dot = mut(d[1]);
      forced_decay_tangent(in[0], d[0], out[0], dout[0], n, 0.3);
    };
#endif
    check_adjoint(p);
  }
}
