#include "corpus_check.hpp"

#include "functor_smooth_run.cpp"
#include "functor_smooth_run_adjoint.hpp"
#if CORPUS_TANGENT
#include "functor_smooth_run_tangent.hpp"
#endif

using namespace corpus;
using V1 = Kokkos::View<double*>;

TEST_CASE("modern: Smooth1D::run") {
  for (int n : {1, 2, 3, 14}) {
    auto v = [&](const double* q) { return V1(mut(q), n); };
    Problem<double> p;
    p.in_sizes = {size_t(n), size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { Smooth1D{v(in[0]), v(in[1]), v(out[0])}.run(); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      const Smooth1D self{v(in[0]), v(in[1]), V1()};
      V1 u_adj = v(adj[0]), w_adj = v(adj[1]), out_adj = v(seed[0]);
      Smooth1D_run_adjoint(self, u_adj, w_adj, out_adj);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      const Smooth1D self{v(in[0]), v(in[1]), v(out[0])};
      V1 u_dot = v(d[0]), w_dot = v(d[1]), out_dot = v(dout[0]);
      Smooth1D_run_tangent(self, u_dot, w_dot, out_dot);
    };
#endif
    check_adjoint(p);
  }
}
