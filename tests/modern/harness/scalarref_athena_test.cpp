#include "corpus_check.hpp"

#include "scalarref_athena.cpp"
#include "scalarref_athena_adjoint.hpp"
#if CORPUS_TANGENT
#include "scalarref_athena_tangent.hpp"
#endif

using namespace corpus;

TEST_CASE("modern: update_and_total") {
  const int n2 = 4, n1 = 6;
  for (auto [is, ie, js, je] : {std::array{2, 2, 1, 1}, {1, 4, 1, 2}}) {
    const Real dt = 0.3;
    Problem<double> p;
    p.in_sizes = {size_t(n2 * n1), size_t(n2 * n1)};
    p.out_sizes = {size_t(n2 * n1), 1};
    p.forward = [&](auto in, auto out) {
      const AthenaArray<Real> u(mut(in[0]), n2, n1), dudt(mut(in[1]), n2, n1);
      AthenaArray<Real> un(out[0], n2, n1);
      update_and_total(u, dudt, un, dt, is, ie, js, je, out[1][0]);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      const AthenaArray<Real> u(mut(in[0]), n2, n1), dudt(mut(in[1]), n2, n1);
      AthenaArray<Real> ua(adj[0], n2, n1), dudta(adj[1], n2, n1), una(mut(seed[0]), n2, n1);
      update_and_total_adjoint(u, ua, dudt, dudta, una, dt, is, ie, js, je, seed[1][0]);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      const AthenaArray<Real> u(mut(in[0]), n2, n1), dudt(mut(in[1]), n2, n1);
      AthenaArray<Real> ud(mut(d[0]), n2, n1), dudtd(mut(d[1]), n2, n1);
      AthenaArray<Real> un(out[0], n2, n1), und(dout[0], n2, n1);
      update_and_total_tangent(u, ud, dudt, dudtd, un, und, dt, is, ie, js, je, out[1][0],
                               dout[1][0]);
    };
#endif
    check_adjoint(p);
  }
}
