#include "corpus_check.hpp"

#include "athena_flux_divergence.cpp"
#include "athena_flux_divergence_adjoint.hpp"
#if CORPUS_TANGENT
#include "athena_flux_divergence_tangent.hpp"
#endif

using namespace corpus;

TEST_CASE("modern: AddFluxDivergence") {
  // cells is..ie etc. inside a block with 1 ghost; fluxes have one more face
  for (int nh : {1, 3}) {
    const int is = 1, ie = 4, js = 1, je = 3, ks = 0, ke = 1;
    const int n1 = ie + 2, n2 = je + 2, n3 = ke + 1; // cell arrays
    const int f1 = n1 + 1, f2 = n2 + 1;              // face arrays
    Problem<double> p;
    p.in_sizes = {size_t(nh * n3 * n2 * f1), size_t(nh * n3 * f2 * n1)};
    p.out_sizes = {size_t(nh * n3 * n2 * n1)};
    p.linear = true;
    p.forward = [&](auto in, auto out) {
      const AthenaArray<Real> x1(mut(in[0]), nh, n3, n2, f1), x2(mut(in[1]), nh, n3, f2, n1);
      AthenaArray<Real> du(out[0], nh, n3, n2, n1);
      AddFluxDivergence(0.5, x1, x2, du, nh, is, ie, js, je, ks, ke, 0.1, 0.2);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      const AthenaArray<Real> x1(mut(in[0]), nh, n3, n2, f1), x2(mut(in[1]), nh, n3, f2, n1);
      AthenaArray<Real> x1a(adj[0], nh, n3, n2, f1), x2a(adj[1], nh, n3, f2, n1);
      AthenaArray<Real> dua(mut(seed[0]), nh, n3, n2, n1);
      AddFluxDivergence_adjoint(0.5, x1, x1a, x2, x2a, dua, nh, is, ie, js, je, ks, ke, 0.1, 0.2);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      const AthenaArray<Real> x1(mut(in[0]), nh, n3, n2, f1), x2(mut(in[1]), nh, n3, f2, n1);
      AthenaArray<Real> x1d(mut(d[0]), nh, n3, n2, f1), x2d(mut(d[1]), nh, n3, f2, n1);
      AthenaArray<Real> du(out[0], nh, n3, n2, n1), dud(dout[0], nh, n3, n2, n1);
      AddFluxDivergence_tangent(0.5, x1, x1d, x2, x2d, du, dud, nh, is, ie, js, je, ks, ke, 0.1,
                                0.2);
    };
#endif
    check_adjoint(p);
  }
}
