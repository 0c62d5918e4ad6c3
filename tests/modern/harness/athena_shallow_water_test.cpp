#include "corpus_check.hpp"

#include "athena_shallow_water.cpp"
#include "athena_shallow_water_adjoint.hpp"
#if CORPUS_TANGENT
#include "athena_shallow_water_tangent.hpp"
#endif

using namespace corpus;

TEST_CASE("modern: RusanovSWE") {
  const int nv = 3, nx1 = 7, nx2 = 2, nx3 = 1;
  for (auto [il, iu] : {std::pair{3, 3}, {1, 6}}) {
    const int k = 0, j = 1;
    Problem<double> p;
    p.in_sizes = {size_t(nv * nx1), size_t(nv * nx1)};
    // every state in [0.2, 1.5]: h > 0 for sqrt(g h), and u, v > 0, away
    // from the kink of |u|
    p.in_ranges = {{0.2, 1.5}, {0.2, 1.5}};
    p.out_sizes = {size_t(nv * nx3 * nx2 * nx1)};
    p.forward = [&](auto in, auto out) {
      const AthenaArray<Real> wl(mut(in[0]), nv, nx1), wr(mut(in[1]), nv, nx1);
      AthenaArray<Real> flx(out[0], nv, nx3, nx2, nx1);
      RusanovSWE(k, j, il, iu, wl, wr, flx, 9.81);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      const AthenaArray<Real> wl(mut(in[0]), nv, nx1), wr(mut(in[1]), nv, nx1);
      AthenaArray<Real> wla(adj[0], nv, nx1), wra(adj[1], nv, nx1);
      AthenaArray<Real> flxa(mut(seed[0]), nv, nx3, nx2, nx1);
      RusanovSWE_adjoint(k, j, il, iu, wl, wla, wr, wra, flxa, 9.81);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      const AthenaArray<Real> wl(mut(in[0]), nv, nx1), wr(mut(in[1]), nv, nx1);
      AthenaArray<Real> wld(mut(d[0]), nv, nx1), wrd(mut(d[1]), nv, nx1);
      AthenaArray<Real> flx(out[0], nv, nx3, nx2, nx1), flxd(dout[0], nv, nx3, nx2, nx1);
      RusanovSWE_tangent(k, j, il, iu, wl, wld, wr, wrd, flx, flxd, 9.81);
    };
#endif
    check_adjoint(p);
  }
}
