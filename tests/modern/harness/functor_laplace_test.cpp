#include "corpus_check.hpp"

#include "functor_laplace.cpp"
#include "functor_laplace_adjoint.hpp"
#if CORPUS_TANGENT
#include "functor_laplace_tangent.hpp"
#endif

using namespace corpus;
using V2 = Kokkos::View<double**>;

TEST_CASE("modern: laplace2d_functor") {
  for (auto [nx, ny] : {std::pair{1, 1}, {3, 3}, {6, 4}}) {
    const size_t N = size_t(nx) * size_t(ny);
    auto v = [&](const double* q) { return V2(mut(q), nx, ny); };
    Problem<double> p;
    p.in_sizes = {N};
    p.out_sizes = {N};
    p.linear = true;
    p.forward = [&](auto in, auto out) { laplace2d_functor(v(in[0]), v(out[0]), 0.5); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      laplace2d_functor_adjoint(v(in[0]), v(adj[0]), v(seed[0]), 0.5);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      laplace2d_functor_tangent(v(in[0]), v(d[0]), v(out[0]), v(dout[0]), 0.5);
    };
#endif
    check_adjoint(p);
  }
}
