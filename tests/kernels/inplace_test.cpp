// inplace (tests/kernels/): DPGEN_INOUT arrays. The adjoint takes u_adj as the
// seed of the new u and returns in it the adjoint of the old u; the tangent
// updates u and u_dot in place. Checked with the dot-product test against
// central differences of the in-place forward (on copies), the tangent
// against the same differences and against the adjoint, and the pass-through
// of elements the kernel does not write.
#include <doctest/doctest.h>

#include "inplace_adjoint.hpp"
#include "inplace_kernels.hpp"
#include "inplace_tangent.hpp"
#include "test_kernels.hpp"

#include <cmath>
#include <functional>
#include <random>
#include <vector>

namespace {
using Vec = std::vector<double>;
using Forward = std::function<void(Vec& u, const Vec& a)>;
using Adjoint = std::function<void(const Vec& u, Vec& u_adj, const Vec& a, Vec& a_adj)>;
using Tangent = std::function<void(Vec& u, Vec& u_dot, const Vec& a, const Vec& a_dot)>;

Vec random(size_t n, std::mt19937_64& rng, double lo = 0.1, double hi = 0.9) {
  Vec v(n);
  for (auto& x : v)
    x = std::uniform_real_distribution<double>(lo, hi)(rng);
  return v;
}

double dot(const Vec& a, const Vec& b) {
  double s = 0;
  for (size_t i = 0; i < a.size(); ++i)
    s += a[i] * b[i];
  return s;
}

void check_inplace(size_t n, const Forward& f, const Adjoint& adj, const Tangent& tan) {
  std::mt19937_64 rng(20261122);
  Vec u = random(n, rng), a = random(n, rng), du = random(n, rng, -1, 1),
      da = random(n, rng, -1, 1), w = random(n, rng, -1, 1);
  // J (du, da) by central differences of the in-place forward on copies.
  const double h = 1e-6;
  Vec up = u, um = u, ap = a, am = a;
  for (size_t i = 0; i < n; ++i) {
    up[i] += h * du[i], um[i] -= h * du[i];
    ap[i] += h * da[i], am[i] -= h * da[i];
  }
  f(up, ap);
  f(um, am);
  Vec jv(n);
  for (size_t i = 0; i < n; ++i)
    jv[i] = (up[i] - um[i]) / (2 * h);
  // Adjoint: seed w in u_adj; on return u_adj is the adjoint of the old u.
  Vec u_adj = w, a_adj(n, 0.0);
  adj(u, u_adj, a, a_adj);
  double lhs = dot(w, jv), rhs = dot(du, u_adj) + dot(da, a_adj);
  INFO("<w, J v> = " << lhs << ", <v, J^T w> = " << rhs);
  CHECK(std::fabs(lhs - rhs) <= 1e-7 * std::max(1.0, std::fabs(lhs)));
  // Tangent: u, u_dot updated in place; u as the forward leaves it.
  Vec ut = u, ut_dot = du, uf = u;
  tan(ut, ut_dot, a, da);
  f(uf, a);
  for (size_t i = 0; i < n; ++i) {
    CHECK(ut[i] == doctest::Approx(uf[i]).epsilon(1e-14));
    CHECK(ut_dot[i] == doctest::Approx(jv[i]).epsilon(1e-6));
  }
  // <w, J v> from the tangent equals the adjoint's <v, J^T w> to rounding.
  CHECK(std::fabs(dot(w, ut_dot) - rhs) <= 1e-12 * std::max(1.0, std::fabs(rhs)));
}
} // namespace

TEST_CASE("react_inplace: adjoint and tangent of an in-place interior update") {
  for (size_t n : {1u, 2u, 3u, 9u}) {
    CAPTURE(n);
    const int ni = int(n);
    check_inplace(
        n, [&](Vec& u, const Vec& r) { react_inplace(u.data(), r.data(), ni, 0.7); },
        [&](const Vec& u, Vec& ua, const Vec& r, Vec& ra) {
          react_inplace_adjoint(u.data(), ua.data(), r.data(), ra.data(), ni, 0.7);
        },
        [&](Vec& u, Vec& ud, const Vec& r, const Vec& rd) {
          react_inplace_tangent(u.data(), ud.data(), r.data(), rd.data(), ni, 0.7);
        });
  }
  // The end elements are not written: their seed passes through unchanged.
  Vec u = {0.2, 0.3, 0.4, 0.6}, r = {1, 1, 1, 1}, ua = {5, 0, 0, 7}, ra(4, 0.0);
  react_inplace_adjoint(u.data(), ua.data(), r.data(), ra.data(), 4, 0.1);
  CHECK(ua[0] == 5.0);
  CHECK(ua[3] == 7.0);
}

TEST_CASE("relax_inplace: adjoint and tangent of an in-place update of every element") {
  for (size_t n : {0u, 1u, 5u}) {
    CAPTURE(n);
    const int ni = int(n);
    check_inplace(
        n, [&](Vec& u, const Vec& t) { relax_inplace(u.data(), t.data(), ni, 0.3); },
        [&](const Vec& u, Vec& ua, const Vec& t, Vec& ta) {
          relax_inplace_adjoint(u.data(), ua.data(), t.data(), ta.data(), ni, 0.3);
        },
        [&](Vec& u, Vec& ud, const Vec& t, const Vec& td) {
          relax_inplace_tangent(u.data(), ud.data(), t.data(), td.data(), ni, 0.3);
        });
  }
}

TEST_CASE("advect_fluxes_inplace: fluxes from the old values, then the update in place") {
  for (size_t n : {2u, 3u, 8u}) {
    CAPTURE(n);
    const int ni = int(n);
    check_inplace(
        n,
        [&](Vec& rho, const Vec& u) {
          Vec flux(n + 1, 0.0);
          advect_fluxes_inplace(rho.data(), u.data(), flux.data(), ni, 0.3);
        },
        [&](const Vec& rho, Vec& rho_adj, const Vec& u, Vec& u_adj) {
          Vec flux_adj(n + 1, 0.0); // (the fluxes' own seed: zero)
          advect_fluxes_inplace_adjoint(rho.data(), rho_adj.data(), u.data(), u_adj.data(),
                                        flux_adj.data(), ni, 0.3);
        },
        [&](Vec& rho, Vec& rho_dot, const Vec& u, const Vec& u_dot) {
          Vec flux(n + 1, 0.0), flux_dot(n + 1, 0.0);
          advect_fluxes_inplace_tangent(rho.data(), rho_dot.data(), u.data(), u_dot.data(),
                                        flux.data(), flux_dot.data(), ni, 0.3);
        });
  }
  // The adjoint reads the old values: the caller's rho is left as it was.
  Vec rho = {0.2, 0.3, 0.4, 0.6}, u = {0.9, 0.9, 0.1, 0.9}, ra = {1, 1, 1, 1}, ua(4, 0.0),
      fa(5, 0.0);
  const Vec before = rho;
  advect_fluxes_inplace_adjoint(rho.data(), ra.data(), u.data(), ua.data(), fa.data(), 4, 0.3);
  CHECK(rho == before);
}

TEST_CASE("normalize_inplace: an accumulator of the old values, then a rescale in place") {
  for (size_t n : {1u, 4u, 11u}) {
    CAPTURE(n);
    const int ni = int(n);
    check_inplace(
        n, [&](Vec& v, const Vec& w) { normalize_inplace(v.data(), w.data(), ni); },
        [&](const Vec& v, Vec& va, const Vec& w, Vec& wa) {
          normalize_inplace_adjoint(v.data(), va.data(), w.data(), wa.data(), ni);
        },
        [&](Vec& v, Vec& vd, const Vec& w, const Vec& wd) {
          normalize_inplace_tangent(v.data(), vd.data(), w.data(), wd.data(), ni);
        });
  }
}

TEST_CASE("branch_inplace: the else arm tests the old value") {
  for (size_t n : {1u, 2u, 7u}) {
    CAPTURE(n);
    const int ni = int(n);
    check_inplace(
        n, [&](Vec& u, const Vec& f) { branch_inplace(u.data(), f.data(), ni); },
        [&](const Vec& u, Vec& ua, const Vec& f, Vec& fa) {
          branch_inplace_adjoint(u.data(), ua.data(), f.data(), fa.data(), ni);
        },
        [&](Vec& u, Vec& ud, const Vec& f, const Vec& fd) {
          branch_inplace_tangent(u.data(), ud.data(), f.data(), fd.data(), ni);
        });
  }
  // u = 0.8 takes the first arm only: 0.8 * 0.5 * 1 = 0.4 (both arms: 0.6).
  Vec u = {0.8}, ud = {1.0}, f = {1.0}, fd = {0.0};
  branch_inplace_tangent(u.data(), ud.data(), f.data(), fd.data(), 1);
  CHECK(u[0] == 0.4);
  CHECK(ud[0] == 0.5);
}

TEST_CASE("coupled_inplace: two arrays in place, the second from the first's new value") {
  for (size_t n : {1u, 3u, 8u}) {
    CAPTURE(n);
    const int ni = int(n);
    std::mt19937_64 rng(20261130);
    Vec u = random(n, rng), v = random(n, rng), f = random(n, rng), du = random(n, rng, -1, 1),
        dv = random(n, rng, -1, 1), df = random(n, rng, -1, 1), wu = random(n, rng, -1, 1),
        wv = random(n, rng, -1, 1);
    // J (du, dv, df) by central differences of the in-place forward on copies.
    const double h = 1e-6;
    Vec up = u, um = u, vp = v, vm = v, fp = f, fm = f;
    for (size_t i = 0; i < n; ++i) {
      up[i] += h * du[i], um[i] -= h * du[i];
      vp[i] += h * dv[i], vm[i] -= h * dv[i];
      fp[i] += h * df[i], fm[i] -= h * df[i];
    }
    coupled_inplace(up.data(), vp.data(), fp.data(), ni);
    coupled_inplace(um.data(), vm.data(), fm.data(), ni);
    // Tangent: the new values as the forward leaves them, their tangents as the differences.
    Vec ut = u, vt = v, ut_dot = du, vt_dot = dv, uf = u, vf = v;
    coupled_inplace_tangent(ut.data(), ut_dot.data(), vt.data(), vt_dot.data(), f.data(), df.data(),
                            ni);
    coupled_inplace(uf.data(), vf.data(), f.data(), ni);
    for (size_t i = 0; i < n; ++i) {
      CAPTURE(i);
      CHECK(ut[i] == doctest::Approx(uf[i]).epsilon(1e-14));
      CHECK(vt[i] == doctest::Approx(vf[i]).epsilon(1e-14));
      CHECK(ut_dot[i] == doctest::Approx((up[i] - um[i]) / (2 * h)).epsilon(1e-6));
      CHECK(vt_dot[i] == doctest::Approx((vp[i] - vm[i]) / (2 * h)).epsilon(1e-6));
    }
    // The adjoint (seeds wu, wv of the new values) against the tangent: the dot-product test.
    Vec ua = wu, va = wv, fa(n, 0.0);
    coupled_inplace_adjoint(u.data(), ua.data(), v.data(), va.data(), f.data(), fa.data(), ni);
    const double lhs = dot(wu, ut_dot) + dot(wv, vt_dot),
                 rhs = dot(du, ua) + dot(dv, va) + dot(df, fa);
    CHECK(std::fabs(lhs - rhs) <= 1e-12 * std::max(1.0, std::fabs(rhs)));
  }
}
