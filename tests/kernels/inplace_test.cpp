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

// A kernel with `io` arrays updated in place, `in` inputs and `out` outputs (each of n
// elements), given as its forward, tangent and adjoint on lists of arrays.
using Arrays = std::vector<Vec>;
struct Kernel {
  size_t io = 0, in = 0, out = 0;
  std::function<void(Arrays& io, const Arrays& in, Arrays& out)> forward;
  std::function<void(Arrays& io, Arrays& io_dot, const Arrays& in, const Arrays& in_dot,
                     Arrays& out, Arrays& out_dot)>
      tangent;
  std::function<void(const Arrays& io, Arrays& io_adj, const Arrays& in, Arrays& in_adj,
                     const Arrays& out_adj)>
      adjoint;
};

double dots(const Arrays& a, const Arrays& b) {
  double s = 0;
  for (size_t k = 0; k < a.size(); ++k)
    s += dot(a[k], b[k]);
  return s;
}

// The tangent's new values and outputs against the forward's, its derivatives against
// central differences of the forward (on copies), and the adjoint against the tangent (the
// dot-product test; the adjoint takes the seeds of the new values in io_adj).
void check_kernel(size_t n, const Kernel& k) {
  std::mt19937_64 rng(20261130 + n);
  auto arrays = [&](size_t m, double lo, double hi) {
    Arrays a;
    for (size_t i = 0; i < m; ++i)
      a.push_back(random(n, rng, lo, hi));
    return a;
  };
  const Arrays io = arrays(k.io, 0.1, 0.9), in = arrays(k.in, 0.1, 0.9), dio = arrays(k.io, -1, 1),
               din = arrays(k.in, -1, 1), wio = arrays(k.io, -1, 1), wout = arrays(k.out, -1, 1);
  const double h = 1e-6;
  Arrays iop = io, iom = io, inp = in, inm = in, outp(k.out, Vec(n, 0.0)), outm = outp;
  for (size_t a = 0; a < k.io; ++a)
    for (size_t i = 0; i < n; ++i)
      iop[a][i] += h * dio[a][i], iom[a][i] -= h * dio[a][i];
  for (size_t a = 0; a < k.in; ++a)
    for (size_t i = 0; i < n; ++i)
      inp[a][i] += h * din[a][i], inm[a][i] -= h * din[a][i];
  k.forward(iop, inp, outp);
  k.forward(iom, inm, outm);
  Arrays io_t = io, io_dot = dio, out_t(k.out, Vec(n, 0.0)), out_dot = out_t, io_f = io,
         out_f = out_t;
  k.tangent(io_t, io_dot, in, din, out_t, out_dot);
  k.forward(io_f, in, out_f);
  auto same = [&](const Arrays& t, const Arrays& f, const Arrays& dot_t, const Arrays& p,
                  const Arrays& m) {
    for (size_t a = 0; a < t.size(); ++a)
      for (size_t i = 0; i < n; ++i) {
        CAPTURE(a);
        CAPTURE(i);
        CHECK(t[a][i] == doctest::Approx(f[a][i]).epsilon(1e-14));
        CHECK(dot_t[a][i] == doctest::Approx((p[a][i] - m[a][i]) / (2 * h)).epsilon(1e-6));
      }
  };
  same(io_t, io_f, io_dot, iop, iom);
  same(out_t, out_f, out_dot, outp, outm);
  Arrays io_adj = wio, in_adj(k.in, Vec(n, 0.0));
  k.adjoint(io, io_adj, in, in_adj, wout);
  const double lhs = dots(wio, io_dot) + dots(wout, out_dot),
               rhs = dots(dio, io_adj) + dots(din, in_adj);
  CHECK(std::fabs(lhs - rhs) <= 1e-12 * std::max(1.0, std::fabs(rhs)));
}

// check_kernel for a kernel f(u, v, a, n) with u and v updated in place and one input a.
using TwoInPlace = void (*)(double*, double*, const double*, int);
using TwoInPlaceTangent = void (*)(double*, double*, double*, double*, const double*, const double*,
                                   int);
using TwoInPlaceAdjoint = void (*)(const double*, double*, const double*, double*, const double*,
                                   double*, int);
void check_two_in_place(size_t n, TwoInPlace f, TwoInPlaceTangent tangent,
                        TwoInPlaceAdjoint adjoint) {
  const int ni = int(n);
  Kernel k;
  k.io = 2, k.in = 1;
  k.forward = [&](Arrays& io, const Arrays& in, Arrays&) {
    f(io[0].data(), io[1].data(), in[0].data(), ni);
  };
  k.tangent = [&](Arrays& io, Arrays& iod, const Arrays& in, const Arrays& ind, Arrays&, Arrays&) {
    tangent(io[0].data(), iod[0].data(), io[1].data(), iod[1].data(), in[0].data(), ind[0].data(),
            ni);
  };
  k.adjoint = [&](const Arrays& io, Arrays& ioa, const Arrays& in, Arrays& ina, const Arrays&) {
    adjoint(io[0].data(), ioa[0].data(), io[1].data(), ioa[1].data(), in[0].data(), ina[0].data(),
            ni);
  };
  check_kernel(n, k);
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
    check_two_in_place(n, coupled_inplace, coupled_inplace_tangent, coupled_inplace_adjoint);
  }
}

TEST_CASE("floor_then_pressure: a conditional in-place store, then a read of the element") {
  for (size_t n : {1u, 2u, 9u}) {
    CAPTURE(n);
    const int ni = int(n);
    Kernel k;
    k.io = 1, k.in = 1, k.out = 1;
    k.forward = [&](Arrays& io, const Arrays& in, Arrays& out) {
      floor_then_pressure(io[0].data(), in[0].data(), out[0].data(), ni);
    };
    k.tangent = [&](Arrays& io, Arrays& iod, const Arrays& in, const Arrays& ind, Arrays& out,
                    Arrays& outd) {
      floor_then_pressure_tangent(io[0].data(), iod[0].data(), in[0].data(), ind[0].data(),
                                  out[0].data(), outd[0].data(), ni);
    };
    k.adjoint = [&](const Arrays& io, Arrays& ioa, const Arrays& in, Arrays& ina,
                    const Arrays& outa) {
      floor_then_pressure_adjoint(io[0].data(), ioa[0].data(), in[0].data(), ina[0].data(),
                                  outa[0].data(), ni);
    };
    check_kernel(n, k);
  }
  // rho = 0.2 is floored to 0.5 + 0.1 e: p = 0.4 (0.5 + 0.1 e) e, dp/drho = 0 (the old
  // generator read the old rho after the if: p = 0.4 * 0.2 * e, dp/drho = 0.4 e).
  const double e[1] = {2.0}, p_adj[1] = {1.0};
  double rho[1] = {0.2}, p[1] = {0.0}, rho_adj[1] = {0.0}, e_adj[1] = {0.0};
  floor_then_pressure_adjoint(rho, rho_adj, e, e_adj, p_adj, 1);
  floor_then_pressure(rho, e, p, 1);
  CHECK(p[0] == doctest::Approx(0.4 * 0.7 * 2.0));
  CHECK(rho_adj[0] == 0.0);
  CHECK(e_adj[0] == doctest::Approx(0.4 * 0.1 * 2.0 + 0.4 * 0.7));
  // The tangent along rho: the floored rho does not move, nor does p.
  double rho_t[1] = {0.2}, rho_dot[1] = {1.0}, e_dot[1] = {0.0}, p_t[1] = {0.0}, p_dot[1] = {0.0};
  floor_then_pressure_tangent(rho_t, rho_dot, e, e_dot, p_t, p_dot, 1);
  CHECK(rho_t[0] == doctest::Approx(0.7));
  CHECK(p_t[0] == doctest::Approx(0.4 * 0.7 * 2.0));
  CHECK(rho_dot[0] == 0.0);
  CHECK(p_dot[0] == 0.0);
}

TEST_CASE("arms_then_update: both arms update v in place, then u reads the new v") {
  for (size_t n : {1u, 4u, 11u}) {
    CAPTURE(n);
    check_two_in_place(n, arms_then_update, arms_then_update_tangent, arms_then_update_adjoint);
  }
}

TEST_CASE("guarded_pin: a guarded straight-line in-place store touches nothing below the guard") {
  for (size_t n : {2u, 3u}) {
    CAPTURE(n);
    const int ni = int(n);
    Kernel k;
    k.io = 1, k.in = 1;
    k.forward = [&](Arrays& io, const Arrays& in, Arrays&) {
      guarded_pin(io[0].data(), in[0].data(), ni);
    };
    k.tangent = [&](Arrays& io, Arrays& iod, const Arrays& in, const Arrays& ind, Arrays&,
                    Arrays&) {
      guarded_pin_tangent(io[0].data(), iod[0].data(), in[0].data(), ind[0].data(), ni);
    };
    k.adjoint = [&](const Arrays& io, Arrays& ioa, const Arrays& in, Arrays& ina, const Arrays&) {
      guarded_pin_adjoint(io[0].data(), ioa[0].data(), in[0].data(), ina[0].data(), ni);
    };
    check_kernel(n, k);
  }
  // n = 1 on arrays of one element (heap-allocated, so that AddressSanitizer sees a read
  // or write past them): nothing changes, the seed passes through.
  std::vector<double> u(1, 0.3), u_dot(1, 1.0), f(1, 2.0), f_dot(1, 0.0), u_adj(1, 5.0),
      f_adj(1, 0.0);
  guarded_pin_tangent(u.data(), u_dot.data(), f.data(), f_dot.data(), 1);
  guarded_pin_adjoint(u.data(), u_adj.data(), f.data(), f_adj.data(), 1);
  CHECK(u[0] == 0.3);
  CHECK(u_dot[0] == 1.0);
  CHECK(u_adj[0] == 5.0);
  CHECK(f_adj[0] == 0.0);
}
