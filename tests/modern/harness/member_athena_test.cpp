#include "corpus_check.hpp"

#include "member_athena.cpp"
#include "member_athena_adjoint.hpp"
#if CORPUS_TANGENT
#include "member_athena_tangent.hpp"
#endif

using namespace corpus;

TEST_CASE("modern: HydroDiffusion::ViscousFluxX1") {
  const int nv = 3, nx1 = 8, nx2 = 3, nx3 = 2, k = 1, j = 2;
  for (auto [il, iu] : {std::pair{1, 1}, {2, 7}, {1, 7}}) {
    Problem<double> p;
    p.in_sizes = {size_t(nv * nx3 * nx2 * nx1), size_t(nx3 * nx2 * nx1)};
    p.in_ranges = {{0.5, 1.5}, {0.1, 1.0}};
    p.out_sizes = {size_t(nv * nx1)};
    p.forward = [&](auto in, auto out) {
      HydroDiffusion hd;
      hd.nu_iso = AthenaArray<Real>(mut(in[1]), nx3, nx2, nx1);
      hd.dx1 = 0.25;
      const AthenaArray<Real> prim(mut(in[0]), nv, nx3, nx2, nx1);
      AthenaArray<Real> flx(out[0], nv, nx1);
      hd.ViscousFluxX1(prim, flx, k, j, il, iu);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      HydroDiffusion self;
      self.nu_iso = AthenaArray<Real>(mut(in[1]), nx3, nx2, nx1);
      self.dx1 = 0.25;
      const AthenaArray<Real> prim(mut(in[0]), nv, nx3, nx2, nx1);
      AthenaArray<Real> prim_adj(adj[0], nv, nx3, nx2, nx1), nu_iso_adj(adj[1], nx3, nx2, nx1);
      AthenaArray<Real> flx_adj(mut(seed[0]), nv, nx1);
      HydroDiffusion_ViscousFluxX1_adjoint(self, prim, prim_adj, flx_adj, k, j, il, iu, nu_iso_adj);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      HydroDiffusion self;
      self.nu_iso = AthenaArray<Real>(mut(in[1]), nx3, nx2, nx1);
      self.dx1 = 0.25;
      const AthenaArray<Real> prim(mut(in[0]), nv, nx3, nx2, nx1);
      AthenaArray<Real> prim_dot(mut(d[0]), nv, nx3, nx2, nx1),
          nu_iso_dot(mut(d[1]), nx3, nx2, nx1);
      AthenaArray<Real> flx(out[0], nv, nx1), flx_dot(dout[0], nv, nx1);
      HydroDiffusion_ViscousFluxX1_tangent(self, prim, prim_dot, flx, flx_dot, k, j, il, iu,
                                           nu_iso_dot);
    };
#endif
    check_adjoint(p);
  }
}
