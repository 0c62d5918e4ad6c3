# Round r5 (issue 20, second half): min/max reductions, stores pinned to one
# iteration, later-writer-wins pairs, in place across nests.
# ADV_SPECS=specs_r5 python3 gen.py [names...]
# expect: "accept" (a right adjoint exists and dpgen should give it) or
# "reject" (dpgen should refuse, reason in why); every kernel whose forward is
# well defined gets a test, so an unexpected acceptance is still judged.
from r5_common import tie_case
N = "n"
SPECS = []
def K(**kw):
    kw["name"] = "r5_" + kw["name"]
    kw.setdefault("expect", "accept")
    SPECS.append(kw)
L1 = "for (int n : {0, 1, 2, 3, 4, 7, 16})"
L1p = "for (int n : {1, 2, 3, 4, 7, 16})"
L2 = "for (auto [n, m] : {std::pair{0, 0}, {1, 1}, {1, 3}, {3, 1}, {2, 2}, {4, 3}, {5, 6}})"
L2p = "for (auto [n, m] : {std::pair{1, 1}, {1, 3}, {3, 1}, {2, 2}, {4, 3}, {5, 6}})"
L2i = "for (auto [n, m] : {std::pair{3, 3}, {3, 4}, {4, 3}, {5, 6}})"
CM = "#include <cmath>\n#include <algorithm>\n"
def a1(*outs): return [("in","a",N)] + [("out",o,s) for o,s in outs] + [("val","n")]
def ab(*outs): return [("in","a",N),("in","b",N)] + [("out",o,s) for o,s in outs] + [("val","n")]
P_A1 = a1(("out","1"))
P_AB1 = ab(("out","1"))

# ======================================================== min/max reductions
K(name="mm_fmax_local", why="fmax into a local, read in an expression", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_fmax_local(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = -10.0;
  for (int i = 0; i < n; ++i) m = fmax(m, a[i] * b[i]);
  out[0] = m * m + std::sin(m);
}""", params=P_AB1,
  cases=tie_case("r5_mm_fmax_local", "r5_mm_fmax_local", P_AB1,
                 {"a": [1, 2, -1, 0.5], "b": [0.5, 0.25, -0.5, 1]}, {"n": "4"},
                 {"out": {0: 0.25 + __import__("math").sin(0.5)}},
                 # products 0.5, 0.5, 0.5, 0.5: four ties, d out/dm = 2m + cos m
                 {"a": [x * (1.0 + __import__("math").cos(0.5)) / 4 for x in [0.5, 0.25, -0.5, 1]],
                  "b": [x * (1.0 + __import__("math").cos(0.5)) / 4 for x in [1, 2, -1, 0.5]]}, "out"))

K(name="mm_std_max_later_loop", why="std::max of |a| read in a later loop", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_std_max_later_loop(DPGEN_IN const double* a, DPGEN_OUT double* u, int n) {
  double m = 0.0;
  for (int i = 0; i < n; ++i) m = std::max(m, std::fabs(a[i]));
  for (int i = 0; i < n; ++i) u[i] = a[i] / (1.0 + m);
}""", params=a1(("u",N)))

K(name="mm_fmin_exp", why="fmin of a difference, exp after", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_fmin_exp(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = 10.0;
  for (int i = 0; i < n; ++i) m = fmin(m, a[i] - b[i]);
  out[0] = std::exp(m);
}""", params=P_AB1)

K(name="mm_std_min_float", why="std::min in a float kernel", T="float", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_std_min_float(DPGEN_IN const float* a, DPGEN_OUT float* out, int n) {
  float m = 4.0f;
  for (int i = 0; i < n; ++i) m = std::min(m, a[i] * a[i] + 0.5f * a[i]);
  out[0] = 2.0f * m + m * m;
}""", params=P_A1)

P = ab(("out","1"))
K(name="mm_macro_max", why="MAX macro of an expression", includes=CM + "#define MAX(x, y) ((x) > (y) ? (x) : (y))\n",
  src="""
DPGEN_KERNEL void r5_mm_macro_max(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = -5.0;
  int i;
  for (i = 0; i < n; i++) m = MAX(m, a[i] * a[i] + b[i]);
  out[0] = m;
}""", params=P)

K(name="mm_macro_min_rev", why="MIN macro, element first", includes=CM + "#define MIN(x, y) (((x) < (y)) ? (x) : (y))\n",
  src="""
DPGEN_KERNEL void r5_mm_macro_min_rev(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = 5.0;
  int i;
  for (i = 0; i < n; i++) m = MIN(a[i] - 2.0 * b[i], m);
  out[0] = m * m;
}""", params=P)

K(name="mm_macro_misnamed", why="a macro named MAX that is a min: dpgen must compute the min", includes=CM + "#define MAX(x, y) ((x) < (y) ? (x) : (y))\n",
  src="""
DPGEN_KERNEL void r5_mm_macro_misnamed(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = 3.0;
  for (int i = 0; i < n; ++i) m = MAX(m, a[i]);
  out[0] = m * m;
}""", params=P_A1)

for nm, expr, why in [
    ("tern_lt_max", "m = (m < e) ? e : m;", "max as (m < e) ? e : m"),
    ("tern_gt_max", "m = m > e ? m : e;", "max as m > e ? m : e"),
    ("tern_ge_max", "m = (e >= m) ? e : m;", "max as (e >= m) ? e : m"),
    ("tern_lt_min", "m = (e < m) ? e : m;", "min as (e < m) ? e : m"),
    ("tern_gt_min", "m = (m > e) ? e : m;", "min as (m > e) ? e : m"),
    ("tern_not_le", "m = !(e <= m) ? e : m;", "max as !(e <= m) ? e : m"),
]:
    K(name="mm_" + nm, why=why, includes=CM,
      src="""
DPGEN_KERNEL void r5_mm_%s(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = 0.25;
  for (int i = 0; i < n; ++i) {
    const double e = a[i] * b[i] - 0.1 * a[i];
    %s
  }
  out[0] = m * (1.0 + m);
}""" % (nm, expr), params=P)

for nm, body, why in [
    ("if_gt", "if (a[i] * b[i] > m) m = a[i] * b[i];", "if (e > m) m = e;"),
    ("if_ge_braced", "{ const double e = a[i] + b[i] * b[i]; if (e >= m) { m = e; } }", "if (e >= m) { m = e; } with a body local"),
    ("if_m_lt", "if (m < std::fabs(a[i] - b[i])) m = std::fabs(a[i] - b[i]);", "if (m < e) m = e; with fabs"),
    ("if_not_le", "if (!(a[i] <= m)) m = a[i];", "if (!(e <= m)) m = e;"),
    ("if_lt_min", "if (b[i] - a[i] < m) m = b[i] - a[i];", "if (e < m) m = e; (min)"),
    ("if_le_min", "if (a[i] * a[i] <= m) m = a[i] * a[i];", "if (e <= m) m = e; (min)"),
]:
    K(name="mm_" + nm, why=why, includes=CM,
      src="""
DPGEN_KERNEL void r5_mm_%s(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = %s;
  for (int i = 0; i < n; ++i)
    %s
  out[0] = std::exp(0.5 * m);
}""" % (nm, "0.3" if "min" in nm else "-0.3", body), params=P)

# ---- not reductions: dpgen must refuse (or be right)
K(name="mm_not_cmp_other", expect="reject", why="if (a[i] > m) m = b[i]: compares one value, keeps another (a recurrence)", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_not_cmp_other(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = -2.0;
  for (int i = 0; i < n; ++i)
    if (a[i] > m) m = b[i];
  out[0] = m;
}""", params=P)

K(name="mm_not_abs_cmp", expect="reject", why="if (fabs(a[i]) > m) m = a[i]: compares |a|, keeps a", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_not_abs_cmp(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = 0.0;
  for (int i = 0; i < n; ++i)
    if (std::fabs(a[i]) > m) m = a[i];
  out[0] = m * m + m;
}""", params=P_A1)

K(name="mm_not_or_flag", expect="reject", why="if (e > m || flag) m = e: with flag set it is the last element", includes=CM,
  loop="for (int flag : {0, 1}) for (int n : {0, 1, 2, 3, 7})", pre="CAPTURE(flag);",
  src="""
DPGEN_KERNEL void r5_mm_not_or_flag(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, int flag) {
  double m = -3.0;
  for (int i = 0; i < n; ++i)
    if (a[i] > m || flag) m = a[i];
  out[0] = m * m;
}""", params=[("in","a",N),("out","out","1"),("val","n"),("val","flag")])

K(name="mm_not_threshold", expect="reject", why="if (e > m + 0.1) m = e: a jump recurrence, not a max", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_not_threshold(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = -3.0;
  for (int i = 0; i < n; ++i)
    if (a[i] > m + 0.1) m = a[i];
  out[0] = m * m;
}""", params=P_A1)

K(name="mm_not_tern_other", expect="reject", why="m = a[i] > m ? b[i] : m", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_not_tern_other(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = -2.0;
  for (int i = 0; i < n; ++i) m = a[i] > m ? b[i] : m;
  out[0] = m;
}""", params=P)

K(name="mm_not_tern_swapped", expect="reject", why="m = (e > m) ? m : e is a min; m = (e > m) ? e : e is not a reduction... here: (m > e) ? m : 2*e", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_not_tern_swapped(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = -2.0;
  for (int i = 0; i < n; ++i) m = (m > a[i]) ? m : 2.0 * a[i];
  out[0] = m;
}""", params=P_A1)

K(name="mm_not_self_in_elem", expect="reject", why="m = fmax(m, 0.5 * m + a[i]): the element reads m", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_not_self_in_elem(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = 0.0;
  for (int i = 0; i < n; ++i) m = fmax(m, 0.5 * m + a[i]);
  out[0] = m;
}""", params=P_A1)

K(name="mm_not_scaled_result", expect="reject", why="m = 0.9 * fmax(m, a[i]): not a plain max", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_not_scaled_result(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = 0.0;
  for (int i = 0; i < n; ++i) m = 0.9 * fmax(m, a[i]);
  out[0] = m;
}""", params=P_A1)

K(name="mm_not_max_plus", expect="reject", why="m = fmax(m + 0.1, a[i])", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_not_max_plus(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = 0.0;
  for (int i = 0; i < n; ++i) m = fmax(m + 0.1, a[i]);
  out[0] = m;
}""", params=P_A1)

K(name="mm_minmax_elseif", expect="reject", why="if (x > mx) mx = x; else if (x < mn) mn = x;: the min runs under a condition on mx (read inside its loop)", includes=CM, loop=L1p,
  src="""
DPGEN_KERNEL void r5_mm_minmax_elseif(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double mx = a[0], mn = a[0];
  for (int i = 1; i < n; ++i) {
    if (a[i] > mx) mx = a[i];
    else if (a[i] < mn) mn = a[i];
  }
  out[0] = mx - mn;
  out[1] = mx * mn;
}""", params=a1(("out","2")))

K(name="mm_argmax_payload", expect="reject", why="if (a[i] > m) { m = a[i]; out[1] = b[i]; }: a payload stored under the running max", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_argmax_payload(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = -5.0;
  out[1] = 0.0;
  for (int i = 0; i < n; ++i)
    if (a[i] > m) { m = a[i]; out[1] = b[i]; }
  out[0] = m;
}""", params=ab(("out","2")))

# ---- nested and several
K(name="mm_nested_fmax_fmax", why="m = fmax(fmax(m, a[i]), b[i]): two updates in one expression", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_nested_fmax_fmax(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = -4.0;
  for (int i = 0; i < n; ++i) m = fmax(fmax(m, a[i]), b[i] * b[i]);
  out[0] = m * m;
}""", params=P)

P = ab(("out","1"))
K(name="mm_elem_is_max", why="m = fmax(m, fmax(a[i], b[i])): the element itself a max", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_elem_is_max(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = -4.0;
  for (int i = 0; i < n; ++i) m = fmax(m, fmax(a[i], 0.5 * b[i]));
  out[0] = m * m;
}""", params=P,
  cases=tie_case("r5_mm_elem_is_max", "r5_mm_elem_is_max", P, {"a": [1.0, 0.5], "b": [2.0, 4.0]}, {"n": "2"},
                 {"out": {0: 4.0}},
                 # elements fmax(1, 1) (inner tie: the inner fmax is a plain max, its derivative
                 # goes to one argument by dpgen's rule for std::max) and fmax(0.5, 2) = 2: one tie of 2
                 {"a": [0, 0], "b": [0, 2.0]}, "out"))

K(name="mm_init_list", why="m = std::max({m, a[i], b[i]})", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_init_list(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = -4.0;
  for (int i = 0; i < n; ++i) m = std::max({m, a[i], b[i]});
  out[0] = m * m;
}""", params=P)

K(name="mm_two_updates_ties", why="two updates per iteration, ties across arrays", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_two_updates_ties(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = -4.0;
  for (int i = 0; i < n; ++i) {
    m = std::max(m, a[i]);
    m = std::max(b[i], m);
  }
  out[0] = 3.0 * m;
}""", params=P,
  cases=tie_case("r5_mm_two_updates_ties", "r5_mm_two_updates_ties", P,
                 {"a": [1.0, 2.0, 2.0], "b": [2.0, 0.0, -1.0]}, {"n": "3"}, {"out": {0: 6.0}},
                 {"a": [0, 1.0, 1.0], "b": [1.0, 0, 0]}, "out"))

K(name="mm_range_same_loop", why="a max and a min of the same data in one loop", includes=CM, loop=L1p,
  src="""
DPGEN_KERNEL void r5_mm_range_same_loop(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double mx = a[0], mn = a[0];
  for (int i = 0; i < n; ++i) {
    mx = fmax(mx, a[i]);
    mn = fmin(mn, a[i]);
  }
  out[0] = mx - mn;
  out[1] = mx * mn;
}""", params=a1(("out","2")),
  cases=tie_case("r5_mm_range_same_loop", "r5_mm_range_same_loop", a1(("out","2")),
                 {"a": [3.0, 3.0, 1.0, 1.0]}, {"n": "4"}, {"out": {0: 2.0, 1: 3.0}},
                 # max 3: start a[0], a[0], a[1]: 2/3 and 1/3; min 1 at a[2], a[3]: half each
                 {"a": [2.0 / 3, 1.0 / 3, -0.5, -0.5]}, "out", 0))

K(name="mm_start_a0_ties", why="start from a[0], the loop includes index 0 (start and a[0] tie)", includes=CM, loop=L1p,
  src="""
DPGEN_KERNEL void r5_mm_start_a0_ties(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = a[0];
  for (int i = 0; i < n; ++i)
    m = std::max(m, a[i]);
  out[0] = m * m;
}""", params=P_A1,
  cases=tie_case("r5_mm_start_a0_ties_a", "r5_mm_start_a0_ties", P_A1, {"a": [3.0, 3.0, 1.0]}, {"n": "3"},
                 {"out": {0: 9.0}}, {"a": [4.0, 2.0, 0]}, "out") + "\n" +
        tie_case("r5_mm_start_a0_ties_b", "r5_mm_start_a0_ties", P_A1, {"a": [3.0, 1.0, 2.0]}, {"n": "3"},
                 {"out": {0: 9.0}}, {"a": [6.0, 0, 0]}, "out"))

K(name="mm_start_param_tie", why="start from a parameter, ties with it", includes=CM,
  loop="for (double lo : {-0.5, 0.25}) for (int n : {0, 1, 2, 5})", pre="CAPTURE(lo);",
  src="""
DPGEN_KERNEL void r5_mm_start_param_tie(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, double lo) {
  double m = lo;
  for (int i = 0; i < n; ++i) m = fmax(m, a[i]);
  out[0] = m * m * m;
}""", params=[("in","a",N),("out","out","1"),("val","n"),("val","lo")],
  cases=tie_case("r5_mm_start_param_tie", "r5_mm_start_param_tie", [("in","a",N),("out","out","1"),("val","n"),("val","lo")],
                 {"a": [2.0, 1.0, 2.0]}, {"n": "3", "lo": "2.0"}, {"out": {0: 8.0}},
                 # three ties: lo (no derivative), a[0], a[2]: 12 / 3 each
                 {"a": [4.0, 0, 4.0]}, "out"))

K(name="mm_start_const_tie", why="start 0 ties with a zero element", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_start_const_tie(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double e = 0.0;
  for (int i = 0; i < n; ++i) e = fmax(e, a[i] - b[i]);
  out[0] = 2.0 * e + 1.0;
}""", params=P,
  cases=tie_case("r5_mm_start_const_tie", "r5_mm_start_const_tie", P, {"a": [1.0, -1.0], "b": [1.0, 0.5]}, {"n": "2"},
                 {"out": {0: 1.0}}, {"a": [1.0, 0], "b": [-1.0, 0]}, "out"))

K(name="mm_err_ptr_later_loop", why="*err = 0; *err = fmax(*err, |r|); the output read by a later loop", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_err_ptr_later_loop(DPGEN_IN const double* r, DPGEN_OUT double* err, DPGEN_OUT double* u, int n) {
  *err = 0.0;
  for (int i = 0; i < n; ++i) *err = fmax(*err, fabs(r[i]));
  for (int i = 0; i < n; ++i) u[i] = r[i] / (1.0 + *err);
}""", params=[("in","r",N),("out","err","1"),("out","u",N),("val","n")])

K(name="mm_err_ptr_sqrt_after", why="*err = max of squares, then *err = sqrt(*err) (read back after the loop)", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_err_ptr_sqrt_after(DPGEN_IN const double* r, DPGEN_OUT double* err, int n) {
  *err = 1e-3;
  for (int i = 0; i < n; ++i) *err = fmax(*err, r[i] * r[i]);
  *err = std::sqrt(*err);
}""", params=[("in","r",N),("out","err","1"),("val","n")])

K(name="mm_err_ptr_overwritten", why="*err reduced, then overwritten with another value after the loop", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_err_ptr_overwritten(DPGEN_IN const double* r, DPGEN_OUT double* err, int n) {
  err[0] = 0.0;
  for (int i = 0; i < n; ++i) err[0] = fmax(err[0], r[i]);
  err[1] = 2.0 * err[0];
  err[0] = r[0] * 0.0 + 1.0;
}""", loop=L1p, params=[("in","r",N),("out","err","2"),("val","n")])

K(name="mm_err_two_loops_chain", why="*err reduced over two loops in turn (the second starts from the first)", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_err_two_loops_chain(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* err, int n) {
  *err = 0.0;
  for (int i = 0; i < n; ++i) *err = fmax(*err, fabs(a[i]));
  for (int i = 0; i < n; ++i) *err = fmax(*err, 2.0 * fabs(b[i]));
}""", params=ab(("err","1")),
  cases=tie_case("r5_mm_err_two_loops_chain", "r5_mm_err_two_loops_chain", ab(("err","1")),
                 {"a": [2.0, -1.0], "b": [1.0, -0.5]}, {"n": "2"}, {"err": {0: 2.0}},
                 # 2 = |a0| = 2|b0|: half each
                 {"a": [0.5, 0], "b": [1.0, 0]}, "err"))

K(name="mm_local_two_loops_chain", why="a local reduced by two loops in turn", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_local_two_loops_chain(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = -1.0;
  for (int i = 0; i < n; ++i) m = std::max(m, a[i]);
  for (int i = 0; i < n; ++i) m = std::max(m, b[i] * b[i]);
  out[0] = m * m;
}""", params=P)

K(name="mm_reset_reuse", why="reduce, copy, reset, reduce again", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_reset_reuse(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = -1.0;
  for (int i = 0; i < n; ++i) m = fmax(m, a[i]);
  const double first = m;
  m = 1.0;
  for (int i = 0; i < n; ++i) m = fmin(m, b[i]);
  out[0] = first * m;
  out[1] = first - m * m;
}""", params=ab(("out","2")))

K(name="mm_chain_start_from_other", why="a second reduction starts from the first's result", includes=CM, loop=L1p,
  src="""
DPGEN_KERNEL void r5_mm_chain_start_from_other(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m1 = a[0];
  for (int i = 1; i < n; ++i) m1 = fmax(m1, a[i]);
  double m2 = m1;
  for (int i = 0; i < n; ++i) m2 = fmax(m2, b[i]);
  out[0] = m1 * m2;
}""", params=P,
  cases=tie_case("r5_mm_chain_start_from_other", "r5_mm_chain_start_from_other", P,
                 {"a": [1.0, 2.0], "b": [2.0, 0.0]}, {"n": "2"}, {"out": {0: 4.0}},
                 # m1 = a1 = 2; m2 = max(m1, b0 = 2): tie start/b0; out = m1 m2:
                 # d/da1 = m2 + m1/2 = 3, d/db0 = m1/2 = 1
                 {"a": [0, 3.0], "b": [1.0, 0]}, "out"))

K(name="mm_cond_index_path_ties", why="max under an index condition; an excluded element equals the max", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_cond_index_path_ties(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = -9.0;
  for (int i = 0; i < n; ++i)
    if (i % 2 == 0) m = fmax(m, a[i]);
  out[0] = m * m;
}""", params=P_A1,
  cases=tie_case("r5_mm_cond_index_path_ties", "r5_mm_cond_index_path_ties", P_A1,
                 {"a": [1.0, 5.0, 5.0]}, {"n": "3"}, {"out": {0: 25.0}}, {"a": [0, 0, 10.0]}, "out"))

K(name="mm_cond_data_path_ties", why="max under a data condition; an excluded element equals the max", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_cond_data_path_ties(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = -9.0;
  for (int i = 0; i < n; ++i)
    if (b[i] > 0.0) m = std::max(m, a[i]);
  out[0] = m * m;
}""", params=P,
  cases=tie_case("r5_mm_cond_data_path_ties", "r5_mm_cond_data_path_ties", P,
                 {"a": [5.0, 5.0, 1.0], "b": [-1.0, 1.0, 1.0]}, {"n": "3"}, {"out": {0: 25.0}},
                 {"a": [0, 10.0, 0], "b": [0, 0, 0]}, "out"))

K(name="mm_continue_ties", why="max after a continue; a skipped element equals the max", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_continue_ties(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = -9.0;
  for (int i = 0; i < n; ++i) {
    if (b[i] > 0.0) continue;
    if (a[i] > m) m = a[i];
  }
  out[0] = m * m;
}""", params=P,
  cases=tie_case("r5_mm_continue_ties", "r5_mm_continue_ties", P,
                 {"a": [5.0, 5.0, 1.0], "b": [1.0, -1.0, -1.0]}, {"n": "3"}, {"out": {0: 25.0}},
                 {"a": [0, 10.0, 0], "b": [0, 0, 0]}, "out"))

K(name="mm_if_and_cond", why="if (e > m && i > 0) m = e;", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_if_and_cond(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = -9.0;
  for (int i = 0; i < n; ++i)
    if (a[i] > m && i > 0) m = a[i];
  out[0] = m * m;
}""", params=P_A1,
  cases=tie_case("r5_mm_if_and_cond", "r5_mm_if_and_cond", P_A1,
                 {"a": [5.0, 5.0, 1.0]}, {"n": "3"}, {"out": {0: 25.0}}, {"a": [0, 10.0, 0]}, "out"))

K(name="mm_strided_ties", why="min over a stride-2 loop; the skipped odd element is smaller", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_strided_ties(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = 10.0;
  for (int i = 0; i < n; i += 2) m = fmin(m, a[i]);
  out[0] = m * m + m;
}""", params=P_A1,
  cases=tie_case("r5_mm_strided_ties", "r5_mm_strided_ties", P_A1,
                 {"a": [0.5, -5.0, 0.5]}, {"n": "3"}, {"out": {0: 0.75}}, {"a": [1.0, 0, 1.0]}, "out"))

K(name="mm_triangular", why="max over a triangular nest", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_triangular(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = -9.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j <= i; ++j)
      m = fmax(m, a[i] * a[j] + 0.1 * j);
  out[0] = m;
}""", params=P_A1)

K(name="mm_triangular_repeat_ties", why="the same element met several times by a triangular nest (per-occurrence split?)", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_triangular_repeat_ties(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = -9.0;
  for (int i = 0; i < n; ++i)
    for (int j = i; j < n; ++j)
      m = fmax(m, a[i]);
  out[0] = m;
}""", params=P_A1,
  # a0 = a2 = max: a0 met 3 times, a2 once. Documented: split among the elements equal to the
  # extremum (ties): per occurrence 3/4 and 1/4; per element 1/2 each. Expect per occurrence.
  cases=tie_case("r5_mm_triangular_repeat_ties", "r5_mm_triangular_repeat_ties", P_A1,
                 {"a": [2.0, 1.0, 2.0]}, {"n": "3"}, {"out": {0: 2.0}}, {"a": [0.75, 0, 0.25]}, "out"))

K(name="mm_countdown", why="max in a loop counting down", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_countdown(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = -2.0;
  int i;
  for (i = n - 1; i >= 0; i--) m = fmax(m, a[i] * (1.0 + a[i]));
  out[0] = m;
}""", params=P_A1)

K(name="mm_unsigned_size_t", why="size_t counter and size", includes=CM + "#include <cstddef>\n",
  src="""
DPGEN_KERNEL void r5_mm_unsigned_size_t(DPGEN_IN const double* a, DPGEN_OUT double* out, std::size_t n) {
  double m = 100.0;
  for (std::size_t i = 0; i < n; ++i) m = std::min(m, a[i] * a[i] - a[i]);
  out[0] = m;
}""", params=[("in","a",N),("out","out","1"),("val","std::size_t(n)")])

K(name="mm_omp_reduction_pragma", why="#pragma omp parallel for reduction(max:err) over a 2D interior (C89, IDX macro)", includes=CM + "#define IDX(i, j) ((j) * nx + (i))\n",
  loop=L2, src="""
DPGEN_KERNEL void r5_mm_omp_reduction_pragma(DPGEN_IN const double* u, DPGEN_IN const double* f, DPGEN_OUT double* res, int nx, int ny) {
  int i, j;
  double err = 0.0;
#pragma omp parallel for private(i) reduction(max : err)
  for (j = 1; j < ny - 1; j++)
    for (i = 1; i < nx - 1; i++) {
      double r = f[IDX(i, j)] - (4.0 * u[IDX(i, j)] - u[IDX(i - 1, j)] - u[IDX(i + 1, j)] - u[IDX(i, j - 1)] - u[IDX(i, j + 1)]);
      err = fmax(err, fabs(r));
    }
  res[0] = std::sqrt(err + 1.0);
}""", params=[("in","u","n*m"),("in","f","n*m"),("out","res","1"),("val","n"),("val","m")])

K(name="mm_helper_ternary", why="m = mymax(m, e), a user helper returning a ?: max", includes=CM,
  src="""
static inline double mymax(double x, double y) { return x > y ? x : y; }
DPGEN_KERNEL void r5_mm_helper_ternary(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = -3.0;
  for (int i = 0; i < n; ++i) m = mymax(m, a[i] * b[i]);
  out[0] = m * m;
}""", params=P)

K(name="mm_helper_misnamed", why="a helper called vmax that returns the min", includes=CM,
  src="""
static inline double vmax(double x, double y) { return x < y ? x : y; }
DPGEN_KERNEL void r5_mm_helper_misnamed(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = 3.0;
  for (int i = 0; i < n; ++i) m = vmax(m, a[i]);
  out[0] = m * m;
}""", params=P_A1)

K(name="mm_helper_ptr_update", why="void helper updating *m through a pointer: if (e > *m) *m = e;", includes=CM,
  src="""
static inline void upd_max(double* m, double e) { if (e > *m) *m = e; }
DPGEN_KERNEL void r5_mm_helper_ptr_update(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = -3.0;
  for (int i = 0; i < n; ++i) upd_max(&m, a[i] * a[i] - a[i]);
  out[0] = m * m;
}""", params=P_A1)

K(name="mm_helper_ref_update", why="void helper updating m by reference with std::max", includes=CM,
  src="""
static inline void upd_max(double& m, double e) { m = std::max(m, e); }
DPGEN_KERNEL void r5_mm_helper_ref_update(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = -3.0;
  for (int i = 0; i < n; ++i) upd_max(m, a[i] * a[i] - a[i]);
  out[0] = m * m;
}""", params=P_A1)

K(name="mm_lambda_value", why="lambda max m = mx(m, e)", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_lambda_value(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  auto mx = [](double x, double y) { return x > y ? x : y; };
  double m = -3.0;
  for (int i = 0; i < n; ++i) m = mx(m, std::sin(a[i]));
  out[0] = m * m;
}""", params=P_A1)

K(name="mm_lambda_ref_capture", why="[&] lambda updating the captured m", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_lambda_ref_capture(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = -3.0;
  auto upd = [&](double e) { m = std::max(m, e); };
  for (int i = 0; i < n; ++i) upd(a[i] * b[i]);
  out[0] = m * m;
}""", params=P)

K(name="mm_float_near_ties", why="float products that tie only after float rounding", T="float", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_float_near_ties(DPGEN_IN const float* a, DPGEN_IN const float* b, DPGEN_OUT float* out, int n) {
  float m = -2.0f;
  for (int i = 0; i < n; ++i) m = fmaxf(m, a[i] * b[i]);
  out[0] = 2.0f * m;
}""", params=P,
  # 0.1f * 3.0f rounds to 0.3f exactly: a tie in float, not in real arithmetic
  cases=tie_case("r5_mm_float_near_ties", "r5_mm_float_near_ties", P, {"a": [0.1, 0.3], "b": [3.0, 1.0]},
                 {"n": "2"}, {"out": {0: 0.6}}, {"a": [3.0, 1.0], "b": [0.1, 0.3]}, "out", T="float"))

K(name="mm_float_double_literal", why="float max of a float times a double literal (the element is a double, m a float)", T="float", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_float_double_literal(DPGEN_IN const float* a, DPGEN_OUT float* out, int n) {
  float m = -2.0f;
  for (int i = 0; i < n; ++i) m = fmax(m, a[i] * 0.1);
  out[0] = 10.0f * m;
}""", params=P_A1,
  cases=tie_case("r5_mm_float_double_literal", "r5_mm_float_double_literal", P_A1, {"a": [3.0]},
                 {"n": "1"}, {"out": {0: 3.0}}, {"a": [1.0]}, "out", T="float"))

K(name="mm_float_if_double_expr", why="if (a[i] * 0.1 < m) m = a[i] * 0.1; in a float kernel", T="float", ranges="{-8.0, 8.0}", loop="for (int n : {0, 1, 2, 3, 5, 7})", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_float_if_double_expr(DPGEN_IN const float* a, DPGEN_OUT float* out, int n) {
  float m = 2.0f;
  for (int i = 0; i < n; ++i)
    if (a[i] * 0.1 < m) m = a[i] * 0.1;
  out[0] = 10.0f * m;
}""", params=P_A1,
  cases=tie_case("r5_mm_float_if_double_expr", "r5_mm_float_if_double_expr", P_A1, {"a": [3.0, 7.0]},
                 {"n": "2"}, {"out": {0: 3.0}}, {"a": [1.0, 0.0]}, "out", T="float"))

K(name="mm_double_local_float_data", why="double max over float data in a float kernel", T="float", ranges="{-8.0, 8.0}", loop="for (int n : {0, 1, 2, 3, 5, 7})", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_double_local_float_data(DPGEN_IN const float* a, DPGEN_OUT float* out, int n) {
  double m = -2.0;
  for (int i = 0; i < n; ++i) m = std::max(m, (double)a[i] * a[i]);
  out[0] = (float)(0.5 * m);
}""", params=P_A1)

K(name="mm_rowmax_softmax", why="per-row max, then a sum of exp(a - max), then the normalised row (softmax)", includes=CM, loop=L2,
  src="""
DPGEN_KERNEL void r5_mm_rowmax_softmax(DPGEN_IN const double* a, DPGEN_OUT double* p, int nx, int ny) {
  for (int j = 0; j < ny; ++j) {
    double m = a[j * nx];
    for (int i = 1; i < nx; ++i) m = fmax(m, a[j * nx + i]);
    double s = 0.0;
    for (int i = 0; i < nx; ++i) s += std::exp(a[j * nx + i] - m);
    for (int i = 0; i < nx; ++i) p[j * nx + i] = std::exp(a[j * nx + i] - m) / s;
  }
}""", params=[("in","a","n*m"),("out","p","n*m"),("val","n"),("val","m")])

K(name="mm_logsumexp", why="log-sum-exp with the max subtracted", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_logsumexp(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = -1e30;
  for (int i = 0; i < n; ++i) m = std::max(m, a[i]);
  double s = 0.0;
  for (int i = 0; i < n; ++i) s += std::exp(a[i] - m);
  out[0] = n > 0 ? m + std::log(s) : 0.0;
}""", params=P_A1,
  cases=tie_case("r5_mm_logsumexp", "r5_mm_logsumexp", P_A1, {"a": [1.0, 1.0]}, {"n": "2"},
                 {"out": {0: 1.0 + __import__("math").log(2.0)}}, {"a": [0.5, 0.5]}, "out"))

K(name="mm_rowmax_out_elem", why="rowmax[j] = -1e30; rowmax[j] = fmax(rowmax[j], ...) per row (an output element per row)", includes=CM, loop=L2,
  src="""
DPGEN_KERNEL void r5_mm_rowmax_out_elem(DPGEN_IN const double* a, DPGEN_OUT double* rowmax, int nx, int ny) {
  for (int j = 0; j < ny; ++j) {
    rowmax[j] = -1e3;
    for (int i = 0; i < nx; ++i) rowmax[j] = fmax(rowmax[j], a[j * nx + i] * a[j * nx + i]);
  }
}""", params=[("in","a","n*m"),("out","rowmax","m"),("val","n"),("val","m")])

K(name="mm_colmin_rowptr", why="colmin[i] = a[0][i]; for j from 0: if (a[j][i] < colmin[i]) colmin[i] = a[j][i]; (double**)", includes=CM, loop=L2p,
  src="""
DPGEN_KERNEL void r5_mm_colmin_rowptr(DPGEN_IN double** a, DPGEN_OUT double* colmin, int nx, int ny) {
  for (int i = 0; i < nx; ++i) {
    colmin[i] = a[0][i];
    for (int j = 0; j < ny; ++j)
      if (a[j][i] < colmin[i]) colmin[i] = a[j][i];
  }
}""", params=[("inr","a","m","n"),("out","colmin","n"),("val","n"),("val","m")])

K(name="mm_colmax_c89_idx", why="C89 column max into an output row through an IDX macro, loops i outer j inner", includes=CM + "#define IDX(i, j) ((j) * nx + (i))\n", loop=L2p,
  src="""
DPGEN_KERNEL void r5_mm_colmax_c89_idx(DPGEN_IN const double* a, DPGEN_OUT double* cmax, int nx, int ny) {
  int i, j;
  for (i = 0; i < nx; i++) {
    cmax[i] = a[IDX(i, 0)];
    for (j = 1; j < ny; j++)
      cmax[i] = cmax[i] > a[IDX(i, j)] ? cmax[i] : a[IDX(i, j)];
  }
}""", params=[("in","a","n*m"),("out","cmax","n"),("val","n"),("val","m")])

K(name="mm_out_elem_param_index", why="out[k] = 0; out[k] = fmax(out[k], a[i]); k a parameter", includes=CM,
  loop="for (int k : {0, 2}) for (int n : {0, 1, 2, 5})", pre="CAPTURE(k);",
  src="""
DPGEN_KERNEL void r5_mm_out_elem_param_index(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, int k) {
  out[k] = 0.0;
  for (int i = 0; i < n; ++i) out[k] = fmax(out[k], a[i] * a[i]);
}""", params=[("in","a",N),("out","out","3"),("val","n"),("val","k")])

K(name="mm_two_out_elems", why="err[0] a max, err[1] a min of the same loop (output elements)", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_two_out_elems(DPGEN_IN const double* a, DPGEN_OUT double* err, int n) {
  err[0] = -1.0;
  err[1] = 1.0;
  for (int i = 0; i < n; ++i) {
    err[0] = fmax(err[0], a[i]);
    err[1] = fmin(err[1], a[i]);
  }
}""", params=a1(("err","2")))

K(name="mm_out_no_init", expect="reject", why="*err = fmax(*err, ...) without setting *err first (documented rejection)", reject=True, includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_out_no_init(DPGEN_IN const double* r, DPGEN_OUT double* err, int n) {
  for (int i = 0; i < n; ++i) *err = fmax(*err, fabs(r[i]));
}""", params=[("in","r",N),("out","err","1"),("val","n")])

K(name="mm_elem_reads_output", why="the element reads an output stored earlier in the iteration", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_elem_reads_output(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* u, DPGEN_OUT double* out, int n) {
  double m = -3.0;
  for (int i = 0; i < n; ++i) {
    u[i] = a[i] * b[i];
    m = fmax(m, u[i] + 0.5 * u[i] * u[i]);
  }
  out[0] = m;
}""", params=ab(("u",N),("out","1")))

K(name="mm_with_accumulator", why="a max and a sum in one loop, divided after", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_with_accumulator(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 1.0, m = 0.0;
  for (int i = 0; i < n; ++i) {
    s += a[i] * a[i];
    m = fmax(m, fabs(a[i]));
  }
  out[0] = m / s;
}""", params=P_A1)

K(name="mm_over_work_array", why="max over a work array (DPGEN_OUT) filled by an earlier loop", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_over_work_array(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* w, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) w[i] = a[i] * a[i] - b[i];
  double m = -5.0;
  for (int i = 0; i < n; ++i) m = fmax(m, w[i]);
  out[0] = m * m;
}""", params=ab(("w",N),("out","1")))

K(name="mm_stencil_diff", why="max |u[i+1] - u[i]| (each element in two differences)", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_stencil_diff(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  double g = 0.0;
  for (int i = 0; i + 1 < n; ++i) g = fmax(g, fabs(u[i + 1] - u[i]));
  out[0] = g * g;
}""", params=[("in","u",N),("out","out","1"),("val","n")])

K(name="mm_3d_idx_omp", why="3D max over an interior, IDX3 macro, omp", includes=CM + "#define IDX3(i, j, k) (((k) * ny + (j)) * nx + (i))\n",
  loop="for (auto [nx, ny, nz] : {std::tuple{1, 1, 1}, {3, 3, 3}, {4, 3, 5}})", pre="const int n = nx * ny * nz; CAPTURE(nx); CAPTURE(ny); CAPTURE(nz);",
  src="""
DPGEN_KERNEL void r5_mm_3d_idx_omp(DPGEN_IN const double* u, DPGEN_OUT double* out, int nx, int ny, int nz) {
  double m = 0.0;
  #pragma omp parallel for collapse(2) reduction(max : m)
  for (int k = 1; k < nz - 1; ++k)
    for (int j = 1; j < ny - 1; ++j)
      for (int i = 1; i < nx - 1; ++i)
        m = std::max(m, std::fabs(u[IDX3(i + 1, j, k)] + u[IDX3(i, j, k - 1)] - 2.0 * u[IDX3(i, j, k)]));
  out[0] = m;
}""", params=[("in","u",N),("out","out","1"),("val","nx"),("val","ny"),("val","nz")])

K(name="mm_guard_return", why="if (n < 1) return; m = -HUGE_VAL", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_guard_return(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  if (n < 1) return;
  double m = -HUGE_VAL;
  for (int i = 0; i < n; ++i) m = fmax(m, a[i]);
  out[0] = m;
}""", params=P_A1)

K(name="mm_numeric_limits", why="m = std::numeric_limits<double>::lowest()", includes=CM + "#include <limits>\n", loop=L1p,
  src="""
DPGEN_KERNEL void r5_mm_numeric_limits(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = std::numeric_limits<double>::lowest();
  for (int i = 0; i < n; ++i) m = std::max(m, a[i] * a[i]);
  out[0] = m;
}""", params=P_A1)

K(name="mm_branch_param_arms", why="max in one arm, min of another local in the other (flag parameter)", includes=CM,
  loop="for (int flag : {0, 1}) for (int n : {0, 1, 3, 7})", pre="CAPTURE(flag);",
  src="""
DPGEN_KERNEL void r5_mm_branch_param_arms(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, int flag) {
  if (flag == 0) {
    double m = -1.0;
    for (int i = 0; i < n; ++i) m = fmax(m, a[i]);
    out[0] = m;
  } else {
    double m = 1.0;
    for (int i = 0; i < n; ++i) m = fmin(m, a[i]);
    out[0] = m * m;
  }
}""", params=[("in","a",N),("out","out","1"),("val","n"),("val","flag")])

K(name="mm_result_in_condition", why="the max used in a later loop's condition and value", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_result_in_condition(DPGEN_IN const double* a, DPGEN_OUT double* u, int n) {
  double m = 0.0;
  for (int i = 0; i < n; ++i) m = fmax(m, fabs(a[i]));
  for (int i = 0; i < n; ++i)
    u[i] = fabs(a[i]) > 0.5 * m ? a[i] * m : 0.25 * a[i];
}""", params=a1(("u",N)))

K(name="mm_rowptr_rows", why="max over a double** 2D grid", includes=CM, loop=L2,
  src="""
DPGEN_KERNEL void r5_mm_rowptr_rows(DPGEN_IN double** a, DPGEN_OUT double* out, int nx, int ny) {
  double m = -7.0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      m = fmax(m, a[j][i] - 0.5 * a[j][i] * a[j][i]);
  out[0] = m;
}""", params=[("inr","a","m","n"),("out","out","1"),("val","n"),("val","m")])

K(name="mm_per_row_triangular", why="per-row max over a triangular row, started from the diagonal", includes=CM, loop=L1p,
  src="""
DPGEN_KERNEL void r5_mm_per_row_triangular(DPGEN_IN const double* a, DPGEN_OUT double* r, int n) {
  for (int j = 0; j < n; ++j) {
    double m = a[j * n + j];
    for (int i = 0; i < j; ++i) m = fmax(m, a[j * n + i]);
    r[j] = m * m;
  }
}""", params=[("in","a","n*n"),("out","r",N),("val","n")])

K(name="mm_auto_local", why="auto m = a[0]; if-update min with a C89 counter", includes=CM, loop=L1p,
  src="""
DPGEN_KERNEL void r5_mm_auto_local(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  auto m = a[0] * 2.0;
  int i;
  for (i = 1; i < n; i++)
    if (2.0 * a[i] < m) m = 2.0 * a[i];
  out[0] = m;
}""", params=P_A1)

K(name="mm_read_in_pinned", expect="reject", why="the max read inside its own loop through a pinned store if (i == n - 1) out[0] = m", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_read_in_pinned(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = -1.0;
  for (int i = 0; i < n; ++i) {
    m = fmax(m, a[i]);
    if (i == n - 1) out[0] = m;
  }
}""", params=P_A1)

K(name="mm_clamp_elem", why="max of a clamped element fmax(m, fmin(a[i], 0.5))", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_clamp_elem(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = -3.0;
  for (int i = 0; i < n; ++i) m = fmax(m, fmin(a[i], 0.5) + 0.1 * a[i]);
  out[0] = m;
}""", params=P_A1)

# ======================================================== stores pinned to one iteration
K(name="pin_first_last", why="if (i == 0) / if (i == n - 1) diagnostics beside the main store", includes=CM,
  src="""
DPGEN_KERNEL void r5_pin_first_last(DPGEN_IN const double* a, DPGEN_OUT double* u, DPGEN_OUT double* ends, int n) {
  for (int i = 0; i < n; ++i) {
    u[i] = a[i] * a[i];
    if (i == 0) ends[0] = std::exp(a[i]);
    if (i == n - 1) ends[1] = a[i] * a[0];
  }
}""", params=a1(("u",N),("ends","2")))

K(name="pin_param_k", why="if (i == k) out[0] = ...; k may be outside the loop (then nothing is stored)", includes=CM,
  loop="for (int k : {-1, 0, 2, 5}) for (int n : {0, 1, 2, 3, 7})", pre="CAPTURE(k);",
  src="""
DPGEN_KERNEL void r5_pin_param_k(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, int k) {
  for (int i = 0; i < n; ++i)
    if (i == k) out[0] = a[i] * a[i] + 1.0;
}""", params=[("in","a",N),("out","out","1"),("val","n"),("val","k")])

K(name="pin_2d_corner_and", why="if (i == 0 && j == 0) and if (j == ny - 1 && i == nx - 1) in a 2D nest", includes=CM, loop=L2,
  src="""
DPGEN_KERNEL void r5_pin_2d_corner_and(DPGEN_IN const double* a, DPGEN_OUT double* b, DPGEN_OUT double* c, int nx, int ny) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      b[j * nx + i] = 2.0 * a[j * nx + i];
      if (i == 0 && j == 0) c[0] = a[0] * a[0];
      if (j == ny - 1 && i == nx - 1) c[1] = std::sin(a[j * nx + i]);
    }
}""", params=[("in","a","n*m"),("out","b","n*m"),("out","c","2"),("val","n"),("val","m")])

K(name="pin_strided_last_maybe_missing", why="if (i == n - 1) in a stride-2 loop: iteration n - 1 exists only for odd n", includes=CM,
  loop="for (int n : {0, 1, 2, 3, 4, 5, 8, 9})",
  src="""
DPGEN_KERNEL void r5_pin_strided_last_maybe_missing(DPGEN_IN const double* a, DPGEN_OUT double* u, DPGEN_OUT double* last, int n) {
  for (int i = 0; i < n; i += 2) {
    u[i] = a[i] * 3.0;
    if (i == n - 1) last[0] = a[i] * a[i];
  }
}""", params=a1(("u",N),("last","1")))

K(name="pin_const_index", why="if (i == 5): no such iteration for n <= 5", includes=CM,
  src="""
DPGEN_KERNEL void r5_pin_const_index(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    if (i == 5) out[0] = a[i] * a[i - 1];
}""", params=P_A1)

K(name="pin_half_even", why="if (2 * i == n): an iteration only for even n", includes=CM,
  src="""
DPGEN_KERNEL void r5_pin_half_even(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    if (2 * i == n) out[0] = a[i] * a[i] + a[0];
}""", params=P_A1)

K(name="pin_n_div_2", why="if (i == n / 2)", includes=CM,
  src="""
DPGEN_KERNEL void r5_pin_n_div_2(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    if (i == n / 2) out[0] = a[i] * a[i];
}""", params=P_A1)

K(name="pin_first_then_last_same_elem", why="if (i == 0) out[0] = x; if (i == n - 1) out[0] = y; (n = 1: one iteration, y wins)", includes=CM,
  src="""
DPGEN_KERNEL void r5_pin_first_then_last_same_elem(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    if (i == 0) out[0] = std::sin(a[i]);
    if (i == n - 1) out[0] = a[i] * a[i];
  }
}""", params=P_A1)

K(name="pin_last_then_first_same_elem", why="if (i == n - 1) out[0] = y; if (i == 0) out[0] = x; (n = 1: x wins, else y)", includes=CM,
  src="""
DPGEN_KERNEL void r5_pin_last_then_first_same_elem(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    if (i == n - 1) out[0] = a[i] * a[i];
    if (i == 0) out[0] = std::sin(a[i]);
  }
}""", params=P_A1)

K(name="pin_countdown_same_elem", why="count-down loop: iteration 0 runs last, so if (i == 0) wins over if (i == n - 1)", includes=CM,
  src="""
DPGEN_KERNEL void r5_pin_countdown_same_elem(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = n - 1; i >= 0; --i) {
    if (i == 0) out[0] = std::sin(a[i]);
    if (i == n - 1) out[0] = a[i] * a[i];
  }
}""", params=P_A1)

K(name="pin_before_loop_overwrite", why="out[0] set before the loop, then overwritten by if (i == n - 1)", includes=CM,
  src="""
DPGEN_KERNEL void r5_pin_before_loop_overwrite(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  out[0] = 0.5;
  for (int i = 0; i < n; ++i)
    if (i == n - 1) out[0] = a[i] * b[i];
}""", params=P)

K(name="pin_row_first", why="if (i == 0) rowfirst[j] = ... in a 2D nest (one per row)", includes=CM, loop=L2,
  src="""
DPGEN_KERNEL void r5_pin_row_first(DPGEN_IN const double* a, DPGEN_OUT double* b, DPGEN_OUT double* rowfirst, int nx, int ny) {
  int i, j;
  for (j = 0; j < ny; j++)
    for (i = 0; i < nx; i++) {
      b[j * nx + i] = a[j * nx + i] * a[j * nx + i];
      if (i == 0) rowfirst[j] = 2.0 * a[j * nx + i] + a[j * nx + nx - 1];
    }
}""", params=[("in","a","n*m"),("out","b","n*m"),("out","rowfirst","m"),("val","n"),("val","m")])

K(name="pin_diag_elem", why="if (i == j) d[i] = ... (each element once, on the diagonal)", includes=CM, loop=L1,
  src="""
DPGEN_KERNEL void r5_pin_diag_elem(DPGEN_IN const double* a, DPGEN_OUT double* d, int n) {
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (i == j) d[i] = a[j * n + i] * a[j * n + i];
}""", params=[("in","a","n*n"),("out","d",N),("val","n")])

K(name="pin_diag_same_elem", expect="reject", why="if (i == j) tr[0] = ...: n iterations store tr[0] (the last wins)", includes=CM,
  src="""
DPGEN_KERNEL void r5_pin_diag_same_elem(DPGEN_IN const double* a, DPGEN_OUT double* tr, int n) {
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (i == j) tr[0] = a[j * n + i] * a[j * n + i];
}""", params=[("in","a","n*n"),("out","tr","1"),("val","n")])

K(name="pin_k_k_2d", why="if (i == k && j == k) in 2D with k a parameter", includes=CM,
  loop="for (int k : {0, 1, 3}) for (auto [n, m] : {std::pair{0, 0}, {1, 1}, {2, 3}, {4, 4}})", pre="CAPTURE(k);",
  src="""
DPGEN_KERNEL void r5_pin_k_k_2d(DPGEN_IN const double* a, DPGEN_OUT double* out, int nx, int ny, int k) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      if (i == k && j == k) out[0] = a[j * nx + i] * a[j * nx + i];
}""", params=[("in","a","n*m"),("out","out","1"),("val","n"),("val","m"),("val","k")])

K(name="pin_or_ends", expect="reject", why="if (i == 0 || i == n - 1) e[0] = ...: two iterations store e[0]", includes=CM,
  src="""
DPGEN_KERNEL void r5_pin_or_ends(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  for (int i = 0; i < n; ++i)
    if (i == 0 || i == n - 1) e[0] = a[i] * a[i];
}""", params=a1(("e","1")))

K(name="pin_ne_else", why="if (i != 0) {...} else out[0] = ...", includes=CM,
  src="""
DPGEN_KERNEL void r5_pin_ne_else(DPGEN_IN const double* a, DPGEN_OUT double* u, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    if (i != 0) u[i] = a[i] - a[i - 1];
    else out[0] = a[0] * a[0];
  }
}""", params=a1(("u",N),("out","1")))

K(name="pin_continue", why="if (i == 0) { out[0] = ...; continue; }", includes=CM,
  src="""
DPGEN_KERNEL void r5_pin_continue(DPGEN_IN const double* a, DPGEN_OUT double* u, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    if (i == 0) { out[0] = std::exp(a[0]); continue; }
    u[i] = a[i] * a[i - 1];
  }
}""", params=a1(("u",N),("out","1")))

K(name="pin_inner_every_row", expect="reject", why="if (i == 0) out[0] = ... inside a row loop: ny iterations store out[0]", includes=CM, loop=L2,
  src="""
DPGEN_KERNEL void r5_pin_inner_every_row(DPGEN_IN const double* a, DPGEN_OUT double* out, int nx, int ny) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      if (i == 0) out[0] = a[j * nx + i] * a[j * nx + i];
}""", params=[("in","a","n*m"),("out","out","1"),("val","n"),("val","m")])

K(name="pin_lower_bound_2", why="for (i = 2; ...) if (i == 2); and if (i == 1) that never fires", includes=CM,
  src="""
DPGEN_KERNEL void r5_pin_lower_bound_2(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 2; i < n; ++i) {
    if (i == 2) out[0] = a[i] * a[i - 2];
    if (i == 1) out[1] = a[i];
  }
}""", params=a1(("out","2")))

K(name="pin_overwritten_by_later_iter", why="u[i] = a[i]; if (i == 0) u[n - 1] = b[0]; (iteration n - 1 overwrites it for n >= 2)", includes=CM,
  src="""
DPGEN_KERNEL void r5_pin_overwritten_by_later_iter(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* u, int n) {
  for (int i = 0; i < n; ++i) {
    u[i] = a[i] * a[i];
    if (i == 0) u[n - 1] = b[0] * 3.0;
  }
}""", params=ab(("u",N)))

K(name="pin_overwrites_earlier_iter", why="if (i == n - 1) u[0] = b[0]; u[i] = a[i]; (the pinned store wins for n >= 2, loses for n = 1)", includes=CM,
  src="""
DPGEN_KERNEL void r5_pin_overwrites_earlier_iter(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* u, int n) {
  for (int i = 0; i < n; ++i) {
    if (i == n - 1) u[0] = b[0] * 3.0;
    u[i] = a[i] * a[i];
  }
}""", params=ab(("u",N)))

K(name="pin_le_bound", why="for (i = 0; i <= n; i++) if (i == n) out[0] = ...", includes=CM,
  src="""
DPGEN_KERNEL void r5_pin_le_bound(DPGEN_IN const double* a, DPGEN_OUT double* u, DPGEN_OUT double* out, int n) {
  for (int i = 0; i <= n; i++) {
    u[i] = a[i] * 2.0;
    if (i == n) out[0] = a[i] * a[i];
  }
}""", params=[("in","a","n + 1"),("out","u","n + 1"),("out","out","1"),("val","n")])

K(name="pin_unsigned_countdown", why="for (size_t i = n; i-- > 0;) if (i == 0) out[0] = ...", includes=CM + "#include <cstddef>\n",
  src="""
DPGEN_KERNEL void r5_pin_unsigned_countdown(DPGEN_IN const double* a, DPGEN_OUT double* u, DPGEN_OUT double* out, std::size_t n) {
  for (std::size_t i = n; i-- > 0;) {
    u[i] = a[i] * a[i];
    if (i == 0) out[0] = a[0] + a[n - 1];
  }
}""", params=[("in","a",N),("out","u",N),("out","out","1"),("val","std::size_t(n)")])

K(name="pin_flag_conj", why="if (i == n - 1 && flag) with a parameter flag", includes=CM,
  loop="for (int flag : {0, 1}) for (int n : {0, 1, 2, 5})", pre="CAPTURE(flag);",
  src="""
DPGEN_KERNEL void r5_pin_flag_conj(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, int flag) {
  out[0] = 0.0;
  for (int i = 0; i < n; ++i)
    if (i == n - 1 && flag) out[0] = a[i] * a[i];
}""", params=[("in","a",N),("out","out","1"),("val","n"),("val","flag")])

K(name="pin_data_conj", why="if (i == 0 && a[0] > 0): pinned and data-dependent", includes=CM,
  src="""
DPGEN_KERNEL void r5_pin_data_conj(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    if (i == 0 && a[i] > 0.0) out[0] = a[i] * a[i];
}""", params=P_A1)

K(name="pin_readback", why="if (i == n - 1) { out[0] = a[i]; out[0] = out[0] * out[0]; }", includes=CM,
  src="""
DPGEN_KERNEL void r5_pin_readback(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    if (i == n - 1) {
      out[0] = a[i] + 1.0;
      out[0] = out[0] * out[0];
    }
}""", params=P_A1)

K(name="pin_macro_idx", why="#define LAST (n - 1); if (i == LAST) and IDX-based pinned element", includes=CM + "#define LAST (n - 1)\n#define IDX(i) ((i) + 1)\n",
  src="""
DPGEN_KERNEL void r5_pin_macro_idx(DPGEN_IN const double* a, DPGEN_OUT double* u, int n) {
  int i;
  for (i = 0; i < n; i++) {
    u[IDX(i)] = a[i] * a[i];
    if (i == LAST) u[0] = a[LAST] - a[0];
  }
}""", params=a1(("u","n + 1")))

# ======================================================== later writer wins
K(name="lw_basic_then_next", why="K[j] = f; K[j + 1] = g;", includes=CM,
  src="""
DPGEN_KERNEL void r5_lw_basic_then_next(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* K, int n) {
  for (int j = 0; j < n; ++j) {
    K[j] = a[j] * b[j];
    K[j + 1] = std::sin(a[j]) + b[j];
  }
}""", params=ab(("K","n + 1")))

K(name="lw_next_then_basic", why="K[j + 1] = g; K[j] = f; (order reversed)", includes=CM,
  src="""
DPGEN_KERNEL void r5_lw_next_then_basic(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* K, int n) {
  for (int j = 0; j < n; ++j) {
    K[j + 1] = std::sin(a[j]) + b[j];
    K[j] = a[j] * b[j];
  }
}""", params=ab(("K","n + 1")))

K(name="lw_countdown", why="count-down loop: K[j] = f; K[j + 1] = g; now the K[j + 1] of iteration j - 1... wins", includes=CM,
  src="""
DPGEN_KERNEL void r5_lw_countdown(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* K, int n) {
  for (int j = n - 1; j >= 0; --j) {
    K[j] = a[j] * b[j];
    K[j + 1] = std::sin(a[j]) + b[j];
  }
}""", params=ab(("K","n + 1")))

K(name="lw_countdown_c89_minus", why="C89 count-down with a negative shift: K[j] = f; K[j - 1] = g;", includes=CM,
  src="""
DPGEN_KERNEL void r5_lw_countdown_c89_minus(DPGEN_IN const double* a, DPGEN_OUT double* K, int n) {
  int j;
  for (j = n; j >= 1; j--) {
    K[j] = a[j] * a[j];
    K[j - 1] = 2.0 * a[j] + a[j - 1];
  }
}""", params=[("in","a","n + 1"),("out","K","n + 1"),("val","n")])

K(name="lw_minus_shift", why="K[j] = f; K[j - 1] = g; for j = 1..n-1", includes=CM,
  src="""
DPGEN_KERNEL void r5_lw_minus_shift(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* K, int n) {
  for (int j = 1; j < n; ++j) {
    K[j] = a[j] * a[j];
    K[j - 1] = b[j] * a[j - 1];
  }
}""", params=ab(("K",N)))

K(name="lw_three_stores", why="K[j] = f; K[j + 1] = g; K[j + 2] = h;", includes=CM,
  src="""
DPGEN_KERNEL void r5_lw_three_stores(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* K, int n) {
  for (int j = 0; j < n; ++j) {
    K[j] = a[j] * a[j];
    K[j + 1] = b[j] * a[j];
    K[j + 2] = std::exp(b[j]);
  }
}""", params=ab(("K","n + 2")))

K(name="lw_three_stores_rev", why="K[j + 2] = h; K[j + 1] = g; K[j] = f;", includes=CM,
  src="""
DPGEN_KERNEL void r5_lw_three_stores_rev(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* K, int n) {
  for (int j = 0; j < n; ++j) {
    K[j + 2] = std::exp(b[j]);
    K[j + 1] = b[j] * a[j];
    K[j] = a[j] * a[j];
  }
}""", params=ab(("K","n + 2")))

K(name="lw_stride2_overlap", why="for (j = 0; j < n; j += 2) { K[j] = f; K[j + 2] = g; }", includes=CM,
  src="""
DPGEN_KERNEL void r5_lw_stride2_overlap(DPGEN_IN const double* a, DPGEN_OUT double* K, int n) {
  for (int j = 0; j < n; j += 2) {
    K[j] = a[j] * a[j];
    K[j + 2] = std::sin(a[j]);
  }
}""", params=[("in","a",N),("out","K","n + 2"),("val","n")])

K(name="lw_stride2_no_overlap_odd_shift", why="for (j = 0; j < n; j += 2) { K[j] = f; K[j + 3] = g; }: never the same element (parity)", includes=CM,
  src="""
DPGEN_KERNEL void r5_lw_stride2_no_overlap_odd_shift(DPGEN_IN const double* a, DPGEN_OUT double* K, int n) {
  for (int j = 0; j < n; j += 2) {
    K[j + 3] = std::sin(a[j]);
    K[j] = a[j] * a[j];
  }
}""", params=[("in","a",N),("out","K","n + 3"),("val","n")])

K(name="lw_stride2_shift1_partial", why="for (j = 0; j < n; j += 2) { K[j] = f; K[j + 1] = g; K[j + 2] = h; }", includes=CM,
  src="""
DPGEN_KERNEL void r5_lw_stride2_shift1_partial(DPGEN_IN const double* a, DPGEN_OUT double* K, int n) {
  for (int j = 0; j < n; j += 2) {
    K[j] = a[j] * a[j];
    K[j + 1] = 3.0 * a[j];
    K[j + 2] = std::cos(a[j]);
  }
}""", params=[("in","a",N),("out","K","n + 2"),("val","n")])

K(name="lw_coef2_overlap", why="K[2 * j] = f; K[2 * j + 2] = g;", includes=CM,
  src="""
DPGEN_KERNEL void r5_lw_coef2_overlap(DPGEN_IN const double* a, DPGEN_OUT double* K, int n) {
  for (int j = 0; j < n; ++j) {
    K[2 * j + 2] = std::sin(a[j]);
    K[2 * j] = a[j] * a[j];
  }
}""", params=[("in","a",N),("out","K","2 * n + 2"),("val","n")])

K(name="lw_coef2_odd_shift", why="K[2 * j] = f; K[2 * j + 3] = g; (never the same element)", includes=CM,
  src="""
DPGEN_KERNEL void r5_lw_coef2_odd_shift(DPGEN_IN const double* a, DPGEN_OUT double* K, int n) {
  for (int j = 0; j < n; ++j) {
    K[2 * j + 3] = std::sin(a[j]);
    K[2 * j] = a[j] * a[j];
  }
}""", params=[("in","a",N),("out","K","2 * n + 3"),("val","n")])

K(name="lw_pinned_shift_mix", why="K[j + 1] = f(j); if (j == 0) K[0] = g;", includes=CM,
  src="""
DPGEN_KERNEL void r5_lw_pinned_shift_mix(DPGEN_IN const double* a, DPGEN_OUT double* K, int n) {
  for (int j = 0; j < n; ++j) {
    K[j + 1] = a[j] * a[j];
    if (j == 0) K[0] = std::exp(a[0]);
  }
}""", params=[("in","a",N),("out","K","n + 1"),("val","n")])

K(name="lw_pinned_overwrites_shift", why="K[j] = f; K[j + 1] = g; if (j == n - 1) K[0] = h; (pinned store onto K[0] of iteration 0)", includes=CM,
  src="""
DPGEN_KERNEL void r5_lw_pinned_overwrites_shift(DPGEN_IN const double* a, DPGEN_OUT double* K, int n) {
  for (int j = 0; j < n; ++j) {
    K[j] = a[j] * a[j];
    K[j + 1] = 2.0 * a[j];
    if (j == n - 1) K[0] = std::sin(a[j]);
  }
}""", params=[("in","a",N),("out","K","n + 1"),("val","n")])

K(name="lw_cond_data_overwritten", why="if (a[j] > 0) K[j + 1] = g; K[j] = f; (the overwritten store conditional)", includes=CM,
  src="""
DPGEN_KERNEL void r5_lw_cond_data_overwritten(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* K, int n) {
  for (int j = 0; j < n; ++j) {
    if (a[j] > 0.0) K[j + 1] = b[j] * b[j];
    K[j] = a[j] * b[j];
  }
}""", params=ab(("K","n + 1")))

K(name="lw_cond_index_overwriter", expect="reject", why="K[j + 1] = g; if (j > 0) K[j] = f; (a conditional overwrite, on the index)", includes=CM,
  src="""
DPGEN_KERNEL void r5_lw_cond_index_overwriter(DPGEN_IN const double* a, DPGEN_OUT double* K, int n) {
  for (int j = 0; j < n; ++j) {
    K[j + 1] = a[j] * a[j];
    if (j > 0) K[j] = std::sin(a[j]);
  }
}""", params=[("in","a",N),("out","K","n + 1"),("val","n")])

K(name="lw_eq_then_pluseq", why="K[j] = f; K[j + 1] += g; (the += is overwritten by the next iteration's =)", includes=CM,
  src="""
DPGEN_KERNEL void r5_lw_eq_then_pluseq(DPGEN_IN const double* a, DPGEN_OUT double* K, int n) {
  for (int j = 0; j < n; ++j) {
    K[j] = a[j] * a[j];
    K[j + 1] += 2.0 * a[j];
  }
}""", params=[("in","a",N),("out","K","n + 1"),("val","n")])

K(name="lw_next_then_pluseq", why="K[j + 1] = g; K[j] += f; (K[j] = g(j - 1) + f(j))", includes=CM,
  src="""
DPGEN_KERNEL void r5_lw_next_then_pluseq(DPGEN_IN const double* a, DPGEN_OUT double* K, int n) {
  for (int j = 0; j < n; ++j) {
    K[j + 1] = std::sin(a[j]);
    K[j] += a[j] * a[j];
  }
}""", params=[("in","a",N),("out","K","n + 1"),("val","n")])

K(name="lw_reads_prev_iter", expect="reject", why="K[j + 1] = a[j]; K[j] = K[j] + b[j]; (reads what the previous iteration stored)", includes=CM, loop=L1p,
  src="""
DPGEN_KERNEL void r5_lw_reads_prev_iter(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* K, int n) {
  K[0] = 1.0;
  for (int j = 0; j < n; ++j) {
    K[j + 1] = a[j] * a[j];
    K[j] = K[j] * b[j];
  }
}""", params=ab(("K","n + 1")))

K(name="lw_readback_same_iter", why="K[j] = a; K[j + 1] = K[j] * b; (readback in the iteration)", includes=CM,
  src="""
DPGEN_KERNEL void r5_lw_readback_same_iter(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* K, int n) {
  for (int j = 0; j < n; ++j) {
    K[j] = a[j] * a[j];
    K[j + 1] = K[j] * b[j];
  }
}""", params=ab(("K","n + 1")))

K(name="lw_rowwise_2d", why="rows of length nx + 1: K[j*(nx+1) + i] = f; K[j*(nx+1) + i + 1] = g; (meet within a row only)", includes=CM, loop=L2,
  src="""
DPGEN_KERNEL void r5_lw_rowwise_2d(DPGEN_IN const double* a, DPGEN_OUT double* K, int nx, int ny) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      K[j * (nx + 1) + i] = a[j * nx + i] * a[j * nx + i];
      K[j * (nx + 1) + i + 1] = std::sin(a[j * nx + i]);
    }
}""", params=[("in","a","n*m"),("out","K","(n + 1) * m"),("val","n"),("val","m")])

K(name="lw_then_statement", why="the loop's pair, then K[0] = h after the loop", includes=CM,
  src="""
DPGEN_KERNEL void r5_lw_then_statement(DPGEN_IN const double* a, DPGEN_OUT double* K, int n) {
  for (int j = 0; j < n; ++j) {
    K[j] = a[j] * a[j];
    K[j + 1] = 2.0 * a[j];
  }
  K[0] = 0.5;
}""", params=[("in","a",N),("out","K","n + 1"),("val","n")])

K(name="lw_two_loops_overwrite", why="for j: K[j] = f; for j: K[j + 1] = g; (a later loop overwrites: a run-time check throws for n >= 2)", includes=CM,
  loop="for (int n : {0, 1})",
  cases="""TEST_CASE("adversary: r5_lw_two_loops_overwrite n = 2 throws") {
  std::vector<double> a(2, 0.5), a_adj(2, 0.0), K_seed(3, 1.0);
  CHECK_THROWS_AS(r5_lw_two_loops_overwrite_adjoint(a.data(), a_adj.data(), K_seed.data(), 2), std::invalid_argument);
}""",
  src="""
DPGEN_KERNEL void r5_lw_two_loops_overwrite(DPGEN_IN const double* a, DPGEN_OUT double* K, int n) {
  for (int j = 0; j < n; ++j) K[j] = a[j] * a[j];
  for (int j = 0; j < n; ++j) K[j + 1] = std::sin(a[j]);
}""", params=[("in","a",N),("out","K","n + 1"),("val","n")])

K(name="lw_idx_macro", why="IDX macro shift: K[IDX(j) - 1] = f; K[IDX(j)] = g;", includes=CM + "#define IDX(j) ((j) + 1)\n",
  src="""
DPGEN_KERNEL void r5_lw_idx_macro(DPGEN_IN const double* a, DPGEN_OUT double* K, int n) {
  int j;
  for (j = 0; j < n; j++) {
    K[IDX(j) - 1] = a[j] * a[j];
    K[IDX(j)] = std::cos(a[j]);
  }
}""", params=[("in","a",N),("out","K","n + 1"),("val","n")])

K(name="lw_param_shift", why="K[j] = f; K[j + s] = g; with s a parameter (0, 1, 2)", includes=CM,
  loop="for (auto [n, s] : {std::pair{0, 1}, {1, 2}, {2, 2}, {1, 1}})", pre="CAPTURE(s);",
  cases="""TEST_CASE("adversary: r5_lw_param_shift overlapping throws") {
  // s = 0 (both stores on one element) and n > s (the stores meet across iterations): a run-time error
  std::vector<double> a(3, 0.5), a_adj(3, 0.0), K_seed(5, 1.0);
  CHECK_THROWS_AS(r5_lw_param_shift_adjoint(a.data(), a_adj.data(), K_seed.data(), 3, 0), std::invalid_argument);
  CHECK_THROWS_AS(r5_lw_param_shift_adjoint(a.data(), a_adj.data(), K_seed.data(), 3, 1), std::invalid_argument);
}""",
  src="""
DPGEN_KERNEL void r5_lw_param_shift(DPGEN_IN const double* a, DPGEN_OUT double* K, int n, int s) {
  for (int j = 0; j < n; ++j) {
    K[j] = a[j] * a[j];
    K[j + s] = std::sin(a[j]);
  }
}""", params=[("in","a",N),("out","K","n + 2"),("val","n"),("val","s")])

K(name="lw_same_iter_twice_plus_next", why="K[j + 1] = g1; K[j + 1] = g2 * K[j + 1]; K[j] = f;", includes=CM,
  src="""
DPGEN_KERNEL void r5_lw_same_iter_twice_plus_next(DPGEN_IN const double* a, DPGEN_OUT double* K, int n) {
  for (int j = 0; j < n; ++j) {
    K[j + 1] = a[j] + 1.0;
    K[j + 1] = K[j + 1] * a[j];
    K[j] = std::exp(a[j]);
  }
}""", params=[("in","a",N),("out","K","n + 1"),("val","n")])

K(name="lw_guard_shorter_loop", why="if (n < 2) return; for (j = 0; j < n - 1; j++) { K[j] = ..; K[j + 1] = ..; }", includes=CM,
  src="""
DPGEN_KERNEL void r5_lw_guard_shorter_loop(DPGEN_IN const double* a, DPGEN_OUT double* K, int n) {
  if (n < 2) return;
  for (int j = 0; j < n - 1; j++) {
    K[j] = a[j] * a[j + 1];
    K[j + 1] = a[j + 1] - a[j];
  }
}""", params=[("in","a",N),("out","K",N),("val","n")])

K(name="lw_work_array_then_read", why="a later-writer pair fills a work array that a later loop reads", includes=CM,
  src="""
DPGEN_KERNEL void r5_lw_work_array_then_read(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* w, DPGEN_OUT double* out, int n) {
  for (int j = 0; j < n; ++j) {
    w[j] = a[j] * b[j];
    w[j + 1] = a[j] + b[j];
  }
  for (int i = 0; i < n; ++i) out[i] = w[i] * w[i + 1];
}""", params=ab(("w","n + 1"),("out",N)))

K(name="lw_tridiag_setup", why="tridiagonal setup as codes write it: diag/upper of row j and a guess of row j + 1", includes=CM,
  src="""
DPGEN_KERNEL void r5_lw_tridiag_setup(DPGEN_IN const double* k, DPGEN_OUT double* d, DPGEN_OUT double* up, int n) {
  int j;
  for (j = 0; j < n; j++) {
    d[j] = k[j] + k[j + 1];
    up[j] = -k[j + 1];
    d[j + 1] = k[j + 1];
  }
}""", params=[("in","k","n + 1"),("out","d","n + 1"),("out","up",N),("val","n")])

K(name="lw_unsigned_countdown", why="for (size_t j = n; j-- > 0;) { K[j] = f; K[j + 1] = g; }", includes=CM + "#include <cstddef>\n",
  src="""
DPGEN_KERNEL void r5_lw_unsigned_countdown(DPGEN_IN const double* a, DPGEN_OUT double* K, std::size_t n) {
  for (std::size_t j = n; j-- > 0;) {
    K[j] = a[j] * a[j];
    K[j + 1] = std::sin(a[j]);
  }
}""", params=[("in","a",N),("out","K","n + 1"),("val","std::size_t(n)")])

K(name="lw_pair_in_param_arm", why="the pair inside an arm of an if on a parameter; the other arm writes K[j] only", includes=CM,
  loop="for (int flag : {0, 1}) for (int n : {0, 1, 2, 3, 7})", pre="CAPTURE(flag);",
  src="""
DPGEN_KERNEL void r5_lw_pair_in_param_arm(DPGEN_IN const double* a, DPGEN_OUT double* K, int n, int flag) {
  if (flag == 1) {
    for (int j = 0; j < n; ++j) {
      K[j] = a[j] * a[j];
      K[j + 1] = std::sin(a[j]);
    }
  } else {
    for (int j = 0; j < n; ++j) K[j] = 3.0 * a[j];
    K[n] = 1.0;
  }
}""", params=[("in","a",N),("out","K","n + 1"),("val","n"),("val","flag")])

# ======================================================== in place across nests
INC = CM + "#define IDX(i, j) ((j) * nx + (i))\n"
K(name="ip_upwind_c89_macros", why="fluxes from the old rho (C89, macros), then rho updated in place on the interior", includes=CM + "#define UP(u, l, r) ((u) > 0.0 ? (u) * (l) : (u) * (r))\n",
  loop="for (int n : {0, 1, 2, 3, 4, 9})",
  src="""
DPGEN_KERNEL void r5_ip_upwind_c89_macros(DPGEN_INOUT double* rho, DPGEN_IN const double* u, DPGEN_OUT double* flux, int n, double dt) {
  int i;
  for (i = 1; i < n; i++)
    flux[i] = UP(u[i], rho[i - 1], rho[i]);
  for (i = 1; i < n - 1; i++)
    rho[i] = rho[i] - dt * (flux[i + 1] - flux[i]);
}""", params=[("io","rho",N),("in","u",N),("out","flux","n + 1"),("val","n"),("val","0.3")])

K(name="ip_2d_fluxes_omp", why="2D x/y fluxes from the old q (IDX macro, omp), then q updated in place", includes=INC, loop=L2,
  src="""
DPGEN_KERNEL void r5_ip_2d_fluxes_omp(DPGEN_INOUT double* q, DPGEN_OUT double* fx, DPGEN_OUT double* fy, int nx, int ny, double c) {
  int i, j;
#pragma omp parallel for private(i)
  for (j = 0; j < ny; j++)
    for (i = 1; i < nx; i++)
      fx[IDX(i, j)] = c * (q[IDX(i, j)] - q[IDX(i - 1, j)]);
#pragma omp parallel for private(i)
  for (j = 1; j < ny; j++)
    for (i = 0; i < nx; i++)
      fy[IDX(i, j)] = c * (q[IDX(i, j)] - q[IDX(i, j - 1)]) * q[IDX(i, j)];
#pragma omp parallel for private(i)
  for (j = 1; j < ny - 1; j++)
    for (i = 1; i < nx - 1; i++)
      q[IDX(i, j)] += fx[IDX(i + 1, j)] - fx[IDX(i, j)] + fy[IDX(i, j + 1)] - fy[IDX(i, j)];
}""", params=[("io","q","n*m"),("out","fx","n*m"),("out","fy","n*m"),("val","n"),("val","m"),("val","0.2")])

K(name="ip_normalize_by_max", why="a max of |v| (min/max reduction) of the old values, then v rescaled in place", includes=CM,
  src="""
DPGEN_KERNEL void r5_ip_normalize_by_max(DPGEN_INOUT double* v, int n) {
  double m = 0.0;
  for (int i = 0; i < n; ++i) m = fmax(m, fabs(v[i]));
  for (int i = 0; i < n; ++i) v[i] = v[i] / (1.0 + m);
}""", params=[("io","v",N),("val","n")])

K(name="ip_normalize_by_max_err_out", why="*err = max |v - t| of the old values (output reduction), then v = t in place blended", includes=CM,
  src="""
DPGEN_KERNEL void r5_ip_normalize_by_max_err_out(DPGEN_INOUT double* v, DPGEN_IN const double* t, DPGEN_OUT double* err, int n) {
  *err = 0.0;
  for (int i = 0; i < n; ++i) *err = fmax(*err, fabs(v[i] - t[i]));
  for (int i = 0; i < n; ++i) v[i] = 0.5 * (v[i] + t[i] * t[i]);
}""", params=[("io","v",N),("in","t",N),("out","err","1"),("val","n")])

K(name="ip_rownorm_per_row", why="per-row accumulator of the old row, then the row rescaled in place (one outer loop)", includes=INC, loop=L2,
  src="""
DPGEN_KERNEL void r5_ip_rownorm_per_row(DPGEN_INOUT double* u, int nx, int ny) {
  for (int j = 0; j < ny; ++j) {
    double s = 1.0;
    for (int i = 0; i < nx; ++i) s += u[IDX(i, j)] * u[IDX(i, j)];
    const double inv = 1.0 / std::sqrt(s);
    for (int i = 0; i < nx; ++i) u[IDX(i, j)] *= inv;
  }
}""", params=[("io","u","n*m"),("val","n"),("val","m")])

K(name="ip_rowmax_per_row", why="per-row max of the old row, then the row divided in place", includes=INC, loop=L2,
  src="""
DPGEN_KERNEL void r5_ip_rowmax_per_row(DPGEN_INOUT double* u, int nx, int ny) {
  for (int j = 0; j < ny; ++j) {
    double m = 0.5;
    for (int i = 0; i < nx; ++i) m = std::max(m, std::fabs(u[IDX(i, j)]));
    for (int i = 0; i < nx; ++i) u[IDX(i, j)] = u[IDX(i, j)] / m;
  }
}""", params=[("io","u","n*m"),("val","n"),("val","m")])

K(name="ip_reads_prev_row_new", expect="reject", why="per row: an accumulator reads row j - 1, which the previous outer iteration already updated (new values)", includes=INC, loop=L2,
  src="""
DPGEN_KERNEL void r5_ip_reads_prev_row_new(DPGEN_INOUT double* u, int nx, int ny) {
  for (int j = 1; j < ny; ++j) {
    double s = 0.0;
    for (int i = 0; i < nx; ++i) s += u[IDX(i, j - 1)];
    for (int i = 0; i < nx; ++i) u[IDX(i, j)] = u[IDX(i, j)] + 0.1 * s * s;
  }
}""", params=[("io","u","n*m"),("val","n"),("val","m")])

K(name="ip_reads_next_row_old", why="per row: an accumulator reads row j + 1 (not yet updated: old values), then row j updated", includes=INC, loop=L2,
  src="""
DPGEN_KERNEL void r5_ip_reads_next_row_old(DPGEN_INOUT double* u, int nx, int ny) {
  for (int j = 0; j < ny - 1; ++j) {
    double s = 0.0;
    for (int i = 0; i < nx; ++i) s += u[IDX(i, j + 1)];
    for (int i = 0; i < nx; ++i) u[IDX(i, j)] = u[IDX(i, j)] + 0.1 * s * s;
  }
}""", params=[("io","u","n*m"),("val","n"),("val","m")])

K(name="ip_cond_update", why="fluxes from the old values, then a conditional update in place", includes=CM,
  src="""
DPGEN_KERNEL void r5_ip_cond_update(DPGEN_INOUT double* u, DPGEN_OUT double* f, int n) {
  for (int i = 0; i + 1 < n; ++i) f[i] = u[i + 1] * u[i + 1] - u[i];
  for (int i = 0; i + 1 < n; ++i)
    if (f[i] > 0.0) u[i] -= 0.25 * f[i];
}""", params=[("io","u",N),("out","f",N),("val","n")])

K(name="ip_reversed_read", why="a work array from u[n - 1 - i], then u[i] updated from it", includes=CM,
  src="""
DPGEN_KERNEL void r5_ip_reversed_read(DPGEN_INOUT double* u, DPGEN_OUT double* w, int n) {
  for (int i = 0; i < n; ++i) w[i] = u[n - 1 - i] * u[i];
  for (int i = 0; i < n; ++i) u[i] = w[i] + 0.5 * u[i];
}""", params=[("io","u",N),("out","w",N),("val","n")])

K(name="ip_cyclic_shift", why="a cyclic shift in place through a work array (the update does not read u)", includes=CM,
  src="""
DPGEN_KERNEL void r5_ip_cyclic_shift(DPGEN_INOUT double* u, DPGEN_OUT double* w, int n) {
  for (int i = 0; i < n; ++i) w[i] = u[i == n - 1 ? 0 : i + 1];
  for (int i = 0; i < n; ++i) u[i] = w[i] * w[i];
}""", params=[("io","u",N),("out","w",N),("val","n")])

K(name="ip_read_after_update", expect="reject", why="a loop reads u after the loop that updated it", includes=CM,
  src="""
DPGEN_KERNEL void r5_ip_read_after_update(DPGEN_INOUT double* u, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) u[i] = u[i] * u[i];
  double s = 0.0;
  for (int i = 0; i < n; ++i) s += u[i];
  out[0] = s;
}""", params=[("io","u",N),("out","out","1"),("val","n")])

K(name="ip_two_updates", expect="reject", why="two pointwise update loops in turn (the second reads the first's new values)", includes=CM,
  src="""
DPGEN_KERNEL void r5_ip_two_updates(DPGEN_INOUT double* u, int n) {
  for (int i = 0; i < n; ++i) u[i] = u[i] * u[i];
  for (int i = 0; i < n; ++i) u[i] = u[i] + 1.0;
}""", params=[("io","u",N),("val","n")])

K(name="ip_update_reads_neighbour", expect="reject", why="the update loop reads u[i - 1] (Gauss-Seidel)", includes=CM,
  src="""
DPGEN_KERNEL void r5_ip_update_reads_neighbour(DPGEN_INOUT double* u, DPGEN_OUT double* f, int n) {
  for (int i = 0; i < n; ++i) f[i] = u[i] * u[i];
  for (int i = 1; i < n; ++i) u[i] = 0.5 * (u[i] + u[i - 1]) + f[i];
}""", params=[("io","u",N),("out","f",N),("val","n")])

K(name="ip_two_inout", why="two in-place arrays exchanging through a work array: f = u - v; u -= f; v += f", includes=CM,
  src="""
DPGEN_KERNEL void r5_ip_two_inout(DPGEN_INOUT double* u, DPGEN_INOUT double* v, DPGEN_OUT double* f, int n) {
  for (int i = 0; i < n; ++i) f[i] = 0.5 * (u[i] - v[i]) * u[i];
  for (int i = 0; i < n; ++i) u[i] -= f[i];
  for (int i = 0; i < n; ++i) v[i] += f[i] * v[i];
}""", params=[("io","u",N),("io","v",N),("out","f",N),("val","n")])

K(name="ip_heat_lap_work", why="explicit heat step in place: lap from the old u (IDX, C89), then u += dt * lap", includes=INC, loop=L2,
  src="""
DPGEN_KERNEL void r5_ip_heat_lap_work(DPGEN_INOUT double* u, DPGEN_OUT double* lap, int nx, int ny, double dt) {
  int i, j;
  for (j = 1; j < ny - 1; j++)
    for (i = 1; i < nx - 1; i++)
      lap[IDX(i, j)] = u[IDX(i - 1, j)] + u[IDX(i + 1, j)] + u[IDX(i, j - 1)] + u[IDX(i, j + 1)] - 4.0 * u[IDX(i, j)];
  for (j = 1; j < ny - 1; j++)
    for (i = 1; i < nx - 1; i++)
      u[IDX(i, j)] = u[IDX(i, j)] + dt * lap[IDX(i, j)] * (1.0 + u[IDX(i, j)] * u[IDX(i, j)]);
}""", params=[("io","u","n*m"),("out","lap","n*m"),("val","n"),("val","m"),("val","0.1")])

K(name="ip_work_accum_between", why="a work array from u, an accumulator over the work array, then u updated from both", includes=CM,
  src="""
DPGEN_KERNEL void r5_ip_work_accum_between(DPGEN_INOUT double* u, DPGEN_IN const double* a, DPGEN_OUT double* w, int n) {
  for (int i = 0; i < n; ++i) w[i] = u[i] * a[i];
  double s = 0.0;
  for (int i = 0; i < n; ++i) s += w[i] * w[i];
  for (int i = 0; i < n; ++i) u[i] = u[i] - 0.1 * s * w[i];
}""", params=[("io","u",N),("in","a",N),("out","w",N),("val","n")])

K(name="ip_diag_output_old", why="a diagnostic output from the old values (energy), and a pinned first value, then the update", includes=CM,
  src="""
DPGEN_KERNEL void r5_ip_diag_output_old(DPGEN_INOUT double* u, DPGEN_OUT double* diag, int n) {
  diag[0] = 0.0;
  for (int i = 0; i < n; ++i) {
    diag[0] += 0.5 * u[i] * u[i];
    if (i == 0) diag[1] = u[0];
  }
  for (int i = 0; i < n; ++i) u[i] = std::sin(u[i]);
}""", params=[("io","u",N),("out","diag","2"),("val","n")])

K(name="ip_countdown_update", why="fluxes, then the update in a loop counting down", includes=CM,
  src="""
DPGEN_KERNEL void r5_ip_countdown_update(DPGEN_INOUT double* u, DPGEN_OUT double* f, int n) {
  for (int i = 0; i < n; ++i) f[i] = u[i] * u[n - 1 - i];
  for (int i = n - 1; i >= 0; --i) u[i] = u[i] + f[i];
}""", params=[("io","u",N),("out","f",N),("val","n")])

K(name="ip_strided_update", why="fluxes from all of u, then every other element updated in place", includes=CM,
  src="""
DPGEN_KERNEL void r5_ip_strided_update(DPGEN_INOUT double* u, DPGEN_OUT double* f, int n) {
  for (int i = 0; i + 1 < n; ++i) f[i] = u[i + 1] - u[i];
  for (int i = 0; i + 1 < n; i += 2) u[i] = u[i] * (1.0 + f[i]);
}""", params=[("io","u",N),("out","f",N),("val","n")])

K(name="ip_float_fluxes", why="float in-place update with fluxes", T="float", includes=CM,
  src="""
DPGEN_KERNEL void r5_ip_float_fluxes(DPGEN_INOUT float* rho, DPGEN_OUT float* flux, int n) {
  for (int i = 1; i < n; ++i) flux[i] = 0.5f * (rho[i] * rho[i] - rho[i - 1]);
  for (int i = 1; i < n - 1; ++i) rho[i] -= 0.3f * (flux[i + 1] - flux[i]);
}""", params=[("io","rho",N),("out","flux",N),("val","n")])

K(name="ip_boundary_flux_pinned", why="fluxes with boundary values pinned to the first/last iterations, then the update", includes=CM,
  src="""
DPGEN_KERNEL void r5_ip_boundary_flux_pinned(DPGEN_INOUT double* u, DPGEN_OUT double* f, int n) {
  for (int i = 0; i <= n; ++i) {
    if (i == 0) f[0] = u[0] * u[0];
    else if (i == n) f[n] = -u[n - 1];
    else f[i] = 0.5 * (u[i] - u[i - 1]);
  }
  for (int i = 0; i < n; ++i) u[i] -= 0.2 * (f[i + 1] - f[i]);
}""", params=[("io","u",N),("out","f","n + 1"),("val","n")])

K(name="ip_helper_flux", why="fluxes through a limiter helper, then the update in place", includes=CM + """
static inline double minmod(double a, double b) { return a * b <= 0.0 ? 0.0 : (std::fabs(a) < std::fabs(b) ? a : b); }
""",
  src="""
DPGEN_KERNEL void r5_ip_helper_flux(DPGEN_INOUT double* u, DPGEN_OUT double* f, int n) {
  for (int i = 1; i < n - 1; ++i) f[i] = u[i] + 0.5 * minmod(u[i] - u[i - 1], u[i + 1] - u[i]);
  for (int i = 2; i < n - 1; ++i) u[i] -= 0.4 * (f[i] - f[i - 1]);
}""", params=[("io","u",N),("out","f",N),("val","n")])

K(name="ip_lambda_flux", why="fluxes through a lambda, then the update", includes=CM,
  src="""
DPGEN_KERNEL void r5_ip_lambda_flux(DPGEN_INOUT double* u, DPGEN_OUT double* f, int n) {
  auto flx = [&](int i) { return 0.5 * (u[i] * u[i] + u[i + 1] * u[i + 1]); };
  for (int i = 0; i + 1 < n; ++i) f[i] = flx(i);
  for (int i = 1; i + 1 < n; ++i) u[i] -= 0.1 * (f[i] - f[i - 1]);
}""", params=[("io","u",N),("out","f",N),("val","n")])

K(name="ip_lastwriter_work", why="a later-writer pair fills the work array from the old values, then the update", includes=CM,
  src="""
DPGEN_KERNEL void r5_ip_lastwriter_work(DPGEN_INOUT double* u, DPGEN_OUT double* w, int n) {
  for (int j = 0; j < n; ++j) {
    w[j] = u[j] * u[j];
    w[j + 1] = 2.0 * u[j];
  }
  for (int i = 0; i < n; ++i) u[i] = u[i] + w[i + 1] - w[i];
}""", params=[("io","u",N),("out","w","n + 1"),("val","n")])

K(name="ip_rowptr_inout", expect="reject", why="double** in place: row fluxes from the old grid, then the update", includes=CM, loop=L2,
  src="""
DPGEN_KERNEL void r5_ip_rowptr_inout(DPGEN_INOUT double** u, DPGEN_OUT double* f, int nx, int ny) {
  for (int j = 0; j < ny; ++j)
    for (int i = 1; i < nx; ++i) f[j * nx + i] = u[j][i] - u[j][i - 1];
  for (int j = 0; j < ny; ++j)
    for (int i = 1; i < nx - 1; ++i) u[j][i] += 0.25 * (f[j * nx + i + 1] - f[j * nx + i]);
}""", params=[("io","u","n*m"),("out","f","n*m"),("val","n"),("val","m")], reject=True)

K(name="ip_old_in_update_and_work", why="the update reads u[i] and a work array from u[i + 1] and u[i - 1]", includes=CM,
  src="""
DPGEN_KERNEL void r5_ip_old_in_update_and_work(DPGEN_INOUT double* u, DPGEN_IN const double* k, DPGEN_OUT double* g, int n) {
  for (int i = 1; i < n - 1; ++i) g[i] = k[i] * (u[i + 1] - 2.0 * u[i] + u[i - 1]);
  for (int i = 1; i < n - 1; ++i) u[i] = u[i] * std::exp(-0.1 * g[i]);
}""", params=[("io","u",N),("in","k",N),("out","g",N),("val","n")])

# ======================================================== more min/max
K(name="mm_branchy_elem", why="the element is a data branch: fmax(m, a[i] > 0 ? a[i] : -2 * a[i])", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_branchy_elem(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = 0.0;
  for (int i = 0; i < n; ++i) m = fmax(m, a[i] > 0.0 ? a[i] : -2.0 * a[i]);
  out[0] = m * m;
}""", params=P_A1)

K(name="mm_gather_index", why="max over a[idx[i]] (a data-dependent read)", includes=CM,
  pre="std::vector<int> perm(static_cast<size_t>(n)); for (int q = 0; q < n; ++q) perm[size_t(q)] = (3 * q + 1) % n;",
  src="""
DPGEN_KERNEL void r5_mm_gather_index(DPGEN_IN const double* a, const int* idx, DPGEN_OUT double* out, int n) {
  double m = -4.0;
  for (int i = 0; i < n; ++i) m = fmax(m, a[idx[i]] * (1.0 + 0.1 * i));
  out[0] = m;
}""", params=[("in","a",N),("val","perm.data()"),("out","out","1"),("val","n")])

K(name="mm_local_from_data", why="the element uses a kernel-level local computed from data", includes=CM, loop=L1p,
  src="""
DPGEN_KERNEL void r5_mm_local_from_data(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  const double c = 1.0 + a[0] * a[0];
  double m = -4.0;
  for (int i = 0; i < n; ++i) m = fmax(m, c * b[i]);
  out[0] = m * c;
}""", params=P)

K(name="mm_rowmax_summed", why="per-row max fed into a sum over rows", includes=CM, loop=L2,
  src="""
DPGEN_KERNEL void r5_mm_rowmax_summed(DPGEN_IN const double* a, DPGEN_OUT double* out, int nx, int ny) {
  double tot = 0.0;
  for (int j = 0; j < ny; ++j) {
    double m = -1e3;
    for (int i = 0; i < nx; ++i) m = fmax(m, a[j * nx + i]);
    tot += m * m;
  }
  out[0] = tot;
}""", params=[("in","a","n*m"),("out","out","1"),("val","n"),("val","m")])

K(name="mm_max_of_rowmax", why="a global max of per-row maxima (a reduction over a reduction)", includes=CM, loop=L2,
  src="""
DPGEN_KERNEL void r5_mm_max_of_rowmax(DPGEN_IN const double* a, DPGEN_OUT double* out, int nx, int ny) {
  double gm = -1e3;
  for (int j = 0; j < ny; ++j) {
    double m = -1e3;
    for (int i = 0; i < nx; ++i) m = fmax(m, a[j * nx + i]);
    gm = fmax(gm, 2.0 * m);
  }
  out[0] = gm;
}""", params=[("in","a","n*m"),("out","out","1"),("val","n"),("val","m")],
  cases=tie_case("r5_mm_max_of_rowmax", "r5_mm_max_of_rowmax", [("in","a","n*m"),("out","out","1"),("val","n"),("val","m")],
                 {"a": [1.0, 3.0, 3.0, 0.0]}, {"n": "2", "m": "2"}, {"out": {0: 6.0}},
                 # row maxima 3 (a1) and 3 (a2): global tie, half each, times 2
                 {"a": [0, 1.0, 1.0, 0]}, "out"))

K(name="mm_normalised_max_is_one", why="m1 = max a; m2 = max a[i] / m1 (= 1): its derivative is zero", includes=CM,
  loop=L1p, ranges="{1.0, 2.0}",
  src="""
DPGEN_KERNEL void r5_mm_normalised_max_is_one(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m1 = 0.5;
  for (int i = 0; i < n; ++i) m1 = fmax(m1, a[i]);
  double m2 = 0.0;
  for (int i = 0; i < n; ++i) m2 = fmax(m2, a[i] / m1);
  out[0] = m2 + m1;
}""", params=P_A1)

K(name="mm_reduce_in_flag_arm", why="a reduction loop under if (flag), read after the if", includes=CM,
  loop="for (int flag : {0, 1}) for (int n : {0, 1, 3, 7})", pre="CAPTURE(flag);",
  src="""
DPGEN_KERNEL void r5_mm_reduce_in_flag_arm(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, int flag) {
  double m = 0.5;
  if (flag) {
    for (int i = 0; i < n; ++i) m = fmax(m, a[i] * a[i]);
  }
  out[0] = m * m;
}""", params=[("in","a",N),("out","out","1"),("val","n"),("val","flag")])

K(name="mm_two_if_updates", why="if (a[i] > m) m = a[i]; if (b[i] > m) m = b[i];", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_two_if_updates(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = -4.0;
  for (int i = 0; i < n; ++i) {
    if (a[i] > m) m = a[i];
    if (b[i] * b[i] > m) m = b[i] * b[i];
  }
  out[0] = m;
}""", params=P)

K(name="mm_if_else_store", expect="reject", why="if (e > m) m = e; else u[i] = m; (the else arm reads the running max)", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_if_else_store(DPGEN_IN const double* a, DPGEN_OUT double* u, DPGEN_OUT double* out, int n) {
  double m = -4.0;
  for (int i = 0; i < n; ++i) {
    u[i] = 0.0;
    if (a[i] > m) m = a[i];
    else u[i] = a[i] * 2.0;
  }
  out[0] = m;
}""", params=a1(("u",N),("out","1")))

K(name="mm_std_max_template_arg", why="std::max<double>(m, e) and std::fmax", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_std_max_template_arg(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = -4.0, q = -4.0;
  for (int i = 0; i < n; ++i) {
    m = std::max<double>(m, a[i] * a[i]);
    q = std::fmax(q, -a[i]);
  }
  out[0] = m + q * q;
}""", params=P_A1)

K(name="mm_index_cond_elem", why="the element uses the counter: fmax(m, i == 0 ? 0 : a[i] - a[i - 1])", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_index_cond_elem(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = -4.0;
  for (int i = 0; i < n; ++i) m = fmax(m, i == 0 ? 0.0 : a[i] - a[i - 1]);
  out[0] = m * m;
}""", params=P_A1)

K(name="mm_start_of_accumulator", why="the max starts a later accumulator: s = m; s += a[i]", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_start_of_accumulator(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = 0.0;
  for (int i = 0; i < n; ++i) m = fmax(m, a[i]);
  double s = m;
  for (int i = 0; i < n; ++i) s += a[i] * m;
  out[0] = s * s;
}""", params=P_A1)

K(name="mm_fma_sensitive", why="element a*b + c (FMA-contractible): the scan and the tie test must agree bit for bit", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_fma_sensitive(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_IN const double* c, DPGEN_OUT double* out, int n) {
  double m = -4.0;
  for (int i = 0; i < n; ++i) m = fmax(m, a[i] * b[i] + c[i]);
  out[0] = m;
}""", params=[("in","a",N),("in","b",N),("in","c",N),("out","out","1"),("val","n")])

# ======================================================== more pinned
K(name="pin_antidiag_same_elem", expect="reject", why="if (i + j == n - 1) s[0] = ...: n iterations store s[0]", includes=CM,
  src="""
DPGEN_KERNEL void r5_pin_antidiag_same_elem(DPGEN_IN const double* a, DPGEN_OUT double* s, int n) {
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (i + j == n - 1) s[0] = a[j * n + i] * a[j * n + i];
}""", params=[("in","a","n*n"),("out","s","1"),("val","n")])

K(name="pin_i_eq_2j_same_elem", expect="reject", why="if (i == 2 * j) s[0] = ...: several iterations store s[0]", includes=CM,
  src="""
DPGEN_KERNEL void r5_pin_i_eq_2j_same_elem(DPGEN_IN const double* a, DPGEN_OUT double* s, int n) {
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (i == 2 * j) s[0] = std::sin(a[j * n + i]);
}""", params=[("in","a","n*n"),("out","s","1"),("val","n")])

K(name="pin_antidiag_elem", why="if (i == n - 1 - j) anti[j] = ... (one per j)", includes=CM,
  src="""
DPGEN_KERNEL void r5_pin_antidiag_elem(DPGEN_IN const double* a, DPGEN_OUT double* anti, int n) {
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (i == n - 1 - j) anti[j] = a[j * n + i] * a[j * n + i];
}""", params=[("in","a","n*n"),("out","anti",N),("val","n")])

K(name="pin_diag_last_j", why="if (i == j && j == n - 1) c[0] = ...: one iteration", includes=CM,
  src="""
DPGEN_KERNEL void r5_pin_diag_last_j(DPGEN_IN const double* a, DPGEN_OUT double* c, int n) {
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (i == j && j == n - 1) c[0] = a[j * n + i] * a[j * n + i];
}""", params=[("in","a","n*n"),("out","c","1"),("val","n")])

K(name="pin_3d_two_counters", expect="reject", why="if (i == k) in a 3D nest storing e[j]: nz iterations per element", includes=CM,
  loop="for (int n : {0, 1, 2, 3})",
  src="""
DPGEN_KERNEL void r5_pin_3d_two_counters(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        if (i == k) e[j] = a[(k * n + j) * n + i] * a[(k * n + j) * n + i];
}""", params=[("in","a","n*n*n"),("out","e",N),("val","n")])

# ======================================================== minimal reproducers
K(name="min_helper_ref_after_loop", why="MINIMAL: a void helper assigning a kernel-level local through a reference inside a loop; the local read after the loop", includes=CM,
  src="""
static inline void setv(double& s, double e) { s = e; }
DPGEN_KERNEL void r5_min_helper_ref_after_loop(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 1.0;
  for (int i = 0; i < n; ++i) setv(s, a[i] * a[i]);
  out[0] = s;
}""", params=P_A1)

K(name="min_helper_ptr_accum", why="MINIMAL: a void helper summing into a kernel-level local through a pointer inside a loop", includes=CM,
  src="""
static inline void addp(double* s, double e) { *s += e; }
DPGEN_KERNEL void r5_min_helper_ptr_accum(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 0.0;
  for (int i = 0; i < n; ++i) addp(&s, a[i] * a[i]);
  out[0] = s;
}""", params=P_A1)

K(name="min_lambda_ref_after_loop", why="MINIMAL: a [&] lambda assigning a captured local inside a loop; the local read after the loop", includes=CM,
  src="""
DPGEN_KERNEL void r5_min_lambda_ref_after_loop(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 1.0;
  auto set = [&](double e) { s = e; };
  for (int i = 0; i < n; ++i) set(a[i] * a[i]);
  out[0] = s;
}""", params=P_A1)

K(name="min_helper_recurrence", expect="reject", why="MINIMAL: a recurrence s = 0.5 s + e hidden in a helper: accepted, the loop dropped", includes=CM,
  src="""
static inline void rec(double& s, double e) { s = 0.5 * s + e; }
DPGEN_KERNEL void r5_min_helper_recurrence(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 1.0;
  for (int i = 0; i < n; ++i) rec(s, a[i]);
  out[0] = s;
}""", params=P_A1)

K(name="min_pin_two_counters", why="MINIMAL: if (i == j) tr[0] = a[i]: n iterations store tr[0], the adjoint credits all of them", includes=CM,
  expect="reject",
  src="""
DPGEN_KERNEL void r5_min_pin_two_counters(DPGEN_IN const double* a, DPGEN_OUT double* tr, int n) {
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (i == j) tr[0] = a[i];
}""", params=a1(("tr","1")), linear=True)

K(name="min_lw_countdown", why="MINIMAL: later writer in a loop counting down: iteration j - 1 runs after j, so K[j + 1] of iteration j - 1... the adjoint credits K[j] (ascending order assumed)",
  src="""
DPGEN_KERNEL void r5_min_lw_countdown(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* K, int n) {
  for (int j = n - 1; j >= 0; --j) {
    K[j] = a[j];
    K[j + 1] = b[j];
  }
}""", params=ab(("K","n + 1")), linear=True)

K(name="min_ip_cond_on_sum", why="MINIMAL: in-place update under a condition on an accumulator of the old values: the adjoint does not compile (dpgen_sum_s not declared)", includes=CM,
  src="""
DPGEN_KERNEL void r5_min_ip_cond_on_sum(DPGEN_INOUT double* v, int n) {
  double s = 0.0;
  for (int i = 0; i < n; ++i) s += v[i] * v[i];
  for (int i = 0; i < n; ++i)
    if (s > 1.0) v[i] = v[i] / s;
}""", params=[("io","v",N),("val","n")], ranges="{-2.0, 2.0}")

K(name="min_ip_cond_on_max", why="MINIMAL: in-place update under a condition on a max reduction of the old values: the adjoint does not compile (dpgen_max_m not declared)", includes=CM,
  src="""
DPGEN_KERNEL void r5_min_ip_cond_on_max(DPGEN_INOUT double* v, int n) {
  double m = 0.0;
  for (int i = 0; i < n; ++i) m = fmax(m, v[i]);
  for (int i = 0; i < n; ++i)
    if (v[i] > 0.5 * m) v[i] = v[i] * v[i];
}""", params=[("io","v",N),("val","n")])

K(name="min_ip_cond_on_work_local", why="MINIMAL: in-place update under a condition on a body local read from a work array: the adjoint does not compile ('w' not declared)", includes=CM,
  src="""
DPGEN_KERNEL void r5_min_ip_cond_on_work_local(DPGEN_INOUT double* v, DPGEN_OUT double* w, int n) {
  for (int i = 0; i < n; ++i) w[i] = v[i] * 2.0;
  for (int i = 0; i < n; ++i) {
    const double t = w[i];
    if (t > 0.0) v[i] = t * v[i];
  }
}""", params=[("io","v",N),("out","w",N),("val","n")])

K(name="ip_pinned_update", why="a sum of the old values, then only u[0] updated (pinned store in the update loop)", includes=CM,
  src="""
DPGEN_KERNEL void r5_ip_pinned_update(DPGEN_INOUT double* u, int n) {
  double s = 0.0;
  for (int i = 0; i < n; ++i) s += u[i] * u[i];
  for (int i = 0; i < n; ++i)
    if (i == 0) u[0] = s;
}""", params=[("io","u",N),("val","n")])

K(name="ip_lastwriter_update", why="the update loop is a later-writer pair over u (reads only a work array)", includes=CM,
  src="""
DPGEN_KERNEL void r5_ip_lastwriter_update(DPGEN_INOUT double* u, DPGEN_OUT double* w, int n) {
  for (int i = 0; i < n; ++i) w[i] = u[i] * u[i + 1];
  for (int j = 0; j < n; ++j) {
    u[j] = w[j];
    u[j + 1] = 2.0 * w[j];
  }
}""", params=[("io","u","n + 1"),("out","w",N),("val","n")])

K(name="mm_inout_err", why="err DPGEN_INOUT: err[0] = fmax(err[0], |r|) starts from the caller's value, an input here", includes=CM,
  src="""
DPGEN_KERNEL void r5_mm_inout_err(DPGEN_INOUT double* err, DPGEN_IN const double* r, int n) {
  for (int i = 0; i < n; ++i) err[0] = fmax(err[0], fabs(r[i]));
}""", params=[("io","err","1"),("in","r",N),("val","n")])

K(name="ip_max_ties", why="in place: v / (1 + max|v|) with ties in the max (hand-computed)", includes=CM,
  src="""
DPGEN_KERNEL void r5_ip_max_ties(DPGEN_INOUT double* v, int n) {
  double m = 0.0;
  for (int i = 0; i < n; ++i) m = fmax(m, fabs(v[i]));
  for (int i = 0; i < n; ++i) v[i] = v[i] / (1.0 + m);
}""", params=[("io","v",N),("val","n")],
  cases="""TEST_CASE("adversary: r5_ip_max_ties ties") {
  // v = {2, -2, 1}: m = 2 at v0 and v1 (half each, with the sign); seed e_0 on the new v:
  // d v0'/d v0 = 1/3 - 2/9 * 1/2 = 2/9, d v0'/d v1 = -2/9 * (-1/2) = 1/9, d v0'/d v2 = 0
  std::vector<double> v = {2.0, -2.0, 1.0}, va = {1.0, 0.0, 0.0};
  r5_ip_max_ties_adjoint(v.data(), va.data(), 3);
  CHECK(va[0] == doctest::Approx(2.0 / 9));
  CHECK(va[1] == doctest::Approx(1.0 / 9));
  CHECK(va[2] == doctest::Approx(0.0));
  std::vector<double> vt = v, vd = {0.0, 1.0, 0.0};
  r5_ip_max_ties_tangent(vt.data(), vd.data(), 3);
  CHECK(vt[0] == doctest::Approx(2.0 / 3));
  CHECK(vd[0] == doctest::Approx(1.0 / 9));
}""")

K(name="min_mm_ternary_oob", why="MINIMAL: the element of a max is an index-guarded ternary reading a[i - 1]: the adjoint's cell range starts at -1 and adds 0.0 to a_adj[-1] (heap out-of-bounds write)", includes=CM,
  src="""
DPGEN_KERNEL void r5_min_mm_ternary_oob(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = -4.0;
  for (int i = 0; i < n; ++i) m = fmax(m, i == 0 ? 0.0 : a[i - 1]);
  out[0] = m;
}""", params=P_A1)
