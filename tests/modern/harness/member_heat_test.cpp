#include "corpus_check.hpp"

#include "member_heat.cpp"
#include "member_heat_adjoint.hpp"
#if CORPUS_TANGENT
#include "member_heat_tangent.hpp"
#endif

using namespace corpus;

TEST_CASE("modern: Heat1D::step") {
  for (int n : {1, 2, 3, 11}) {
    Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.linear = true;
    p.forward = [&](auto in, auto out) { Heat1D(n, 0.7, in[0], out[0]).step(0.4); };
    // the object the adjoint reads: sizes and coefficients (its arrays are the primal ones)
    p.adjoint = [&](auto in, auto adj, auto seed) {
      const Heat1D self(n, 0.7, in[0], nullptr);
      Heat1D_step_adjoint(self, 0.4, adj[0], mut(seed[0]));
    };
#if CORPUS_TANGENT
    // tangent (assumed by analogy): self, the method's parameters, then one
    // direction per annotated member in declaration order (inputs: direction,
    // outputs: where J v goes); the primal outputs go where self points
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      const Heat1D self(n, 0.7, in[0], out[0]);
      Heat1D_step_tangent(self, 0.4, mut(d[0]), dout[0]);
    };
#endif
    check_adjoint(p);
  }
}
