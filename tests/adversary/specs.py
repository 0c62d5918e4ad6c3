N = "n"
def io(*a): return list(a)
SPECS = []
def K(**kw): SPECS.append(kw)

K(name="a01_readback_restore", why="store, read back, store again (unconditional) in one iteration",
  src="""
DPGEN_KERNEL void a01_readback_restore(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                       DPGEN_OUT double* u, int n) {
  for (int i = 0; i < n; ++i) {
    u[i] = a[i] * a[i];
    u[i] = u[i] * b[i] + u[i];
  }
}""", params=[("in","a",N),("in","b",N),("out","u",N),("val","n")])

K(name="a02_cond_restore", why="conditional second store reading the first value; condition on output",
  src="""
DPGEN_KERNEL void a02_cond_restore(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                   DPGEN_OUT double* u, int n) {
  for (int i = 0; i < n; ++i) {
    u[i] = a[i] * b[i];
    if (u[i] > 0) u[i] = u[i] * u[i] + b[i];
  }
}""", params=[("in","a",N),("in","b",N),("out","u",N),("val","n")])

K(name="a03_assign_then_accum", why="= in one nest, += / -= into the same output in a later nest (flux accumulation on top of a source)",
  src="""
DPGEN_KERNEL void a03_assign_then_accum(DPGEN_IN const double* a, DPGEN_IN const double* s,
                                        DPGEN_OUT double* r, int n) {
  for (int i = 0; i < n; ++i) r[i] = s[i] * s[i];
  for (int i = 0; i + 1 < n; ++i) {
    double f = a[i + 1] * a[i];
    r[i] += f;
    r[i + 1] -= f;
  }
}""", params=[("in","a",N),("in","s",N),("out","r",N),("val","n")])

K(name="a04_assign_accum_same_nest", why="= then += into the same element in one iteration, plus a loss reduction",
  src="""
DPGEN_KERNEL void a04_assign_accum_same_nest(DPGEN_IN const double* a, DPGEN_OUT double* u,
                                             DPGEN_OUT double* loss, int n) {
  for (int i = 0; i < n; ++i) {
    u[i] = a[i];
    u[i] += a[i] * a[i];
    loss[0] += a[i] * a[i] * a[i];
  }
}""", params=[("in","a",N),("out","u",N),("out","loss","1"),("val","n")])

K(name="a05_outer_zero_accum", why="for j { out[j]=0; for i out[j] += } and out[j] = x then +=",
  src="""
DPGEN_KERNEL void a05_outer_zero_accum(DPGEN_IN const double* a, DPGEN_OUT double* o,
                                       DPGEN_OUT double* q, int n, int m) {
  for (int j = 0; j < n; ++j) {
    o[j] = 0;
    q[j] = a[j * m] * 3.0;
    for (int i = 0; i < m; ++i) {
      o[j] += a[j * m + i] * a[j * m + i];
      q[j] -= a[j * m + i];
    }
  }
}""", params=[("in","a","n*m"),("out","o",N),("out","q",N),("val","n"),("val","m")],
  loop="for (int n : {1, 2, 3, 5}) for (int m : {1, 2, 4})")

K(name="a06_outer_shift_accum", reject=True, why="for j { out[j]=0; for i out[j+1] += } must be rejected",
  src="""
DPGEN_KERNEL void a06_outer_shift_accum(DPGEN_IN const double* a, DPGEN_OUT double* o, int n, int m) {
  for (int j = 0; j < n; ++j) {
    o[j] = 0;
    for (int i = 0; i < m; ++i) o[j + 1] += a[j * m + i];
  }
}""", params=[])

K(name="a07_straight_k", why="straight-line stores u[0], u[n-1], u[k] after a loop; k may coincide",
  src="""
DPGEN_KERNEL void a07_straight_k(DPGEN_IN const double* a, DPGEN_OUT double* u, int n, int k) {
  for (int i = 0; i < n; ++i) u[i] = a[i] * a[i];
  u[0] = 2.0 * a[0];
  u[n - 1] = 3.0 * a[n - 1] * a[0];
  u[k] = a[k] * a[0];
}""", params=[("in","a",N),("out","u",N),("val","n"),("val","k")],
  loop="for (int n : {1, 2, 3, 5}) for (int k = 0; k < n; ++k)")

K(name="a08_straight_k_before", why="u[k] before the loop, loop overwrites interior; k coincides",
  src="""
DPGEN_KERNEL void a08_straight_k_before(DPGEN_IN const double* a, DPGEN_OUT double* u, int n, int k) {
  u[k] = 5.0 * a[0] * a[0];
  for (int i = 1; i < n - 1; ++i) u[i] = a[i] - a[i - 1];
  u[n - 1] = a[k] * a[n - 1];
}""", params=[("in","a",N),("out","u",N),("val","n"),("val","k")],
  loop="for (int n : {1, 2, 3, 5}) for (int k = 0; k < n; ++k)")

K(name="a09_flux_update", why="work array: fluxes then update",
  src="""
DPGEN_KERNEL void a09_flux_update(DPGEN_IN const double* q, DPGEN_OUT double* f,
                                  DPGEN_OUT double* qn, int n) {
  for (int i = 0; i < n - 1; ++i) f[i] = 0.5 * (q[i + 1] * q[i + 1] + q[i] * q[i]);
  for (int i = 1; i < n - 1; ++i) qn[i] = q[i] - 0.3 * (f[i] - f[i - 1]) * f[i];
}""", params=[("in","q",N),("out","f",N),("out","qn",N),("val","n")])

K(name="a10_flux_read_beyond", reject=True, why="work array read beyond what was written (f[n-1] never written)",
  src="""
DPGEN_KERNEL void a10_flux_read_beyond(DPGEN_IN const double* q, DPGEN_OUT double* f,
                                       DPGEN_OUT double* qn, int n) {
  for (int i = 0; i < n - 1; ++i) f[i] = q[i + 1] * q[i];
  for (int i = 0; i < n; ++i) qn[i] = q[i] - (f[i] - 2.0 * f[i]);
}""", params=[])

K(name="a11_carried_readback", why="output written in iteration i read at i-1 in the same nest (carried)",
  src="""
DPGEN_KERNEL void a11_carried_readback(DPGEN_IN const double* a, DPGEN_OUT double* w,
                                       DPGEN_OUT double* v, int n) {
  w[0] = a[0] * a[0];
  for (int i = 1; i < n; ++i) {
    w[i] = a[i] * a[i];
    v[i] = w[i - 1] * a[i];
  }
}""", params=[("in","a",N),("out","w",N),("out","v",N),("val","n")], loop="for (int n : {1, 2, 3, 7})")

K(name="a12_overlap_iters", why="out[i] and out[i+1] both stored per iteration: iteration i+1 overwrites",
  src="""
DPGEN_KERNEL void a12_overlap_iters(DPGEN_IN const double* a, DPGEN_OUT double* u, int n) {
  for (int i = 0; i + 1 < n; ++i) {
    u[i] = a[i] * a[i];
    u[i + 1] = a[i] * 3.0;
  }
}""", params=[("in","a",N),("out","u",N),("val","n")])

K(name="a13_c89_reuse", why="C89 counter reused across nests, work array, n > i, i + 1 < n",
  src="""
DPGEN_KERNEL void a13_c89_reuse(DPGEN_IN const double* a, DPGEN_OUT double* w, DPGEN_OUT double* o, int n) {
  int i;
  for (i = 0; n > i; i++) w[i] = a[i] * a[i];
  for (i = 1; i + 1 < n; i++) o[i] = w[i - 1] + w[i + 1] - 2.0 * w[i];
}""", params=[("in","a",N),("out","w",N),("out","o",N),("val","n")])

K(name="a14_unsigned", why="size_t and unsigned counters, n > i",
  src="""
#include <cstddef>
DPGEN_KERNEL void a14_unsigned(DPGEN_IN const double* a, DPGEN_OUT double* o, DPGEN_OUT double* p, std::size_t n) {
  for (std::size_t i = 1; i + 1 < n; ++i) o[i] = a[i + 1] * a[i - 1];
  for (unsigned i = 0; n > i; i++) p[i] = a[i] * a[i];
}""", params=[("in","a",N),("out","o",N),("out","p",N),("val","size_t(n)")])

K(name="a15_stride_param", why="strided i += 3 from parameter start s, and i += 2",
  src="""
DPGEN_KERNEL void a15_stride_param(DPGEN_IN const double* a, DPGEN_OUT double* o, DPGEN_OUT double* c, int n, int s) {
  for (int i = s; i < n; i += 3) o[i] = a[i] * a[i] + a[i - s];
  for (int i = 0; i + 1 < n; i += 2) c[i / 2] = a[i] * a[i + 1];
}""", params=[("in","a",N),("out","o",N),("out","c",N),("val","n"),("val","s")],
  loop="for (int n : {0, 1, 2, 3, 4, 7, 10}) for (int s = 0; s < 4; ++s)")

K(name="a16_countdown", why="loops counting down, > and >=",
  src="""
DPGEN_KERNEL void a16_countdown(DPGEN_IN const double* a, DPGEN_OUT double* o, DPGEN_OUT double* p, int n) {
  for (int i = n - 1; i > 0; --i) o[i] = a[i] * a[i - 1];
  for (int i = n - 2; i >= 0; i--) { p[i] = a[i + 1] * a[i]; p[i] = p[i] * a[i + 1]; }
}""", params=[("in","a",N),("out","o",N),("out","p",N),("val","n")])

K(name="a17_temp_onebranch", reject=True, why="function-scope temp assigned in one branch only, then read",
  src="""
DPGEN_KERNEL void a17_temp_onebranch(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  double t;
  for (int i = 0; i < n; ++i) {
    if (a[i] > 0) t = a[i];
    o[i] = t * t;
  }
}""", params=[])

K(name="a18_temp_readfirst", reject=True, why="function-scope temp read before it is assigned in the iteration",
  src="""
DPGEN_KERNEL void a18_temp_readfirst(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  double t = 0;
  for (int i = 0; i < n; ++i) {
    o[i] = t * a[i];
    t = a[i];
  }
}""", params=[])

K(name="a19_temp_ok", why="function-scope temps assigned before use, both branches, and reassigned",
  src="""
DPGEN_KERNEL void a19_temp_ok(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  double t, s;
  for (int i = 0; i < n; ++i) {
    if (a[i] > 0) t = a[i] * a[i]; else t = -a[i];
    s = t * 2.0;
    s = s * t;
    o[i] = s + t;
  }
}""", params=[("in","a",N),("out","o",N),("val","n")])

K(name="a20_half_minmax", why="int local half = n/2 in bounds/indices, std::min/max clamped reads",
  src="""
#include <algorithm>
DPGEN_KERNEL void a20_half_minmax(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  int half = n / 2;
  for (int i = 0; i < half; ++i) o[i] = a[2 * i] * a[std::min(2 * i + 1, n - 1)];
  for (int i = half; i < n; ++i) o[i] = a[std::max(i - 3, 0)] * a[i];
}""", params=[("in","a",N),("out","o",N),("val","n")])

K(name="a21_store_max_index", reject=True, why="store at std::max(i-1,0): element 0 written twice",
  src="""
#include <algorithm>
DPGEN_KERNEL void a21_store_max_index(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  for (int i = 0; i < n; ++i) o[std::max(i - 1, 0)] = a[i] * a[i];
}""", params=[])

K(name="a22_rows_fixed", why="double (*a)[8] and double o[][8], n <= 8 correct; n > 8 must throw",
  src="""
DPGEN_KERNEL void a22_rows_fixed(DPGEN_IN const double (*a)[8], DPGEN_OUT double o[][8], int n) {
  for (int j = 1; j < n - 1; ++j)
    for (int i = 1; i < n - 1; ++i)
      o[j][i] = a[j][i] * (a[j - 1][i] + a[j + 1][i] + a[j][i - 1] + a[j][i + 1]);
}""", params=[("in","a","8*n","double(*)[8]"),("out","o","8*n","double(*)[8]"),("val","n")],
  loop="for (int n : {0, 1, 2, 3, 5, 8})",
  extra="""{
  std::vector<double> a(8 * 12, 1.0), aa(8 * 12, 0.0), s(8 * 12, 1.0);
  CHECK_THROWS_AS(a22_rows_fixed_adjoint((const double(*)[8])a.data(), (double(*)[8])aa.data(), (const double(*)[8])s.data(), 11), std::invalid_argument);
}""")

K(name="a23_ld_param", why="leading dimension ld separate from nx: correct when ld >= nx, must throw when ld < nx",
  src="""
DPGEN_KERNEL void a23_ld_param(DPGEN_IN const double* a, DPGEN_OUT double* o, int nx, int ny, int ld) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      o[j * ld + i] = a[j * ld + i] * a[j * ld + i];
}""", params=[("in","a","ld*ny+nx"),("out","o","ld*ny+nx"),("val","nx"),("val","ny"),("val","ld")],
  loop="for (int nx : {1, 2, 4}) for (int ny : {1, 2, 3}) for (int ld : {nx, nx + 1})", pre="int n = nx;",
  extra="""{
  std::vector<double> a(64, 1.0), aa(64, 0.0), s(64, 1.0);
  CHECK_THROWS_AS(a23_ld_param_adjoint(a.data(), aa.data(), s.data(), 4, 3, 3), std::invalid_argument);
}""")

K(name="a24_helpers", why="helpers: multiple returns, nested ifs, helper calling helper, array parameter",
  src="""
#include <cmath>
static inline double sq(double x) { return x * x; }
static inline double lim(double l, double r) {
  if (l * r <= 0) return 0.0;
  if (std::fabs(l) < std::fabs(r)) {
    if (l > 0) return sq(l);
    return -sq(l);
  }
  return r;
}
static double diff(const double* p, int i) { return p[i + 1] - p[i]; }
DPGEN_KERNEL void a24_helpers(DPGEN_IN const double* q, DPGEN_OUT double* o, int n) {
  for (int i = 1; i < n - 1; ++i) o[i] = q[i] + 0.5 * lim(diff(q, i - 1), diff(q, i)) * q[i];
}""", params=[("in","q",N),("out","o",N),("val","n")])

K(name="a25_local_arrays", why="small local arrays, unrolled constant loops, line buffer",
  src="""
DPGEN_KERNEL void a25_local_arrays(DPGEN_IN const double* u, DPGEN_OUT double* o, int n) {
  const double w[3] = {0.25, 0.5, 0.25};
  for (int i = 2; i < n - 2; ++i) {
    double v[5];
    for (int m = 0; m < 5; ++m) v[m] = u[i - 2 + m] * u[i - 2 + m];
    double s = 0;
    for (int m = 0; m < 3; ++m) s += w[m] * v[m + 1];
    v[2] = s * v[0];
    o[i] = v[2] + v[4] - v[2] * v[3];
  }
}""", params=[("in","u",N),("out","o",N),("val","n")])

K(name="a26_index_branch_periodic", why="index branches with continue, periodic wraps (read), periodic-wrapped store",
  src="""
DPGEN_KERNEL void a26_index_branch_periodic(DPGEN_IN const double* u, DPGEN_OUT double* o, DPGEN_OUT double* p, int n) {
  for (int i = 0; i < n; ++i) {
    if (i == 0 || i == n - 1) { o[i] = u[i] * u[i]; continue; }
    o[i] = u[i - 1] * u[i + 1];
  }
  for (int i = 0; i < n; ++i) {
    int ip = i == n - 1 ? 0 : i + 1;
    int im = i == 0 ? n - 1 : i - 1;
    p[ip] = u[im] * u[i] + u[ip];
  }
}""", params=[("in","u",N),("out","o",N),("out","p",N),("val","n")])

K(name="a27_work2d_multi", why="2D, two work arrays fx, fy then update reading both",
  src="""
DPGEN_KERNEL void a27_work2d_multi(DPGEN_IN const double* q, DPGEN_OUT double* fx, DPGEN_OUT double* fy,
                                   DPGEN_OUT double* qn, int nx, int ny) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx - 1; ++i) fx[j * nx + i] = q[j * nx + i + 1] * q[j * nx + i];
  for (int j = 0; j < ny - 1; ++j)
    for (int i = 0; i < nx; ++i) fy[j * nx + i] = q[(j + 1) * nx + i] - q[j * nx + i] * q[j * nx + i];
  for (int j = 1; j < ny - 1; ++j)
    for (int i = 1; i < nx - 1; ++i)
      qn[j * nx + i] = q[j * nx + i] - (fx[j * nx + i] - fx[j * nx + i - 1]) * (fy[j * nx + i] - fy[(j - 1) * nx + i]);
}""", params=[("in","q","nx*ny"),("out","fx","nx*ny"),("out","fy","nx*ny"),("out","qn","nx*ny"),("val","nx"),("val","ny")],
  loop="for (int nx : {1, 2, 3, 5}) for (int ny : {1, 2, 3, 4})", pre="int n = nx * ny;")

K(name="a28_3d_float", T="float", why="float 3D 7-point stencil, int flat index local",
  src="""
DPGEN_KERNEL void a28_3d_float(DPGEN_IN const float* u, DPGEN_OUT float* o, int nx, int ny, int nz) {
  for (int z = 1; z < nz - 1; ++z)
    for (int y = 1; y < ny - 1; ++y)
      for (int x = 1; x < nx - 1; ++x) {
        const int c = (z * ny + y) * nx + x;
        o[c] = u[c] * (u[c - 1] + u[c + 1] + u[c - nx] + u[c + nx] + u[c - nx * ny] + u[c + nx * ny] - 6.0f * u[c]);
      }
}""", params=[("in","u","nx*ny*nz"),("out","o","nx*ny*nz"),("val","nx"),("val","ny"),("val","nz")],
  loop="for (int nx : {1, 3, 4}) for (int ny : {2, 3}) for (int nz : {3, 5})", pre="int n = nx;")

K(name="a29_ptr_scalars", why="scalars by pointer (int lo/hi, double dt)",
  src="""
DPGEN_KERNEL void a29_ptr_scalars(DPGEN_IN const double* u, DPGEN_OUT double* o, const int* xmin, const int* xmax, const double* dt) {
  int x_min = *xmin, x_max = *xmax;
  for (int i = x_min; i <= x_max; ++i) o[i] = u[i] - *dt * (u[i + 1] * u[i + 1] - u[i - 1]);
}""", params=[("in","u","n+2"),("out","o","n+2"),("val","&lo"),("val","&hi"),("val","&dt")],
  pre="int lo = 1, hi = n; double dt = 0.3;")

K(name="a30_vector", why="std::vector<double>& with u.size()", handtest=True,
  src="""
#include <vector>
DPGEN_KERNEL void a30_vector(DPGEN_IN const std::vector<double>& u, DPGEN_OUT std::vector<double>& o) {
  for (std::size_t i = 1; i + 1 < u.size(); ++i) o[i] = u[i - 1] * u[i + 1];
}""", params=[])

K(name="a31_mixed_nests_last_wins", why="sequential nests: += then = (= wins), = on all then = on interior",
  src="""
DPGEN_KERNEL void a31_mixed_nests_last_wins(DPGEN_IN const double* a, DPGEN_OUT double* r, DPGEN_OUT double* u, int n) {
  for (int i = 0; i < n; ++i) r[i] += a[i] * a[i];
  for (int i = 0; i < n; ++i) r[i] = a[i] * 2.0;
  for (int i = 0; i < n; ++i) u[i] = a[i] * a[i];
  for (int i = 1; i < n - 1; ++i) u[i] = a[i] * 7.0;
}""", params=[("in","a",N),("out","r",N),("out","u",N),("val","n")])

K(name="a32_accum_twice_nests", why="+= into r in two nests (both contributions count), -= reduction into loss",
  src="""
DPGEN_KERNEL void a32_accum_twice_nests(DPGEN_IN const double* a, DPGEN_OUT double* r, DPGEN_OUT double* loss, int n) {
  for (int i = 0; i < n; ++i) r[i] += a[i] * a[i];
  for (int i = 0; i < n; ++i) r[i] += 3.0 * a[i];
  for (int i = 0; i < n; ++i) loss[0] -= a[i] * r[i];
}""", params=[("in","a",N),("out","r",N),("out","loss","1"),("val","n")])

K(name="a33_cond_store_index", why="conditional second store under an index branch; store at n-1-i",
  src="""
DPGEN_KERNEL void a33_cond_store_index(DPGEN_IN const double* a, DPGEN_OUT double* u, DPGEN_OUT double* v, int n) {
  for (int i = 0; i < n; ++i) {
    u[i] = a[i];
    if (i > 0) u[i] = a[i - 1] * u[i];
    v[n - 1 - i] = a[i] * a[i];
  }
}""", params=[("in","a",N),("out","u",N),("out","v",N),("val","n")])

K(name="a34_readback_before_store", reject=True, why="output read before any store in the kernel (caller contents)",
  src="""
DPGEN_KERNEL void a34_readback_before_store(DPGEN_IN const double* a, DPGEN_OUT double* u, int n) {
  for (int i = 0; i < n; ++i) u[i] = u[i] * a[i];
}""", params=[])

K(name="a35_work_then_accum_readback", why="work array stored, then += into it in a later nest, then read in a third nest",
  src="""
DPGEN_KERNEL void a35_work_then_accum_readback(DPGEN_IN const double* a, DPGEN_OUT double* w, DPGEN_OUT double* o, int n) {
  for (int i = 0; i < n; ++i) w[i] = a[i] * a[i];
  for (int i = 0; i + 1 < n; ++i) w[i + 1] += a[i];
  for (int i = 0; i < n; ++i) o[i] = w[i] * w[i];
}""", params=[("in","a",N),("out","w",N),("out","o",N),("val","n")])

K(name="a36_cond_store_idx_min", why="minimal a33: second store under if (i > 0) reading the first",
  src="""
DPGEN_KERNEL void a36_cond_store_idx_min(DPGEN_IN const double* a, DPGEN_OUT double* u, int n) {
  for (int i = 0; i < n; ++i) {
    u[i] = a[i];
    if (i > 0) u[i] = a[i - 1] * u[i];
  }
}""", params=[("in","a",N),("out","u",N),("val","n")])

K(name="a37_reversed_store", why="minimal a33: store at n-1-i",
  src="""
DPGEN_KERNEL void a37_reversed_store(DPGEN_IN const double* a, DPGEN_OUT double* v, int n) {
  for (int i = 0; i < n; ++i) v[n - 1 - i] = a[i] * a[i];
}""", params=[("in","a",N),("out","v",N),("val","n")])

K(name="a38_accum_only_work", why="work array written only with += then read by a later nest",
  src="""
DPGEN_KERNEL void a38_accum_only_work(DPGEN_IN const double* a, DPGEN_OUT double* r, DPGEN_OUT double* o, int n) {
  for (int i = 0; i < n; ++i) r[i] += a[i] * a[i];
  for (int i = 0; i < n; ++i) o[i] = r[i] * a[i];
}""", params=[("in","a",N),("out","r",N),("out","o",N),("val","n")])

K(name="a39_read_beyond_nonlin", why="work array read beyond what was written, nonlinearly (f[n-1] never written)",
  src="""
DPGEN_KERNEL void a39_read_beyond_nonlin(DPGEN_IN const double* q, DPGEN_OUT double* f, DPGEN_OUT double* qn, int n) {
  for (int i = 0; i < n - 1; ++i) f[i] = q[i + 1] * q[i];
  for (int i = 0; i < n; ++i) qn[i] = q[i] * f[i];
}""", params=[("in","q",N),("out","f",N),("out","qn",N),("val","n")])

K(name="a40_helper_lim_only", why="a24 split: nested-if helper with several returns only",
  src="""
#include <cmath>
static inline double sq(double x) { return x * x; }
static inline double lim(double l, double r) {
  if (l * r <= 0) return 0.0;
  if (std::fabs(l) < std::fabs(r)) {
    if (l > 0) return sq(l);
    return -sq(l);
  }
  return r;
}
DPGEN_KERNEL void a40_helper_lim_only(DPGEN_IN const double* q, DPGEN_OUT double* o, int n) {
  for (int i = 1; i < n - 1; ++i) o[i] = q[i] + lim(q[i] - q[i - 1], q[i + 1] - q[i]) * q[i];
}""", params=[("in","q",N),("out","o",N),("val","n")])

K(name="a41_helper_arrayparam", why="a24 split: helper with array parameter only",
  src="""
static double diff(const double* p, int i) { return p[i + 1] - p[i]; }
DPGEN_KERNEL void a41_helper_arrayparam(DPGEN_IN const double* q, DPGEN_OUT double* o, int n) {
  for (int i = 1; i < n - 1; ++i) o[i] = q[i] * diff(q, i - 1) * diff(q, i);
}""", params=[("in","q",N),("out","o",N),("val","n")])

K(name="a42_null_adj", why="null adjoint for one input leaves the other's adjoint identical", handtest=True,
  src="""
DPGEN_KERNEL void a42_null_adj(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* w, DPGEN_OUT double* o, int n) {
  for (int i = 0; i < n; ++i) w[i] = a[i] * b[i];
  for (int i = 1; i < n - 1; ++i) o[i] = w[i - 1] * b[i + 1] + a[i] * w[i + 1];
}""", params=[])
