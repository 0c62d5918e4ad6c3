# Round r4 (issue 20): kernels aimed at accumulators, triangular/banded loops,
# moving strided starts, lambdas, std::array, exclusive branches on parameters,
# double** constant rows, index macros with locals, generated-name clashes.
# ADV_SPECS=specs_r4 python3 gen.py [names...]
N = "n"
SPECS = []
def K(**kw):
    kw["name"] = "r4_" + kw["name"]
    SPECS.append(kw)
L1 = "for (int n : {0, 1, 2, 3, 4, 7, 16})"
L1p = "for (int n : {1, 2, 3, 4, 7, 16})"
L2 = "for (auto [n, m] : {std::pair{0, 0}, {1, 1}, {1, 3}, {3, 1}, {2, 2}, {4, 3}, {5, 6}})"
L2p = "for (auto [n, m] : {std::pair{1, 1}, {1, 3}, {3, 1}, {2, 2}, {4, 3}, {5, 6}})"
LF = "for (int flag : {0, 1, 2, -1}) for (int n : {0, 1, 2, 3, 7})"
PF = "CAPTURE(flag);"
LW = "for (int w : {0, 1, 2, 5}) for (int n : {0, 1, 2, 3, 7})"
PW = "CAPTURE(w);"
def io1(*outs, n=N): return [("in","a",n),("in","b",n)] + [("out",o,s) for o,s in outs] + [("val","n")]
CM = "#include <cmath>\n#include <algorithm>\n"

# ---------------------------------------------------------------- accumulators
K(name="acc_in_if_arm", why="accumulator inside an if arm on a parameter", includes=CM, loop=LF, pre=PF,
  src="""
DPGEN_KERNEL void r4_acc_in_if_arm(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, int flag) {
  if (flag == 0) {
    double s = 0.0;
    for (int i = 0; i < n; ++i) s += a[i] * a[i];
    out[0] = std::sqrt(1.0 + s);
  } else {
    double s = 1.0;
    for (int i = 0; i < n; ++i) s += a[i];
    out[0] = s * s;
  }
}""", params=[("in","a",N),("out","out","1"),("val","n"),("val","flag")])

K(name="acc_two_share_store", why="two accumulators sharing a loop with a store", includes=CM,
  src="""
DPGEN_KERNEL void r4_acc_two_share_store(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                         DPGEN_OUT double* u, DPGEN_OUT double* out, int n) {
  double s = 0, t = 0;
  for (int i = 0; i < n; ++i) {
    s += a[i] * b[i];
    u[i] = a[i] * a[i] - b[i];
    t += std::sin(b[i]) * a[i];
  }
  out[0] = s * t;
  out[1] = s - t * t;
}""", params=[("in","a",N),("in","b",N),("out","u",N),("out","out","2"),("val","n")])

K(name="acc_triangular", why="accumulator in a triangular loop (cumulative sums)",
  src="""
DPGEN_KERNEL void r4_acc_triangular(DPGEN_IN const double* a, DPGEN_OUT double* y, int n) {
  for (int i = 0; i < n; ++i) {
    double s = 0;
    for (int j = 0; j <= i; ++j) s += a[j] * a[i - j];
    y[i] = s * s;
  }
}""", params=[("in","a",N),("out","y",N),("val","n")])

K(name="acc_second_loop_same", why="a second loop accumulates the same local again",
  src="""
DPGEN_KERNEL void r4_acc_second_loop_same(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                          DPGEN_OUT double* out, int n) {
  double s = 0.0;
  for (int i = 0; i < n; ++i) s += a[i] * b[i];
  for (int i = 0; i < n; ++i) s += a[i] * a[i] * s;
  out[0] = s * s;
}""", params=[("in","a",N),("in","b",N),("out","out","1"),("val","n")])

K(name="acc_second_loop_linear", why="a second loop accumulates the same local (no self read)",
  src="""
DPGEN_KERNEL void r4_acc_second_loop_linear(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                            DPGEN_OUT double* out, int n) {
  double s = 0.0;
  for (int i = 0; i < n; ++i) s += a[i] * b[i];
  out[1] = s;
  for (int i = 0; i < n; ++i) s += b[i] * b[i];
  out[0] = s * s;
}""", params=[("in","a",N),("in","b",N),("out","out","2"),("val","n")])

K(name="acc_reset_reuse", why="accumulator, used, reset, reused by a second loop",
  src="""
DPGEN_KERNEL void r4_acc_reset_reuse(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                     DPGEN_OUT double* out, int n) {
  double s = 0.0;
  for (int i = 0; i < n; ++i) s += a[i] * a[i];
  const double first = s;
  s = 0.0;
  for (int i = 0; i < n; ++i) s += b[i] * a[i];
  out[0] = first * s;
  out[1] = s + first * first;
}""", params=[("in","a",N),("in","b",N),("out","out","2"),("val","n")])

K(name="acc_index_branch", why="sum used in an index-dependent branch later",
  src="""
DPGEN_KERNEL void r4_acc_index_branch(DPGEN_IN const double* a, DPGEN_OUT double* u, int n) {
  double s = 0;
  for (int i = 0; i < n; ++i) s += a[i] * a[i];
  for (int i = 0; i < n; ++i) {
    if (i % 2 == 0) u[i] = a[i] * s;
    else if (i == n - 1) u[i] = s * s;
    else u[i] = a[i] - s;
  }
}""", params=[("in","a",N),("out","u",N),("val","n")])

K(name="acc_float", why="float accumulator", T="float",
  src="""
DPGEN_KERNEL void r4_acc_float(DPGEN_IN const float* a, DPGEN_OUT float* out, int n) {
  float s = 0.0f;
  for (int i = 0; i < n; ++i) s += a[i] * a[i];
  out[0] = s * s + 0.5f * s;
}""", params=[("in","a",N),("out","out","1"),("val","n")])

K(name="acc_float_double_mix", why="float accumulator of a double product", T="double",
  src="""
DPGEN_KERNEL void r4_acc_float_double_mix(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  float s = 0.0f;
  for (int i = 0; i < n; ++i) s += a[i] * a[i];
  out[0] = 2.0 * s;
}""", params=[("in","a",N),("out","out","1"),("val","n")])

K(name="acc_minus_eq", why="s -= ... with a nonzero init",
  src="""
DPGEN_KERNEL void r4_acc_minus_eq(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                  DPGEN_OUT double* out, int n) {
  double s = 1.0;
  for (int i = 0; i < n; ++i) s -= a[i] * b[i];
  out[0] = s * s;
}""", params=[("in","a",N),("in","b",N),("out","out","1"),("val","n")])

K(name="acc_init_reads_input", why="accumulator whose init reads an input", loop=L1p,
  src="""
DPGEN_KERNEL void r4_acc_init_reads_input(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                          DPGEN_OUT double* out, int n) {
  double s = a[0] * b[0];
  for (int i = 1; i < n; ++i) s += a[i] * a[i - 1];
  out[0] = s * a[0];
}""", params=[("in","a",N),("in","b",N),("out","out","1"),("val","n")])

K(name="acc_guard_return", why="guard return before the accumulator",
  src="""
DPGEN_KERNEL void r4_acc_guard_return(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  out[0] = 0.0;
  if (n < 3) return;
  double s = 0;
  for (int i = 1; i < n - 1; ++i) s += a[i] * (a[i + 1] - a[i - 1]);
  out[0] = s * s;
}""", params=[("in","a",N),("out","out","1"),("val","n")])

K(name="acc_guard_return_noinit", why="guard return, output written only after it",
  src="""
DPGEN_KERNEL void r4_acc_guard_return_noinit(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  if (n < 3) return;
  double s = 0;
  for (int i = 1; i < n - 1; ++i) s += a[i] * (a[i + 1] - a[i - 1]);
  out[0] = s * s;
}""", params=[("in","a",N),("out","out","1"),("val","n")])

K(name="acc_nested_rowsums", why="sum of squared row sums (nested accumulators)", loop=L2,
  src="""
DPGEN_KERNEL void r4_acc_nested_rowsums(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, int m) {
  double tot = 0.0;
  for (int j = 0; j < m; ++j) {
    double r = 0.0;
    for (int i = 0; i < n; ++i) r += a[j * n + i];
    tot += r * r;
  }
  out[0] = tot * tot;
}""", params=[("in","a","n*m"),("out","out","1"),("val","n"),("val","m")])

K(name="acc_later_nest_and_local", why="accumulator read in a later nest and in a kernel-level local", loop=L1p,
  src="""
DPGEN_KERNEL void r4_acc_later_nest_and_local(DPGEN_IN const double* a, DPGEN_OUT double* u, int n) {
  double s = 0;
  for (int i = 0; i < n; ++i) s += a[i] * a[i];
  const double mean = s / n;
  for (int i = 0; i < n; ++i) u[i] = a[i] * s - mean * a[i];
}""", params=[("in","a",N),("out","u",N),("val","n")])

K(name="acc_product", why="multiplicative accumulator s *= a[i]",
  src="""
DPGEN_KERNEL void r4_acc_product(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 1.0;
  for (int i = 0; i < n; ++i) s *= a[i];
  out[0] = s;
}""", params=[("in","a",N),("out","out","1"),("val","n")])

K(name="acc_max", why="max reduction s = std::max(s, a[i]*a[i])", includes=CM,
  src="""
DPGEN_KERNEL void r4_acc_max(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = -1.0;
  for (int i = 0; i < n; ++i) s = std::max(s, a[i] * (1.0 + 0.01 * i));
  out[0] = s * s;
}""", params=[("in","a",N),("out","out","1"),("val","n")])

K(name="acc_cond_data", why="conditional accumulation on data",
  src="""
DPGEN_KERNEL void r4_acc_cond_data(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                   DPGEN_OUT double* out, int n) {
  double s = 0.0;
  for (int i = 0; i < n; ++i)
    if (a[i] > 0.1) s += a[i] * b[i];
    else s -= b[i];
  out[0] = s * s;
}""", params=[("in","a",N),("in","b",N),("out","out","1"),("val","n")])

K(name="acc_prefix_read_in_loop", why="accumulator read inside its own loop (prefix sum)",
  src="""
DPGEN_KERNEL void r4_acc_prefix_read_in_loop(DPGEN_IN const double* a, DPGEN_OUT double* u, int n) {
  double s = 0.0;
  for (int i = 0; i < n; ++i) {
    s += a[i];
    u[i] = s * s;
  }
}""", params=[("in","a",N),("out","u",N),("val","n")])

K(name="acc_linear_recurrence", why="s = 0.5 * s + a[i]",
  src="""
DPGEN_KERNEL void r4_acc_linear_recurrence(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 0.0;
  for (int i = 0; i < n; ++i) s = 0.5 * s + a[i] * a[i];
  out[0] = s;
}""", params=[("in","a",N),("out","out","1"),("val","n")])

K(name="acc_sum_then_weighted", why="t = f(s); second loop accumulates into s with t",
  src="""
DPGEN_KERNEL void r4_acc_sum_then_weighted(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                           DPGEN_OUT double* out, int n) {
  double s = 0.0;
  for (int i = 0; i < n; ++i) s += a[i];
  const double t = s * s;
  for (int i = 0; i < n; ++i) s += t * b[i];
  out[0] = s;
}""", params=[("in","a",N),("in","b",N),("out","out","1"),("val","n")])

K(name="acc_bias_param", why="accumulator initialised from a double parameter", loop="for (int n : {0, 1, 2, 5}) for (double bias : {0.0, 0.7})", pre="CAPTURE(bias);",
  src="""
DPGEN_KERNEL void r4_acc_bias_param(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, double bias) {
  double s = bias;
  for (int i = 0; i < n; ++i) s += a[i] * a[i];
  out[0] = s * s;
}""", params=[("in","a",N),("out","out","1"),("val","n"),("val","bias")])

K(name="acc_count_and_sum", why="int counter and a double sum in one loop, divided after", loop=L1,
  src="""
DPGEN_KERNEL void r4_acc_count_and_sum(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  int cnt = 0;
  double s = 0.0;
  for (int i = 0; i < n; ++i)
    if (a[i] > 0.0) { cnt++; s += a[i] * a[i]; }
  out[0] = cnt > 0 ? s / cnt : 0.0;
}""", params=[("in","a",N),("out","out","1"),("val","n")])

K(name="acc_normalise_output", why="u[i] = a[i] / (1 + s*s) after the sum",
  src="""
DPGEN_KERNEL void r4_acc_normalise_output(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                          DPGEN_OUT double* u, int n) {
  double s = 0.0;
  for (int i = 0; i < n; ++i) s += a[i] / (1.0 + b[i] * b[i]);
  for (int i = 0; i < n; ++i) u[i] = a[i] / (1.0 + s * s);
}""", params=[("in","a",N),("in","b",N),("out","u",N),("val","n")])

K(name="acc_strided", why="accumulator over a step-2 loop",
  src="""
DPGEN_KERNEL void r4_acc_strided(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 0.0;
  for (int i = 1; i < n; i += 2) s += a[i] * a[i - 1];
  out[0] = s * s;
}""", params=[("in","a",N),("out","out","1"),("val","n")])

K(name="acc_tri_down", why="accumulator in a triangle counting down",
  src="""
DPGEN_KERNEL void r4_acc_tri_down(DPGEN_IN const double* a, DPGEN_OUT double* y, int n) {
  for (int i = n - 1; i >= 0; --i) {
    double s = 0.0;
    for (int j = n - 1; j >= i; --j) s += a[j] * a[j - i];
    y[i] = s;
  }
}""", params=[("in","a",N),("out","y",N),("val","n")])

K(name="acc_param_branch_in_loop", why="else-if chain of 3 on a parameter inside the accumulating loop", loop=LF, pre=PF,
  src="""
DPGEN_KERNEL void r4_acc_param_branch_in_loop(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, int flag) {
  double s = 0.5;
  for (int i = 0; i < n; ++i) {
    if (flag == 0) s += a[i];
    else if (flag == 1) s += a[i] * a[i];
    else s -= a[i] * a[i] * a[i];
  }
  out[0] = s * s;
}""", params=[("in","a",N),("out","out","1"),("val","n"),("val","flag")])

K(name="acc_row_normalise", why="row sum then row store in the same outer loop", loop=L2,
  src="""
DPGEN_KERNEL void r4_acc_row_normalise(DPGEN_IN const double* a, DPGEN_OUT double* u, int n, int m) {
  for (int j = 0; j < m; ++j) {
    double s = 1.0;
    for (int i = 0; i < n; ++i) s += a[j * n + i] * a[j * n + i];
    for (int i = 0; i < n; ++i) u[j * n + i] = a[j * n + i] / s;
  }
}""", params=[("in","a","n*m"),("out","u","n*m"),("val","n"),("val","m")])

K(name="acc_readback_output", why="accumulates the output it just stored",
  src="""
DPGEN_KERNEL void r4_acc_readback_output(DPGEN_IN const double* a, DPGEN_OUT double* u,
                                         DPGEN_OUT double* out, int n) {
  double s = 0.0;
  for (int i = 0; i < n; ++i) {
    u[i] = a[i] * a[i];
    s += u[i] * a[i];
  }
  out[0] = s * s;
}""", params=[("in","a",N),("out","u",N),("out","out","1"),("val","n")])

K(name="acc_reset_in_if", why="accumulator reset under an index condition inside the loop",
  src="""
DPGEN_KERNEL void r4_acc_reset_in_if(DPGEN_IN const double* a, DPGEN_OUT double* u, int n) {
  double s = 0.0;
  for (int j = 0; j < n; ++j) {
    if (j % 2 == 0) s = 0.0;
    s += a[j] * a[j];
    u[j] = s;
  }
}""", params=[("in","a",N),("out","u",N),("val","n")])

K(name="acc_int_bound", why="int accumulator used as a later loop bound",
  src="""
DPGEN_KERNEL void r4_acc_int_bound(DPGEN_IN const double* a, DPGEN_OUT double* u, int n) {
  int k = 0;
  for (int i = 0; i < n; ++i) k += 2;
  for (int i = 0; i < k / 2; ++i) u[i] = a[i] * a[i];
}""", params=[("in","a",N),("out","u",N),("val","n")])

K(name="acc_two_phase_product", why="t = s, s reset, s re-accumulated; out = t*s",
  src="""
DPGEN_KERNEL void r4_acc_two_phase_product(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                           DPGEN_OUT double* out, int n) {
  double s = 0;
  for (int i = 0; i < n; ++i) s += a[i];
  double t = s;
  s = 0;
  for (int i = 0; i < n; ++i) s += b[i] * b[i];
  out[0] = t * s + t;
}""", params=[("in","a",N),("in","b",N),("out","out","1"),("val","n")])

K(name="acc_two_outputs_sqrt", why="one sum read by two outputs after", includes=CM,
  src="""
DPGEN_KERNEL void r4_acc_two_outputs_sqrt(DPGEN_IN const double* a, DPGEN_OUT double* o1,
                                          DPGEN_OUT double* o2, int n) {
  double s = 0;
  for (int i = 0; i < n; ++i) s += a[i] * a[i];
  o1[0] = std::sqrt(1.0 + s);
  o2[0] = s * s;
}""", params=[("in","a",N),("out","o1","1"),("out","o2","1"),("val","n")])

K(name="acc_col_then_row", why="sum over columns inside j, reused by i loop and a kernel-level total", loop=L2,
  src="""
DPGEN_KERNEL void r4_acc_col_then_row(DPGEN_IN const double* a, DPGEN_OUT double* u,
                                      DPGEN_OUT double* tot, int n, int m) {
  double all = 0.0;
  for (int j = 0; j < m; ++j) {
    double s = 0.0;
    for (int i = 0; i < n; ++i) s += a[j * n + i];
    all += s;
    for (int i = 0; i < n; ++i) u[j * n + i] = s * a[j * n + i];
  }
  tot[0] = all * all;
}""", params=[("in","a","n*m"),("out","u","n*m"),("out","tot","1"),("val","n"),("val","m")])

K(name="acc_compound_div_eq", why="s /= (1 + a[i]^2)",
  src="""
DPGEN_KERNEL void r4_acc_compound_div_eq(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 2.0;
  for (int i = 0; i < n; ++i) s /= (1.0 + a[i] * a[i]);
  out[0] = s;
}""", params=[("in","a",N),("out","out","1"),("val","n")])

K(name="acc_s_eq_s_plus", why="s = s + a[i]*a[i] in a C89 style with declaration at top",
  src="""
DPGEN_KERNEL void r4_acc_s_eq_s_plus(DPGEN_IN const double* a, DPGEN_OUT double* u, int n) {
  int i;
  double s, t;
  s = 0.0;
  t = 1.0;
  for (i = 0; i < n; i++) {
    s = s + a[i] * a[i];
    t = t - a[i];
  }
  for (i = 0; i < n; i++) u[i] = s * a[i] + t;
}""", params=[("in","a",N),("out","u",N),("val","n")])

# ---------------------------------------------------------------- triangular / banded
NN = "n*n"
K(name="tri_countdown_inner", why="inner loop j = i down to 0",
  src="""
DPGEN_KERNEL void r4_tri_countdown_inner(DPGEN_IN const double* L, DPGEN_IN const double* x,
                                         DPGEN_OUT double* y, int n) {
  for (int i = 0; i < n; ++i) {
    double s = 0;
    for (int j = i; j >= 0; --j) s += L[i * n + j] * x[j] * x[j];
    y[i] = s;
  }
}""", params=[("in","L",NN),("in","x",N),("out","y",N),("val","n")])

K(name="tri_strict_lower", why="j < i (empty row 0) stores into the triangle",
  src="""
DPGEN_KERNEL void r4_tri_strict_lower(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < i; ++j)
      e[i * n + j] = a[i] * a[j] - a[i - j];
}""", params=[("in","a",N),("out","e",NN),("val","n")])

K(name="tri_le_i_store", why="j <= i stores, diagonal included",
  src="""
DPGEN_KERNEL void r4_tri_le_i_store(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  for (int i = 0; i < n; ++i)
    for (int j = 0; j <= i; ++j)
      e[i * n + j] = a[i] * a[j] * a[i - j];
}""", params=[("in","a",N),("out","e",NN),("val","n")])

K(name="tri_bound_i_plus_2", why="bound std::min(n, i + 2)", includes=CM,
  src="""
DPGEN_KERNEL void r4_tri_bound_i_plus_2(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < std::min(n, i + 2); ++j)
      e[i * n + j] = a[j] * a[j] + a[i];
}""", params=[("in","a",N),("out","e",NN),("val","n")])

K(name="tri_bound_i_plus_2_noclip", why="bound i + 2 on an (n+1)-wide output, no clip",
  src="""
DPGEN_KERNEL void r4_tri_bound_i_plus_2_noclip(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < i + 2; ++j)
      e[i * (n + 1) + j] = a[j] * a[i] + a[j];
}""", params=[("in","a","n+1"),("out","e","n*(n+1)"),("val","n")])

K(name="tri_n_minus_i", why="bound n - i (anti-triangle), a[i+j]",
  src="""
DPGEN_KERNEL void r4_tri_n_minus_i(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n - i; ++j)
      e[i * n + j] = a[i + j] * a[j];
}""", params=[("in","a",N),("out","e",NN),("val","n")])

K(name="tri_window_moving", why="window max(0,i-1)..min(n,i+2), both sides moving", includes=CM,
  src="""
DPGEN_KERNEL void r4_tri_window_moving(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    double s = 0;
    for (int j = std::max(0, i - 1); j < std::min(n, i + 2); ++j) s += a[j] * a[i];
    out[i] = s;
  }
}""", params=[("in","a",N),("out","out",N),("val","n")])

K(name="tri_window_inclusive_w", why="window max(0,i-w)..min(n-1,i+w) inclusive, param w", includes=CM, loop=LW, pre=PW,
  src="""
DPGEN_KERNEL void r4_tri_window_inclusive_w(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, int w) {
  for (int i = 0; i < n; ++i) {
    double s = 0;
    for (int j = std::max(0, i - w); j <= std::min(n - 1, i + w); ++j) s += a[j] * a[j] * (j - i + 0.5);
    out[i] = s;
  }
}""", params=[("in","a",N),("out","out",N),("val","n"),("val","w")])

K(name="tri_window_store", why="banded stores e[i][j] for |i-j|<=1 via min/max", includes=CM,
  src="""
DPGEN_KERNEL void r4_tri_window_store(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  for (int i = 0; i < n; ++i)
    for (int j = std::max(0, i - 1); j <= std::min(n - 1, i + 1); ++j)
      e[i * n + j] = a[i] * a[j] + (i - j);
}""", params=[("in","a",N),("out","e",NN),("val","n")])

K(name="tri_outer_countdown", why="outer i counts down, inner j <= i",
  src="""
DPGEN_KERNEL void r4_tri_outer_countdown(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  for (int i = n - 1; i >= 0; --i)
    for (int j = 0; j <= i; ++j)
      e[i * n + j] = a[i] * a[j] * a[j];
}""", params=[("in","a",N),("out","e",NN),("val","n")])

K(name="tri_symmetric_fill", why="fills both triangles (diagonal stored twice, same value)",
  src="""
DPGEN_KERNEL void r4_tri_symmetric_fill(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  for (int i = 0; i < n; ++i)
    for (int j = 0; j <= i; ++j) {
      const double v = a[i] * a[j] + a[i] - a[j];
      e[i * n + j] = v;
      e[j * n + i] = v * v;
    }
}""", params=[("in","a",N),("out","e",NN),("val","n")])

K(name="tri_forward_subst", why="forward substitution: x[i] reads x[j<i] (own output)", linear=False,
  ranges="{2.0, 3.0}, {-1.0, 1.0}",
  src="""
DPGEN_KERNEL void r4_tri_forward_subst(DPGEN_IN const double* L, DPGEN_IN const double* b,
                                       DPGEN_OUT double* x, int n) {
  for (int i = 0; i < n; ++i) {
    double s = b[i];
    for (int j = 0; j < i; ++j) s -= L[i * n + j] * x[j];
    x[i] = s / L[i * n + i];
  }
}""", params=[("in","L",NN),("in","b",N),("out","x",N),("val","n")])

K(name="tri_3d", why="tetrahedral nest k, j<=k, i<=j",
  src="""
DPGEN_KERNEL void r4_tri_3d(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  for (int k = 0; k < n; ++k)
    for (int j = 0; j <= k; ++j)
      for (int i = 0; i <= j; ++i)
        e[(k * n + j) * n + i] = a[i] * a[j] * a[k];
}""", params=[("in","a",N),("out","e","n*n*n"),("val","n")])

K(name="tri_start1_lt_i", why="i from 1, j from 1 to i-1 (i-1 bound written as j <= i - 1)",
  src="""
DPGEN_KERNEL void r4_tri_start1_lt_i(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 1; i < n; ++i) {
    double s = a[i];
    for (int j = 1; j <= i - 1; ++j) s += a[j] * a[i - j];
    out[i] = s * s;
  }
}""", params=[("in","a",N),("out","out",N),("val","n")])

K(name="tri_minmax_reverse", why="for (j = min(n-1,i+1); j >= max(0,i-1); --j)", includes=CM,
  src="""
DPGEN_KERNEL void r4_tri_minmax_reverse(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    double s = 0;
    for (int j = std::min(n - 1, i + 1); j >= std::max(0, i - 1); --j) s = s * 0.5 + a[j] * a[j];
    out[i] = s;
  }
}""", params=[("in","a",N),("out","out",N),("val","n")])

K(name="tri_two_outer_bounds", why="k in [i, j] for j >= i",
  src="""
DPGEN_KERNEL void r4_tri_two_outer_bounds(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  for (int i = 0; i < n; ++i)
    for (int j = i; j < n; ++j) {
      double s = 0;
      for (int k = i; k <= j; ++k) s += a[k];
      e[i * n + j] = s * s;
    }
}""", params=[("in","a",N),("out","e",NN),("val","n")])

K(name="tri_banded_storage", why="banded matvec with band storage A[i*3 + (j-i+1)]", includes=CM,
  src="""
DPGEN_KERNEL void r4_tri_banded_storage(DPGEN_IN const double* A, DPGEN_IN const double* x,
                                        DPGEN_OUT double* y, int n) {
  for (int i = 0; i < n; ++i) {
    double s = 0;
    for (int j = std::max(0, i - 1); j < std::min(n, i + 2); ++j) s += A[i * 3 + (j - i + 1)] * x[j] * x[i];
    y[i] = s;
  }
}""", params=[("in","A","3*n"),("in","x",N),("out","y",N),("val","n")])

K(name="tri_step2_outer", why="outer step 2, inner j <= i",
  src="""
DPGEN_KERNEL void r4_tri_step2_outer(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  for (int i = 0; i < n; i += 2)
    for (int j = 0; j <= i; ++j)
      e[i * n + j] = a[i] * a[j] + a[j];
}""", params=[("in","a",N),("out","e",NN),("val","n")])

K(name="tri_max_i_half", why="lower bound std::max(i, n / 2)", includes=CM,
  src="""
DPGEN_KERNEL void r4_tri_max_i_half(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  for (int i = 0; i < n; ++i)
    for (int j = std::max(i, n / 2); j < n; ++j)
      e[i * n + j] = a[i] * a[j] * a[j];
}""", params=[("in","a",N),("out","e",NN),("val","n")])

K(name="tri_accum_output", why="y[i] += in a triangle after y[i] = 0",
  src="""
DPGEN_KERNEL void r4_tri_accum_output(DPGEN_IN const double* L, DPGEN_IN const double* x,
                                      DPGEN_OUT double* y, int n) {
  for (int i = 0; i < n; ++i) {
    y[i] = 0.0;
    for (int j = 0; j <= i; ++j) y[i] += L[i * n + j] * x[j] * x[i];
  }
}""", params=[("in","L",NN),("in","x",N),("out","y",N),("val","n")])

K(name="tri_colsum_scatter", why="c[j] += over a triangle (scatter into the inner index)",
  src="""
DPGEN_KERNEL void r4_tri_colsum_scatter(DPGEN_IN const double* a, DPGEN_OUT double* c, int n) {
  for (int j = 0; j < n; ++j) c[j] = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j <= i; ++j)
      c[j] += a[i * n + j] * a[i * n + j];
}""", params=[("in","a",NN),("out","c",N),("val","n")])

K(name="tri_upper_countdown_gt", why="for (j = n - 1; j > i; --j) stores",
  src="""
DPGEN_KERNEL void r4_tri_upper_countdown_gt(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  for (int i = 0; i < n; ++i)
    for (int j = n - 1; j > i; --j)
      e[i * n + j] = a[i] - a[j] * a[j - i];
}""", params=[("in","a",N),("out","e",NN),("val","n")])

# ---------------------------------------------------------------- strided / parity
K(name="par_j_mod2", why="start j % 2, step 2", loop=L2,
  src="""
DPGEN_KERNEL void r4_par_j_mod2(DPGEN_IN const double* a, DPGEN_OUT double* e, int n, int m) {
  for (int j = 0; j < m; ++j)
    for (int i = j % 2; i < n; i += 2)
      e[j * n + i] = a[j * n + i] * a[j * n + i] + a[i];
}""", params=[("in","a","n*m"),("out","e","n*m"),("val","n"),("val","m")])

K(name="par_ij_mod3", why="start (j + k) % 3, step 3 (3D)", loop="for (int n : {0, 1, 2, 3, 4, 7})",
  src="""
DPGEN_KERNEL void r4_par_ij_mod3(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = (j + k) % 3; i < n; i += 3)
        e[(k * n + j) * n + i] = a[(k * n + j) * n + i] * a[i];
}""", params=[("in","a","n*n*n"),("out","e","n*n*n"),("val","n")])

K(name="par_rb3d", why="3D red-black start 1 + (j + k) % 2",
  loop="for (int n : {0, 1, 2, 3, 4, 5})",
  src="""
DPGEN_KERNEL void r4_par_rb3d(DPGEN_IN const double* u, DPGEN_OUT double* v, int n) {
  for (int k = 1; k < n - 1; ++k)
    for (int j = 1; j < n - 1; ++j)
      for (int i = 1 + (j + k) % 2; i < n - 1; i += 2) {
        const int c = (k * n + j) * n + i;
        v[c] = (u[c - 1] + u[c + 1] + u[c - n] + u[c + n] + u[c - n * n] + u[c + n * n]) * u[c];
      }
}""", params=[("in","u","n*n*n"),("out","v","n*n*n"),("val","n")])

K(name="par_red_then_black", why="red sweep writes v, black sweep reads v (the output) at red points", loop=L2,
  src="""
DPGEN_KERNEL void r4_par_red_then_black(DPGEN_IN const double* u, DPGEN_OUT double* v, int n, int m) {
  for (int j = 1; j < m - 1; ++j)
    for (int i = 1 + (j + 1) % 2; i < n - 1; i += 2)
      v[j * n + i] = 0.25 * (u[j * n + i - 1] + u[j * n + i + 1]) * u[j * n + i];
  for (int j = 1; j < m - 1; ++j)
    for (int i = 1 + j % 2; i < n - 1; i += 2)
      v[j * n + i] = 0.25 * (v[j * n + i - 1] * v[j * n + i + 1] + u[j * n + i]);
}""", params=[("in","u","n*m"),("out","v","n*m"),("val","n"),("val","m")])

K(name="par_unroll_step3", why="constant loop m = 0..8 step 3 over a table",
  src="""
DPGEN_KERNEL void r4_par_unroll_step3(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  const double w[9] = {1, 2, 3, 4, 5, 6, 7, 8, 9};
  for (int i = 0; i < n; ++i) {
    double s = 0;
    for (int m = 0; m < 9; m += 3) s += w[m] * u[i + m] * u[i + m];
    out[i] = s;
  }
}""", params=[("in","u","n+9"),("out","out",N),("val","n")])

K(name="par_unroll_down2", why="constant loop m = 4 down to 0 step 2",
  src="""
DPGEN_KERNEL void r4_par_unroll_down2(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  const double w[5] = {1, 2, 3, 4, 5};
  for (int i = 0; i < n; ++i) {
    double s = 0;
    for (int m = 4; m >= 0; m -= 2) s = s * 0.5 + w[m] * u[i + m];
    out[i] = s * s;
  }
}""", params=[("in","u","n+5"),("out","out",N),("val","n")])

K(name="par_unroll_odd", why="constant loop m = 1, 3, 5 (m < 6, step 2)",
  src="""
DPGEN_KERNEL void r4_par_unroll_odd(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    double s = 0;
    for (int m = 1; m < 6; m += 2) s += m * u[i + m] * u[i + m - 1];
    out[i] = s;
  }
}""", params=[("in","u","n+6"),("out","out",N),("val","n")])

K(name="par_unroll_le", why="constant loop m <= 6 step 3 (0, 3, 6)",
  src="""
DPGEN_KERNEL void r4_par_unroll_le(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    double s = 0;
    for (int m = 0; m <= 6; m += 3) s += (m + 1) * u[i + m] * u[i];
    out[i] = s;
  }
}""", params=[("in","u","n+7"),("out","out",N),("val","n")])

K(name="par_neighbours_step2", why="v[i] = u[i-1]*u[i+1] on a moving-parity row", loop=L2,
  src="""
DPGEN_KERNEL void r4_par_neighbours_step2(DPGEN_IN const double* u, DPGEN_OUT double* v, int n, int m) {
  for (int j = 0; j < m; ++j)
    for (int i = 1 + j % 2; i < n - 1; i += 2)
      v[j * n + i] = u[j * n + i - 1] * u[j * n + i + 1] + u[j * n + i];
}""", params=[("in","u","n*m"),("out","v","n*m"),("val","n"),("val","m")])

K(name="par_start_j_step3", why="start = j, step 3",
  src="""
DPGEN_KERNEL void r4_par_start_j_step3(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  for (int j = 0; j < n; ++j)
    for (int i = j; i < n; i += 3)
      e[j * n + i] = a[i] * a[j] + a[i - j];
}""", params=[("in","a",N),("out","e",NN),("val","n")])

K(name="par_countdown_step2", why="for (i = n - 1 - j % 2; i >= 0; i -= 2)", loop=L2,
  src="""
DPGEN_KERNEL void r4_par_countdown_step2(DPGEN_IN const double* a, DPGEN_OUT double* e, int n, int m) {
  for (int j = 0; j < m; ++j)
    for (int i = n - 1 - j % 2; i >= 0; i -= 2)
      e[j * n + i] = a[j * n + i] * a[i];
}""", params=[("in","a","n*m"),("out","e","n*m"),("val","n"),("val","m")])

K(name="par_accum_step2", why="accumulator over a parity loop, start j % 2", loop=L2,
  src="""
DPGEN_KERNEL void r4_par_accum_step2(DPGEN_IN const double* a, DPGEN_OUT double* r, int n, int m) {
  for (int j = 0; j < m; ++j) {
    double s = 0;
    for (int i = j % 2; i < n; i += 2) s += a[j * n + i] * a[j * n + i];
    r[j] = s;
  }
}""", params=[("in","a","n*m"),("out","r","m"),("val","n"),("val","m")])

K(name="par_start_2j_mod3", why="start (2 * j) % 3, step 3", loop=L2,
  src="""
DPGEN_KERNEL void r4_par_start_2j_mod3(DPGEN_IN const double* a, DPGEN_OUT double* e, int n, int m) {
  for (int j = 0; j < m; ++j)
    for (int i = (2 * j) % 3; i < n; i += 3)
      e[j * n + i] = a[j * n + i] * a[j * n + i] * (j + 1);
}""", params=[("in","a","n*m"),("out","e","n*m"),("val","n"),("val","m")])

K(name="par_two_halves_two_outs", why="red half into v, black half into w, both reading u", loop=L2,
  src="""
DPGEN_KERNEL void r4_par_two_halves_two_outs(DPGEN_IN const double* u, DPGEN_OUT double* v,
                                             DPGEN_OUT double* w, int n, int m) {
  for (int j = 0; j < m; ++j) {
    for (int i = j % 2; i < n; i += 2) v[j * n + i] = u[j * n + i] * u[j * n + i];
    for (int i = 1 + j % 2; i < n; i += 2) w[j * n + i] = u[j * n + i] * v[j * n + i - 1];
  }
}""", params=[("in","u","n*m"),("out","v","n*m"),("out","w","n*m"),("val","n"),("val","m")])

K(name="par_start_mod2_plus_j", why="start j + j % 2 (moving by 1 or 2 per row), step 2",
  src="""
DPGEN_KERNEL void r4_par_start_mod2_plus_j(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  for (int j = 0; j < n; ++j)
    for (int i = j + j % 2; i < n; i += 2)
      e[j * n + i] = a[i] * a[j] * a[i];
}""", params=[("in","a",N),("out","e",NN),("val","n")])

# ---------------------------------------------------------------- lambdas
K(name="lam_calls_helper", why="lambda calling a static helper", includes=CM,
  src="""
static inline double r4_sq(double x) { return x * x; }
DPGEN_KERNEL void r4_lam_calls_helper(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  auto energy = [&](int i) { return r4_sq(u[i]) + r4_sq(u[i + 1] - u[i]); };
  for (int i = 0; i + 1 < n; ++i) out[i] = energy(i) * u[i];
}""", params=[("in","u",N),("out","out",N),("val","n")])

K(name="lam_calls_lambda", why="lambda calling a lambda",
  src="""
DPGEN_KERNEL void r4_lam_calls_lambda(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  auto grad = [&](int i) { return u[i + 1] - u[i]; };
  auto flux = [&](int i) { return grad(i) * 0.5 * (u[i] + u[i + 1]); };
  for (int i = 1; i + 1 < n; ++i) out[i] = flux(i) - flux(i - 1);
}""", params=[("in","u",N),("out","out",N),("val","n")])

K(name="lam_capture_carray_copy", why="lambda [=] capturing a local C array by copy",
  src="""
DPGEN_KERNEL void r4_lam_capture_carray_copy(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  double w[3] = {0.25, 0.5, 0.25};
  auto smooth = [=](int i) { return w[0] * u[i] + w[1] * u[i + 1] * u[i + 1] + w[2] * u[i + 2]; };
  for (int i = 0; i + 2 < n; ++i) out[i] = smooth(i);
}""", params=[("in","u",N),("out","out",N),("val","n")])

K(name="lam_capture_carray_copy_stale", why="lambda [=] copies a C array that changes afterwards",
  src="""
DPGEN_KERNEL void r4_lam_capture_carray_copy_stale(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  double w[2] = {1.0, 2.0};
  auto f = [=](int i) { return w[0] * u[i] + w[1] * u[i] * u[i]; };
  w[0] = 5.0;
  for (int i = 0; i < n; ++i) out[i] = f(i) + w[0] * u[i];
}""", params=[("in","u",N),("out","out",N),("val","n")])

K(name="lam_loop_inside", why="lambda with a loop inside (stencil sum)",
  src="""
DPGEN_KERNEL void r4_lam_loop_inside(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  auto box = [&](int i) {
    double s = 0;
    for (int m = 0; m < 3; ++m) s += u[i + m] * u[i + m];
    return s;
  };
  for (int i = 0; i + 2 < n; ++i) out[i] = box(i);
}""", params=[("in","u",N),("out","out",N),("val","n")])

K(name="lam_generic_auto", why="generic lambda [](auto x)",
  src="""
DPGEN_KERNEL void r4_lam_generic_auto(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  auto cube = [](auto x) { return x * x * x; };
  for (int i = 0; i < n; ++i) out[i] = cube(u[i]) + cube(2.0) * u[i];
}""", params=[("in","u",N),("out","out",N),("val","n")])

K(name="lam_mutable", why="mutable lambda with a counter (should be rejected or right)",
  src="""
DPGEN_KERNEL void r4_lam_mutable(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  double c = 1.0;
  auto f = [c, u](int i) mutable { c = c * 2.0; return c * u[i]; };
  for (int i = 0; i < n; ++i) out[i] = f(i) * u[i];
}""", params=[("in","u",N),("out","out",N),("val","n")])

K(name="lam_ref_local_changes", why="[&] capture of a local that changes each iteration",
  src="""
DPGEN_KERNEL void r4_lam_ref_local_changes(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  double c = 0.0;
  auto f = [&](int i) { return c * u[i]; };
  for (int i = 0; i < n; ++i) {
    c = u[i] * u[i];
    out[i] = f(i) + c;
  }
}""", params=[("in","u",N),("out","out",N),("val","n")])

K(name="lam_copy_local_changes", why="[=] capture of a local that changes later (stale copy)",
  src="""
DPGEN_KERNEL void r4_lam_copy_local_changes(DPGEN_IN const double* u, DPGEN_OUT double* out, int n, double h) {
  double c = h;
  auto f = [=](int i) { return c * u[i] * u[i]; };
  c = 2.0 * h;
  for (int i = 0; i < n; ++i) out[i] = f(i) + c * u[i];
}""", params=[("in","u",N),("out","out",N),("val","n"),("val","0.5")])

K(name="lam_bool_predicate", why="lambda returning bool used in a condition",
  src="""
DPGEN_KERNEL void r4_lam_bool_predicate(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  auto up = [&](int i) -> bool { return u[i] > 0.0; };
  for (int i = 0; i < n; ++i) out[i] = up(i) ? u[i] * u[i] : -u[i];
}""", params=[("in","u",N),("out","out",N),("val","n")])

K(name="lam_stores_output", why="lambda that stores into the output",
  src="""
DPGEN_KERNEL void r4_lam_stores_output(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  auto put = [&](int i, double v) { out[i] = v * u[i]; };
  for (int i = 0; i < n; ++i) put(i, u[i] + 1.0);
}""", params=[("in","u",N),("out","out",N),("val","n")])

K(name="lam_param_names_generated", why="lambda params named i_adj, u_adj, dpgen_t0",
  src="""
DPGEN_KERNEL void r4_lam_param_names_generated(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  auto f = [&](int i_adj, double u_adj) { const double dpgen_t0 = u[i_adj] * u_adj; return dpgen_t0 + u_adj; };
  for (int i = 0; i < n; ++i) out[i] = f(i, u[i] * u[i]);
}""", params=[("in","u",N),("out","out",N),("val","n")])

K(name="lam_in_loop_calls_outer", why="lambda defined in the loop calls a lambda defined outside",
  src="""
DPGEN_KERNEL void r4_lam_in_loop_calls_outer(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  auto g = [&](int k) { return u[k] * u[k]; };
  for (int i = 1; i < n; ++i) {
    auto h = [&](int d) { return g(i - d) + g(i); };
    out[i] = h(1) * h(0);
  }
}""", params=[("in","u",N),("out","out",N),("val","n")])

K(name="lam_multi_return", why="lambda with three return arms", includes=CM,
  src="""
DPGEN_KERNEL void r4_lam_multi_return(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  auto lim = [](double a, double b) -> double {
    if (a > b) return a * b;
    if (a < -b) return -a;
    return std::sin(a) + b;
  };
  for (int i = 1; i < n; ++i) out[i] = lim(u[i], u[i - 1]);
}""", params=[("in","u",N),("out","out",N),("val","n")])

K(name="lam_captures_accumulator", why="lambda [&] reading an accumulator",
  src="""
DPGEN_KERNEL void r4_lam_captures_accumulator(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  double s = 0;
  for (int i = 0; i < n; ++i) s += u[i] * u[i];
  auto scale = [&](int i) { return u[i] * s; };
  for (int i = 0; i < n; ++i) out[i] = scale(i) + s;
}""", params=[("in","u",N),("out","out",N),("val","n")])

K(name="lam_copies_accumulator", why="lambda [=] copying an accumulator after its loop",
  src="""
DPGEN_KERNEL void r4_lam_copies_accumulator(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  double s = 1.0;
  for (int i = 0; i < n; ++i) s += u[i] * u[i];
  auto scale = [=](int i) { return u[i] / s; };
  for (int i = 0; i < n; ++i) out[i] = scale(i);
}""", params=[("in","u",N),("out","out",N),("val","n")])

K(name="lam_explicit_list", why="explicit capture list [u, h]",
  src="""
DPGEN_KERNEL void r4_lam_explicit_list(DPGEN_IN const double* u, DPGEN_OUT double* out, int n, double h) {
  auto d = [u, h](int i) { return (u[i + 1] - u[i]) * h * u[i]; };
  for (int i = 0; i + 1 < n; ++i) out[i] = d(i);
}""", params=[("in","u",N),("out","out",N),("val","n"),("val","0.7")])

K(name="lam_const_ref_param", why="lambda taking const double& and const auto",
  src="""
DPGEN_KERNEL void r4_lam_const_ref_param(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  const auto f = [](const double& x, const double& y) { return x * y + x; };
  for (int i = 1; i < n; ++i) out[i] = f(u[i], u[i - 1]) * f(u[i - 1], 1.0);
}""", params=[("in","u",N),("out","out",N),("val","n")])

K(name="lam_returns_index", why="lambda computing an index, used in a subscript",
  src="""
DPGEN_KERNEL void r4_lam_returns_index(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  auto wrap = [n](int i) { return (i + n) % n; };
  for (int i = 0; i < n; ++i) out[i] = u[wrap(i - 1)] * u[wrap(i + 1)];
}""", params=[("in","u",N),("out","out",N),("val","n")])

K(name="lam_called_in_bound", why="lambda used in a loop bound",
  src="""
DPGEN_KERNEL void r4_lam_called_in_bound(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  auto last = [n]() { return n - 1; };
  for (int i = 0; i < last(); ++i) out[i] = u[i] * u[i + 1];
}""", params=[("in","u",N),("out","out",N),("val","n")])

# ---------------------------------------------------------------- std::array
AR = "#include <array>\n#include <cmath>\n"
K(name="arr_in_lambda", why="std::array table captured by a lambda", includes=AR,
  src="""
DPGEN_KERNEL void r4_arr_in_lambda(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  constexpr std::array<double, 3> c = {-0.5, 0.0, 0.5};
  auto d = [&](int i) { return c[0] * u[i - 1] + c[1] * u[i] + c[2] * u[i + 1]; };
  for (int i = 1; i + 1 < n; ++i) out[i] = d(i) * d(i);
}""", params=[("in","u",N),("out","out",N),("val","n")])

K(name="arr_constexpr_size", why="std::array<double, K> with constexpr int K", includes=AR,
  src="""
DPGEN_KERNEL void r4_arr_constexpr_size(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  constexpr int K = 4;
  const std::array<double, K> w{1.0, -1.0, 2.0, -2.0};
  for (int i = 0; i < n; ++i) {
    double s = 0;
    for (int m = 0; m < K; ++m) s += w[m] * u[i + m] * u[i];
    out[i] = s;
  }
}""", params=[("in","u","n+4"),("out","out",N),("val","n")])

K(name="arr_accum_buffer", why="std::array buffer accumulated with += then read", includes=AR,
  src="""
DPGEN_KERNEL void r4_arr_accum_buffer(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    std::array<double, 2> b{};
    for (int m = 0; m < 4; ++m) b[m % 2] += u[i + m] * u[i + m];
    out[i] = b[0] * b[1];
  }
}""", params=[("in","u","n+4"),("out","out",N),("val","n")])

K(name="arr_copy_assign", why="std::array copied by assignment", includes=AR,
  src="""
DPGEN_KERNEL void r4_arr_copy_assign(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    std::array<double, 2> a{u[i], u[i] * u[i]};
    std::array<double, 2> b = a;
    b[0] = 3.0;
    out[i] = a[0] * b[1] + b[0] * a[1];
  }
}""", params=[("in","u",N),("out","out",N),("val","n")])

K(name="arr_at", why="std::array::at (rejected or right)", includes=AR,
  src="""
DPGEN_KERNEL void r4_arr_at(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  const std::array<double, 2> w{0.5, 1.5};
  for (int i = 0; i < n; ++i) out[i] = w.at(i % 2) * u[i] * u[i];
}""", params=[("in","u",N),("out","out",N),("val","n")])

K(name="arr_float", why="std::array<float, 3> table in a float kernel", includes=AR, T="float",
  src="""
DPGEN_KERNEL void r4_arr_float(DPGEN_IN const float* u, DPGEN_OUT float* out, int n) {
  const std::array<float, 3> w{0.25f, 0.5f, 0.25f};
  for (int i = 1; i + 1 < n; ++i) out[i] = w[0] * u[i - 1] + w[1] * u[i] * u[i] + w[2] * u[i + 1];
}""", params=[("in","u",N),("out","out",N),("val","n")])

K(name="arr_size_bound", why="loop bound t.size()", includes=AR,
  src="""
DPGEN_KERNEL void r4_arr_size_bound(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  const std::array<double, 3> w{1.0, 2.0, 3.0};
  for (int i = 0; i < n; ++i) {
    double s = 0;
    for (std::size_t m = 0; m < w.size(); ++m) s += w[m] * u[i + m];
    out[i] = s * s;
  }
}""", params=[("in","u","n+3"),("out","out",N),("val","n")])

K(name="arr_2d", why="std::array of std::array", includes=AR,
  src="""
DPGEN_KERNEL void r4_arr_2d(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  const std::array<std::array<double, 2>, 2> M{{{1.0, 2.0}, {3.0, 4.0}}};
  for (int i = 0; i < n; ++i) out[i] = M[0][1] * u[i] * u[i] + M[1][0] * u[i + 1];
}""", params=[("in","u","n+1"),("out","out",N),("val","n")])

K(name="arr_data_index", why="std::array subscript chosen by data", includes=AR,
  src="""
DPGEN_KERNEL void r4_arr_data_index(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  const std::array<double, 2> w{0.5, 2.0};
  for (int i = 0; i < n; ++i) out[i] = w[u[i] > 0.0 ? 1 : 0] * u[i] * u[i];
}""", params=[("in","u",N),("out","out",N),("val","n")])

K(name="arr_buffer_then_reverse", why="std::array buffer filled forward, read reversed", includes=AR,
  src="""
DPGEN_KERNEL void r4_arr_buffer_then_reverse(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    std::array<double, 3> d;
    for (int m = 0; m < 3; ++m) d[m] = u[i + m] * (m + 1);
    out[i] = d[2] * d[0] - d[1] * d[1];
  }
}""", params=[("in","u","n+3"),("out","out",N),("val","n")])

# ---------------------------------------------------------------- exclusive branches on parameters
K(name="br_elseif3", why="else-if chain of 3 loop nests on a parameter", loop=LF, pre=PF,
  src="""
DPGEN_KERNEL void r4_br_elseif3(DPGEN_IN const double* a, DPGEN_OUT double* u, int n, int flag) {
  if (flag == 0) {
    for (int i = 0; i < n; ++i) u[i] = a[i] * a[i];
  } else if (flag == 1) {
    for (int i = 1; i < n; ++i) u[i] = a[i] - a[i - 1] * a[i];
    if (n > 0) u[0] = 0.0;
  } else {
    for (int i = 0; i < n; ++i) u[i] = 3.0 * a[i];
  }
}""", params=[("in","a",N),("out","u",N),("val","n"),("val","flag")])

K(name="br_ne_vs_eq", why="if (flag != 0) nest; if (flag == 0) nest", loop=LF, pre=PF,
  src="""
DPGEN_KERNEL void r4_br_ne_vs_eq(DPGEN_IN const double* a, DPGEN_OUT double* u, int n, int flag) {
  if (flag != 0)
    for (int i = 0; i < n; ++i) u[i] = a[i] * a[i] * a[i];
  if (flag == 0)
    for (int i = 0; i < n; ++i) u[i] = a[i] + a[i] * a[i];
}""", params=[("in","a",N),("out","u",N),("val","n"),("val","flag")])

K(name="br_arm_output_as_work", why="one arm writes w then reads it as a work array, the other writes w only", loop=LF, pre=PF,
  src="""
DPGEN_KERNEL void r4_br_arm_output_as_work(DPGEN_IN const double* a, DPGEN_OUT double* w,
                                           DPGEN_OUT double* u, int n, int flag) {
  if (flag == 1) {
    for (int i = 0; i < n; ++i) w[i] = a[i] * a[i];
    for (int i = 1; i < n; ++i) u[i] = w[i] * w[i - 1];
    if (n > 0) u[0] = w[0];
  } else {
    for (int i = 0; i < n; ++i) w[i] = 2.0 * a[i];
    for (int i = 0; i < n; ++i) u[i] = a[i] * a[i] * a[i];
  }
}""", params=[("in","a",N),("out","w",N),("out","u",N),("val","n"),("val","flag")])

K(name="br_overlapping_conds", why="if (flag > 0) nest; if (flag > 1) nest overwrites (not exclusive)", loop=LF, pre=PF,
  src="""
DPGEN_KERNEL void r4_br_overlapping_conds(DPGEN_IN const double* a, DPGEN_OUT double* u, int n, int flag) {
  for (int i = 0; i < n; ++i) u[i] = a[i];
  if (flag > 0)
    for (int i = 0; i < n; ++i) u[i] = a[i] * a[i];
  if (flag > 1)
    for (int i = 0; i < n; ++i) u[i] = a[i] * a[i] * a[i];
}""", params=[("in","a",N),("out","u",N),("val","n"),("val","flag")])

K(name="br_double_param", why="branch on a double parameter", loop="for (double dt : {0.1, 0.9}) for (int n : {0, 1, 2, 5})", pre="CAPTURE(dt);",
  src="""
DPGEN_KERNEL void r4_br_double_param(DPGEN_IN const double* a, DPGEN_OUT double* u, int n, double dt) {
  if (dt > 0.5) {
    for (int i = 0; i < n; ++i) u[i] = dt * a[i] * a[i];
  } else {
    for (int i = 0; i < n; ++i) u[i] = a[i] - dt;
  }
}""", params=[("in","a",N),("out","u",N),("val","n"),("val","dt")])

K(name="br_one_arm_writes", why="only one arm writes the second output", loop=LF, pre=PF,
  src="""
DPGEN_KERNEL void r4_br_one_arm_writes(DPGEN_IN const double* a, DPGEN_OUT double* u,
                                       DPGEN_OUT double* v, int n, int flag) {
  for (int i = 0; i < n; ++i) u[i] = a[i] * a[i];
  if (flag == 0) {
    for (int i = 0; i < n; ++i) v[i] = a[i] * u[i];
  }
}""", params=[("in","a",N),("out","u",N),("out","v",N),("val","n"),("val","flag")])

K(name="br_arm_accum", why="accumulator computed differently per arm, read after the if", loop=LF, pre=PF,
  src="""
DPGEN_KERNEL void r4_br_arm_accum(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, int flag) {
  double s = 0.0;
  if (flag == 0) {
    for (int i = 0; i < n; ++i) s += a[i] * a[i];
  } else {
    for (int i = 0; i < n; ++i) s += a[i];
  }
  out[0] = s * s + s;
}""", params=[("in","a",N),("out","out","1"),("val","n"),("val","flag")])

K(name="br_switch", why="switch on a parameter with loop nests in cases", loop=LF, pre=PF,
  src="""
DPGEN_KERNEL void r4_br_switch(DPGEN_IN const double* a, DPGEN_OUT double* u, int n, int flag) {
  switch (flag) {
  case 0:
    for (int i = 0; i < n; ++i) u[i] = a[i] * a[i];
    break;
  case 1:
    for (int i = 0; i < n; ++i) u[i] = a[i];
    break;
  default:
    for (int i = 0; i < n; ++i) u[i] = -a[i] * a[i] * a[i];
  }
}""", params=[("in","a",N),("out","u",N),("val","n"),("val","flag")])

K(name="br_ternary_lo", why="loop start chosen by a ternary on a parameter", loop=LF, pre=PF,
  src="""
DPGEN_KERNEL void r4_br_ternary_lo(DPGEN_IN const double* a, DPGEN_OUT double* u, int n, int flag) {
  const int lo = flag != 0 ? 1 : 0;
  for (int i = 0; i < n; ++i) u[i] = 0.0;
  for (int i = lo; i < n; ++i) u[i] = a[i] * a[i - lo];
}""", params=[("in","a",N),("out","u",N),("val","n"),("val","flag")])

K(name="br_arm_return", why="if (flag == 0) { nest; return; } second nest", loop=LF, pre=PF,
  src="""
DPGEN_KERNEL void r4_br_arm_return(DPGEN_IN const double* a, DPGEN_OUT double* u, int n, int flag) {
  if (flag == 0) {
    for (int i = 0; i < n; ++i) u[i] = a[i] * a[i];
    return;
  }
  for (int i = 0; i < n; ++i) u[i] = a[i] + 1.0;
}""", params=[("in","a",N),("out","u",N),("val","n"),("val","flag")])

K(name="br_nested_flags", why="nested if on two parameters", loop="for (int f1 : {0, 1}) for (int f2 : {0, 1}) for (int n : {0, 1, 3, 6})", pre="CAPTURE(f1); CAPTURE(f2);",
  src="""
DPGEN_KERNEL void r4_br_nested_flags(DPGEN_IN const double* a, DPGEN_OUT double* u, int n, int f1, int f2) {
  if (f1 == 1) {
    if (f2 == 1) {
      for (int i = 0; i < n; ++i) u[i] = a[i] * a[i];
    } else {
      for (int i = 0; i < n; ++i) u[i] = a[i] * 2.0;
    }
  } else {
    for (int i = 0; i < n; ++i) u[i] = a[i] * a[i] * a[i];
  }
}""", params=[("in","a",N),("out","u",N),("val","n"),("val","f1"),("val","f2")])

K(name="br_arms_different_extent", why="arms write different extents of the same output, other entries set first", loop=LF, pre=PF,
  src="""
DPGEN_KERNEL void r4_br_arms_different_extent(DPGEN_IN const double* a, DPGEN_OUT double* u, int n, int flag) {
  if (flag == 0) {
    for (int i = 0; i < n; ++i) u[i] = a[i] * a[i];
  } else {
    for (int i = 0; i < n; ++i) u[i] = a[i];
    for (int i = 1; i + 1 < n; ++i) u[i] = a[i - 1] * a[i + 1];
  }
}""", params=[("in","a",N),("out","u",N),("val","n"),("val","flag")])

K(name="br_flag_local", why="branch on a local copied from the parameter", loop=LF, pre=PF,
  src="""
DPGEN_KERNEL void r4_br_flag_local(DPGEN_IN const double* a, DPGEN_OUT double* u, int n, int flag) {
  const bool predict = flag == 0;
  if (predict) {
    for (int i = 0; i < n; ++i) u[i] = a[i] * a[i];
  } else {
    for (int i = 0; i < n; ++i) u[i] = 0.5 * a[i];
  }
}""", params=[("in","a",N),("out","u",N),("val","n"),("val","flag")])

K(name="br_else_reads_other_output", why="else arm's second output reads the first output (work array) written by both arms", loop=LF, pre=PF,
  src="""
DPGEN_KERNEL void r4_br_else_reads_other_output(DPGEN_IN const double* a, DPGEN_OUT double* w,
                                                DPGEN_OUT double* v, int n, int flag) {
  if (flag == 0) {
    for (int i = 0; i < n; ++i) w[i] = a[i] + 1.0;
    for (int i = 0; i < n; ++i) v[i] = a[i] * a[i];
  } else {
    for (int i = 0; i < n; ++i) w[i] = a[i] * a[i];
    for (int i = 0; i + 1 < n; ++i) v[i] = w[i] * w[i + 1];
    if (n > 0) v[n - 1] = w[n - 1];
  }
}""", params=[("in","a",N),("out","w",N),("out","v",N),("val","n"),("val","flag")])

# ---------------------------------------------------------------- double** constant rows
LR = "for (auto [n, m] : {std::pair{1, 2}, {1, 3}, {3, 2}, {2, 4}, {4, 3}, {5, 6}})"
K(name="rp_ghost_both", why="ghost rows 0 and m-1 copied from rows 1 and m-2, interior squared", loop=LR,
  src="""
DPGEN_KERNEL void r4_rp_ghost_both(DPGEN_IN double** a, DPGEN_OUT double** b, int n, int m) {
  for (int j = 1; j < m - 1; ++j)
    for (int i = 0; i < n; ++i) b[j][i] = a[j][i] * a[j][i];
  for (int i = 0; i < n; ++i) {
    b[0][i] = a[1][i] * a[0][i];
    b[m - 1][i] = a[m - 2][i] + a[m - 1][i] * a[m - 1][i];
  }
}""", params=[("inr","a","m","n"),("outr","b","m","n"),("val","n"),("val","m")])

K(name="rp_store_then_read_row", why="b[0][i] stored, then b[1][i] reads b[0][i] (work row)", loop=LR,
  src="""
DPGEN_KERNEL void r4_rp_store_then_read_row(DPGEN_IN double** a, DPGEN_OUT double** b, int n, int m) {
  for (int i = 0; i < n; ++i) b[0][i] = a[0][i] * a[1][i];
  for (int i = 0; i < n; ++i) b[1][i] = b[0][i] * b[0][i] + a[m - 1][i];
}""", params=[("inr","a","m","n"),("outr","b","m","n"),("val","n"),("val","m")])

K(name="rp_colsum_into_row0", why="b[0][i] += a[j][i] over all rows after b[0][i] = 0", loop=LR,
  src="""
DPGEN_KERNEL void r4_rp_colsum_into_row0(DPGEN_IN double** a, DPGEN_OUT double** b, int n, int m) {
  for (int i = 0; i < n; ++i) b[0][i] = 0.0;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) b[0][i] += a[j][i] * a[j][i];
}""", params=[("inr","a","m","n"),("outr","b","1","n"),("val","n"),("val","m")])

K(name="rp_const_row_neighbours", why="row 0 read at i-1, i+1; stored to row m-1", loop=LR,
  src="""
DPGEN_KERNEL void r4_rp_const_row_neighbours(DPGEN_IN double** a, DPGEN_OUT double** b, int n, int m) {
  for (int i = 1; i + 1 < n; ++i) b[m - 1][i] = a[0][i + 1] * a[0][i - 1] - a[m - 1][i];
}""", params=[("inr","a","m","n"),("outr","b","m","n"),("val","n"),("val","m")])

K(name="rp_row_overwrite", why="all rows written, then row m-1 overwritten", loop=LR,
  src="""
DPGEN_KERNEL void r4_rp_row_overwrite(DPGEN_IN double** a, DPGEN_OUT double** b, int n, int m) {
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) b[j][i] = a[j][i] * a[j][i];
  for (int i = 0; i < n; ++i) b[m - 1][i] = a[0][i] * 3.0;
}""", params=[("inr","a","m","n"),("outr","b","m","n"),("val","n"),("val","m")])

K(name="rp_ghost_ng", why="ng ghost rows on both sides copied from the nearest interior row",
  loop="for (auto [n, m] : {std::pair{1, 3}, {3, 4}, {2, 6}, {4, 7}}) for (int ng : {1, 2})", pre="if (m < 2 * ng + 1) continue; CAPTURE(ng);",
  src="""
DPGEN_KERNEL void r4_rp_ghost_ng(DPGEN_IN double** a, DPGEN_OUT double** b, int n, int m, int ng) {
  for (int j = ng; j < m - ng; ++j)
    for (int i = 0; i < n; ++i) b[j][i] = a[j][i] * a[j][i];
  for (int j = 0; j < ng; ++j)
    for (int i = 0; i < n; ++i) {
      b[j][i] = a[ng][i];
      b[m - 1 - j][i] = a[m - 1 - ng][i] * 2.0;
    }
}""", params=[("inr","a","m","n"),("outr","b","m","n"),("val","n"),("val","m"),("val","ng")])

K(name="rp_row_from_local", why="constant row through a kernel-level local const int top = m - 1", loop=LR,
  src="""
DPGEN_KERNEL void r4_rp_row_from_local(DPGEN_IN double** a, DPGEN_OUT double** b, int n, int m) {
  const int top = m - 1;
  for (int i = 0; i < n; ++i) {
    b[top][i] = a[top][i] * a[0][i];
    b[0][i] = a[top][i];
  }
}""", params=[("inr","a","m","n"),("outr","b","m","n"),("val","n"),("val","m")])

K(name="rp_const_column", why="constant column a[j][0] and a[j][n-1]", loop=LR,
  src="""
DPGEN_KERNEL void r4_rp_const_column(DPGEN_IN double** a, DPGEN_OUT double** b, int n, int m) {
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) b[j][i] = a[j][0] * a[j][n - 1] + a[j][i];
}""", params=[("inr","a","m","n"),("outr","b","m","n"),("val","n"),("val","m")])

K(name="rp_mixed_flat", why="double** input and a flat weight input", loop=LR,
  src="""
DPGEN_KERNEL void r4_rp_mixed_flat(DPGEN_IN double** a, DPGEN_IN const double* w, DPGEN_OUT double* r,
                                   int n, int m) {
  for (int i = 0; i < n; ++i) r[i] = w[i] * a[0][i] * a[m - 1][i];
}""", params=[("inr","a","m","n"),("in","w","n"),("out","r","n"),("val","n"),("val","m")])

K(name="rp_rows_in_branch", why="constant rows stored in param-branch arms",
  loop="for (int flag : {0, 1}) for (auto [n, m] : {std::pair{1, 2}, {3, 2}, {4, 3}})", pre="CAPTURE(flag);",
  src="""
DPGEN_KERNEL void r4_rp_rows_in_branch(DPGEN_IN double** a, DPGEN_OUT double** b, int n, int m, int flag) {
  if (flag == 0) {
    for (int i = 0; i < n; ++i) { b[0][i] = a[1][i]; b[1][i] = a[0][i] * a[0][i]; }
  } else {
    for (int i = 0; i < n; ++i) { b[0][i] = a[m - 1][i] * a[0][i]; b[1][i] = 0.0; }
  }
}""", params=[("inr","a","m","n"),("outr","b","2","n"),("val","n"),("val","m"),("val","flag")])

K(name="rp_row_read_and_accum", why="row 0 of the output read back while accumulating into row 1", loop=LR,
  src="""
DPGEN_KERNEL void r4_rp_row_read_and_accum(DPGEN_IN double** a, DPGEN_OUT double** b, int n, int m) {
  for (int i = 0; i < n; ++i) { b[0][i] = a[0][i] * a[0][i]; b[1][i] = 0.0; }
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) b[1][i] += b[0][i] * a[j][i];
}""", params=[("inr","a","m","n"),("outr","b","2","n"),("val","n"),("val","m")])

# ---------------------------------------------------------------- index macros with kernel-level locals
K(name="mac_ptr_locals_stencil", why="IDX with locals from pointers, 5-point stencil",
  loop="for (int n : {1, 2, 3, 5})",
  pre="int lo = 2, hi = lo + n - 1; const int* xmin = &lo; const int* xmax = &hi;",
  includes="#define IDX(i, j) ((i) - (x_min - 1) + ((j) - (x_min - 1)) * (x_max - x_min + 3))\n",
  src="""
DPGEN_KERNEL void r4_mac_ptr_locals_stencil(const int* xmin, const int* xmax, DPGEN_IN const double* u,
                                            DPGEN_OUT double* v) {
  int x_min = *xmin, x_max = *xmax;
  for (int k = x_min; k <= x_max; k++)
    for (int j = x_min; j <= x_max; j++)
      v[IDX(j, k)] = u[IDX(j - 1, k)] * u[IDX(j + 1, k)] + u[IDX(j, k - 1)] - u[IDX(j, k + 1)] * u[IDX(j, k)];
}""", params=[("val","xmin"),("val","xmax"),("in","u","(n+2)*(n+2)"),("out","v","(n+2)*(n+2)")])

K(name="mac_ld_local", why="IDX uses const int ld = nx + 2 * ng", loop=L2p,
  includes="#define IDX(i, j) ((i) + ng + ((j) + ng) * ld)\n",
  src="""
DPGEN_KERNEL void r4_mac_ld_local(DPGEN_IN const double* u, DPGEN_OUT double* v, int n, int m) {
  const int ng = 1;
  const int ld = n + 2 * ng;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i)
      v[IDX(i, j)] = u[IDX(i - 1, j)] * u[IDX(i + 1, j)] + u[IDX(i, j - 1)] * u[IDX(i, j + 1)];
}""", params=[("in","u","(n+2)*(m+2)"),("out","v","(n+2)*(m+2)"),("val","n"),("val","m")])

K(name="mac_local_changes", why="macro's local offset changes between the nests",
  includes="#define AT(i) ((i) + off)\n",
  src="""
DPGEN_KERNEL void r4_mac_local_changes(DPGEN_IN const double* a, DPGEN_OUT double* u, int n) {
  int off = 0;
  for (int i = 0; i < n; ++i) u[AT(i)] = a[AT(i)] * a[AT(i)];
  off = n;
  for (int i = 0; i < n; ++i) u[AT(i)] = a[i] * 3.0 + a[AT(i)];
}""", params=[("in","a","2*n"),("out","u","2*n"),("val","n")])

K(name="mac_nested", why="macro using another macro with a local", loop=L2p,
  includes="#define LD (nx + 2)\n#define IDX(i, j) ((i) + 1 + ((j) + 1) * LD)\n",
  src="""
DPGEN_KERNEL void r4_mac_nested(DPGEN_IN const double* u, DPGEN_OUT double* v, int n, int m) {
  const int nx = n;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i)
      v[IDX(i, j)] = u[IDX(i - 1, j)] - u[IDX(i, j)] * u[IDX(i, j - 1)];
}""", params=[("in","u","(n+2)*(m+2)"),("out","v","(n+2)*(m+2)"),("val","n"),("val","m")])

K(name="mac_local_from_n", why="kernel-level local int h = n / 2 used in macro and bounds",
  includes="#define MIR(i) (h - 1 - (i))\n",
  src="""
DPGEN_KERNEL void r4_mac_local_from_n(DPGEN_IN const double* a, DPGEN_OUT double* u, int n) {
  const int h = n / 2;
  for (int i = 0; i < h; ++i) u[i] = a[MIR(i)] * a[i + h];
}""", params=[("in","a",N),("out","u",N),("val","n")])

# ---------------------------------------------------------------- generated-name clashes
K(name="nm_dpgen_sum_s", why="an accumulator named dpgen_sum_s and one named s",
  src="""
DPGEN_KERNEL void r4_nm_dpgen_sum_s(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 0.0, dpgen_sum_s = 1.0;
  for (int i = 0; i < n; ++i) {
    s += a[i] * a[i];
    dpgen_sum_s += a[i];
  }
  out[0] = s * dpgen_sum_s;
}""", params=[("in","a",N),("out","out","1"),("val","n")])

K(name="nm_s_dot", why="accumulator s next to a local s_dot and s_adj",
  src="""
DPGEN_KERNEL void r4_nm_s_dot(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 0.0;
  for (int i = 0; i < n; ++i) s += a[i] * a[i];
  const double s_dot = 2.0 * s;
  const double s_adj = s_dot * s;
  out[0] = s_adj + s_dot;
}""", params=[("in","a",N),("out","out","1"),("val","n")])

K(name="nm_params_adj_dot", why="inputs named u, u_adj, u_dot",
  src="""
DPGEN_KERNEL void r4_nm_params_adj_dot(DPGEN_IN const double* u, DPGEN_IN const double* u_adj,
                                       DPGEN_IN const double* u_dot, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) out[i] = u[i] * u_adj[i] + u_dot[i] * u_dot[i];
}""", params=[("in","u",N),("in","u_adj",N),("in","u_dot",N),("out","out",N),("val","n")])

K(name="nm_out_adj_param", why="output out and an input named out_adj",
  src="""
DPGEN_KERNEL void r4_nm_out_adj_param(DPGEN_IN const double* out_adj, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) out[i] = out_adj[i] * out_adj[i];
}""", params=[("in","out_adj",N),("out","out",N),("val","n")])

K(name="nm_lambda_acc_names", why="lambda named edge/interior, local named acc/hit",
  src="""
DPGEN_KERNEL void r4_nm_lambda_acc_names(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  auto edge = [&](int i) { return u[i] * u[i]; };
  auto interior = [&](int i) { return edge(i) + u[i]; };
  double acc = 0.0;
  for (int i = 0; i < n; ++i) acc += interior(i);
  for (int i = 0; i < n; ++i) {
    const double hit = acc * u[i];
    out[i] = hit + edge(i);
  }
}""", params=[("in","u",N),("out","out",N),("val","n")])

K(name="nm_array_dpgen", why="std::array named dpgen_sum_s_v and a local c_i", includes=AR,
  src="""
DPGEN_KERNEL void r4_nm_array_dpgen(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  const std::array<double, 2> dpgen_sum_s_v{0.5, 1.5};
  double s = 0.0;
  for (int i = 0; i < n; ++i) s += dpgen_sum_s_v[i % 2] * u[i];
  for (int c_i = 0; c_i < n; ++c_i) out[c_i] = s * u[c_i];
}""", params=[("in","u",N),("out","out",N),("val","n")])

K(name="nm_counter_names", why="loop counters named lo_i, hi_i, in_lo_i, parallel_ok",
  src="""
DPGEN_KERNEL void r4_nm_counter_names(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  const int lo_i = 1, hi_i = n - 1;
  const bool parallel_ok = true;
  for (int in_lo_i = lo_i; in_lo_i < hi_i; ++in_lo_i)
    out[in_lo_i] = parallel_ok ? u[in_lo_i - 1] * u[in_lo_i + 1] : 0.0;
}""", params=[("in","u",N),("out","out",N),("val","n")])

K(name="nm_recompute_name", why="a helper named like the generated recompute/nest functions",
  src="""
static inline double r4_nm_recompute_name_recompute(double x) { return x * x; }
static inline double r4_nm_recompute_name_nest1_adjoint(double x) { return 2.0 * x; }
DPGEN_KERNEL void r4_nm_recompute_name(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  double s = 0.0;
  for (int i = 0; i < n; ++i) s += r4_nm_recompute_name_recompute(u[i]);
  for (int i = 0; i < n; ++i) out[i] = s * r4_nm_recompute_name_nest1_adjoint(u[i]);
}""", params=[("in","u",N),("out","out",N),("val","n")])

K(name="nm_local_out_v", why="a local named out_v / dpgen_sum_s_b while the output is out",
  src="""
DPGEN_KERNEL void r4_nm_local_out_v(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  double out_v = 0.0, dpgen_sum_s_b = 1.0;
  for (int i = 0; i < n; ++i) { out_v += u[i]; dpgen_sum_s_b += u[i] * u[i]; }
  out[0] = out_v * dpgen_sum_s_b;
}""", params=[("in","u",N),("out","out","1"),("val","n")])

# ---------------------------------------------------------------- minimal repros of the defects found
K(name="min_lam_array_copy_stale", why="WRONG: [=] copies a local C array, the array changes before the call; the inlined call reads the new value",
  src="""
DPGEN_KERNEL void r4_min_lam_array_copy_stale(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  double w[1] = {1.0};
  auto f = [=](int i) { return w[0] * u[i]; };
  w[0] = 5.0;
  for (int i = 0; i < n; ++i) out[i] = f(i) * u[i];
}""", params=[("in","u",N),("out","out",N),("val","n")])

K(name="min_local_dpgen_prefix_hang", why="CRASH (hang): a local named dpgen_<x>; the renaming loop keeps the reserved prefix forever",
  src="""
DPGEN_KERNEL void r4_min_local_dpgen_prefix_hang(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    const double dpgen_x = u[i] * u[i];
    out[i] = dpgen_x + u[i];
  }
}""", params=[("in","u",N),("out","out",N),("val","n")])

# ---------------------------------------------------------------- second wave: around the defects
K(name="lam_stdarray_copy_stale", why="[=] copies a std::array that changes before the call", includes=AR,
  src="""
DPGEN_KERNEL void r4_lam_stdarray_copy_stale(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  std::array<double, 2> w{1.0, 2.0};
  auto f = [=](int i) { return w[0] * u[i] + w[1]; };
  w[0] = 4.0;
  for (int i = 0; i < n; ++i) out[i] = f(i) * u[i];
}""", params=[("in","u",N),("out","out",N),("val","n")])

K(name="lam_array_ref_changes", why="[&] captures a local array that changes before the call (must see the new value)",
  src="""
DPGEN_KERNEL void r4_lam_array_ref_changes(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  double w[2] = {1.0, 2.0};
  auto f = [&](int i) { return w[0] * u[i] + w[1]; };
  w[0] = 4.0;
  for (int i = 0; i < n; ++i) out[i] = f(i) * u[i];
}""", params=[("in","u",N),("out","out",N),("val","n")])

K(name="lam_array_copy_in_loop_changes", why="[=] copy of a local array changed inside the loop before each call",
  src="""
DPGEN_KERNEL void r4_lam_array_copy_in_loop_changes(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  double w[1] = {1.0};
  auto f = [=](int i) { return w[0] * u[i]; };
  for (int i = 0; i < n; ++i) {
    w[0] = u[i];
    out[i] = f(i) + w[0];
  }
}""", params=[("in","u",N),("out","out",N),("val","n")])

K(name="lam_scalar_copy_in_loop_changes", why="[=] copy of a scalar changed inside the loop before each call",
  src="""
DPGEN_KERNEL void r4_lam_scalar_copy_in_loop_changes(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  double c = 1.0;
  auto f = [=](int i) { return c * u[i]; };
  for (int i = 0; i < n; ++i) {
    c = u[i];
    out[i] = f(i) + c;
  }
}""", params=[("in","u",N),("out","out",N),("val","n")])

K(name="nm_scalarised_array_clash", why="local array w[2] next to user locals w_0 and w_0_1",
  src="""
DPGEN_KERNEL void r4_nm_scalarised_array_clash(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  double w[2] = {1.0, 2.0};
  const double w_0 = 7.0, w_1 = 11.0;
  w[0] = 3.0;
  const double w_0_1 = 13.0;
  for (int i = 0; i < n; ++i) out[i] = (w[0] + w_0 * w_0_1) * u[i] * u[i] + w[1] * w_1 * u[i];
}""", params=[("in","u",N),("out","out",N),("val","n")])

K(name="nm_counter_i_1", why="a local i_1 while the lambda call renames its counter i to i_1",
  src="""
DPGEN_KERNEL void r4_nm_counter_i_1(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  auto f = [&](int i) { return u[i] * u[i]; };
  for (int i = 0; i < n; ++i) {
    const int i_1 = n - 1 - i;
    out[i] = f(i) + u[i_1];
  }
}""", params=[("in","u",N),("out","out",N),("val","n")])

K(name="acc_same_name_two_blocks", why="two accumulators named s in separate blocks, both read after their loops",
  src="""
DPGEN_KERNEL void r4_acc_same_name_two_blocks(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  {
    double s = 0;
    for (int i = 0; i < n; ++i) s += a[i] * a[i];
    out[0] = s;
  }
  {
    double s = 1;
    for (int i = 0; i < n; ++i) s += a[i];
    out[1] = s * s;
  }
}""", params=[("in","a",N),("out","out","2"),("val","n")])

K(name="acc_two_kernels_one_file", why="two kernels with an accumulator s in one file", kernel="r4_acc_two_kernels_one_file",
  src="""
DPGEN_KERNEL void r4_acc_two_kernels_one_file_b(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 2.0;
  for (int i = 0; i < n; ++i) s += a[i];
  out[0] = s;
}
DPGEN_KERNEL void r4_acc_two_kernels_one_file(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 0;
  for (int i = 0; i < n; ++i) s += a[i] * a[i];
  out[0] = s * s;
}""", params=[("in","a",N),("out","out","1"),("val","n")])

K(name="acc_in_elseif_arms_shared", why="one accumulator s accumulated in 3 else-if arms then read", loop=LF, pre=PF,
  src="""
DPGEN_KERNEL void r4_acc_in_elseif_arms_shared(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, int flag) {
  double s = 1.0;
  if (flag == 0) {
    for (int i = 0; i < n; ++i) s += a[i];
  } else if (flag == 1) {
    for (int i = 0; i < n; ++i) s -= a[i] * a[i];
  } else {
    for (int i = 1; i < n; ++i) s += a[i] * a[i - 1];
  }
  out[0] = s * s;
}""", params=[("in","a",N),("out","out","1"),("val","n"),("val","flag")])

K(name="acc_cond_after_loop", why="accumulator, then an if on data reading it, then accumulated again",
  src="""
DPGEN_KERNEL void r4_acc_cond_after_loop(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 0;
  for (int i = 0; i < n; ++i) s += a[i];
  if (s > 0) s = s * s;
  out[0] = s;
}""", params=[("in","a",N),("out","out","1"),("val","n")])

K(name="acc_used_in_loop_bound_expr", why="accumulator read in a later loop together with a triangular bound",
  src="""
DPGEN_KERNEL void r4_acc_used_in_loop_bound_expr(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  double s = 0;
  for (int i = 0; i < n; ++i) s += a[i] * a[i];
  for (int i = 0; i < n; ++i)
    for (int j = 0; j <= i; ++j) e[i * n + j] = s * a[j] - a[i];
}""", params=[("in","a",N),("out","e","n*n"),("val","n")])

K(name="acc_inner_tri_outer_sum", why="triangular inner accumulator feeding an outer accumulator",
  src="""
DPGEN_KERNEL void r4_acc_inner_tri_outer_sum(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double tot = 0;
  for (int i = 0; i < n; ++i) {
    double s = 0;
    for (int j = i; j < n; ++j) s += a[j];
    tot += s * s;
  }
  out[0] = tot;
}""", params=[("in","a",N),("out","out","1"),("val","n")])

K(name="acc_float_pure", why="float kernel: two float accumulators with -=", T="float",
  src="""
DPGEN_KERNEL void r4_acc_float_pure(DPGEN_IN const float* a, DPGEN_IN const float* b, DPGEN_OUT float* out, int n) {
  float s = 0.0f, t = 1.0f;
  for (int i = 0; i < n; ++i) { s += a[i] * b[i]; t -= b[i] * b[i]; }
  out[0] = s * t;
}""", params=[("in","a",N),("in","b",N),("out","out","1"),("val","n")])

K(name="min_le_min_bound", why="REJECTED, should be accepted: inclusive upper bound j <= std::min(n - 1, i + 1) (the exclusive j < std::min(n, i + 2) is accepted)", includes=CM,
  src="""
DPGEN_KERNEL void r4_min_le_min_bound(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    double s = 0;
    for (int j = i; j <= std::min(n - 1, i + 1); ++j) s += a[j] * a[j];
    out[i] = s;
  }
}""", params=[("in","a",N),("out","out",N),("val","n")])

K(name="min_lam_mutable_state", why="WRONG: a mutable lambda's by-copy capture persists across calls (c = 2, 4, 8, ...); the inlined call restarts from the kernel's c every iteration",
  src="""
DPGEN_KERNEL void r4_min_lam_mutable_state(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  double c = 1.0;
  auto f = [c, u](int i) mutable { c = c * 2.0; return c * u[i]; };
  for (int i = 0; i < n; ++i) out[i] = f(i) * u[i];
}""", params=[("in","u",N),("out","out",N),("val","n")])

# ---------------------------------------------------------------- third wave
K(name="acc_running_across_rows", why="accumulator declared outside the outer loop, not reset per row (a running sum across rows)", loop=L2,
  src="""
DPGEN_KERNEL void r4_acc_running_across_rows(DPGEN_IN const double* a, DPGEN_OUT double* r, int n, int m) {
  double s = 0;
  for (int j = 0; j < m; ++j) {
    for (int i = 0; i < n; ++i) s += a[j * n + i] * a[j * n + i];
    r[j] = s;
  }
}""", params=[("in","a","n*m"),("out","r","m"),("val","n"),("val","m")])

K(name="acc_continue", why="accumulating loop with continue",
  src="""
DPGEN_KERNEL void r4_acc_continue(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 0;
  for (int i = 0; i < n; ++i) {
    if (i % 3 == 1) continue;
    s += a[i] * a[i];
  }
  out[0] = s * s;
}""", params=[("in","a",N),("out","out","1"),("val","n")])

K(name="acc_read_before_and_after", why="accumulator init read by an output before the loop, read again after", loop=L1p,
  src="""
DPGEN_KERNEL void r4_acc_read_before_and_after(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = a[0] * a[0];
  out[0] = s;
  for (int i = 1; i < n; ++i) s += a[i];
  out[1] = s * s;
}""", params=[("in","a",N),("out","out","2"),("val","n")])

K(name="acc_mixed_forms", why="s = s + x in one arm, s += y in the other",
  src="""
DPGEN_KERNEL void r4_acc_mixed_forms(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 0;
  for (int i = 0; i < n; ++i) {
    if (i % 2 == 0) s = s + a[i] * a[i];
    else s += 2.0 * a[i];
  }
  out[0] = s * s;
}""", params=[("in","a",N),("out","out","1"),("val","n")])

K(name="acc_parity_start", why="accumulator over a moving parity loop inside a triangle", loop=L1,
  src="""
DPGEN_KERNEL void r4_acc_parity_start(DPGEN_IN const double* a, DPGEN_OUT double* r, int n) {
  for (int j = 0; j < n; ++j) {
    double s = 0;
    for (int i = j % 2; i <= j; i += 2) s += a[i] * a[j - i];
    r[j] = s;
  }
}""", params=[("in","a",N),("out","r",N),("val","n")])

K(name="lam_copy_acc_before_loop", why="[=] lambda made before the accumulation loop copies s = 0, called after (stale)",
  src="""
DPGEN_KERNEL void r4_lam_copy_acc_before_loop(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 1.0;
  auto f = [=](double x) { return s * x; };
  for (int i = 0; i < n; ++i) s += a[i] * a[i];
  out[0] = f(s);
}""", params=[("in","a",N),("out","out","1"),("val","n")])

K(name="lam_ref_acc_before_loop", why="[&] lambda made before the accumulation loop, called after (sees the sum)",
  src="""
DPGEN_KERNEL void r4_lam_ref_acc_before_loop(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 1.0;
  auto f = [&](double x) { return s * x; };
  for (int i = 0; i < n; ++i) s += a[i] * a[i];
  out[0] = f(a[0 * n]) + f(2.0);
}""", params=[("in","a","n+1"),("out","out","1"),("val","n")])

K(name="lam_ref_acc_in_loop", why="[&] lambda reading the accumulator inside its loop (a recurrence)",
  src="""
DPGEN_KERNEL void r4_lam_ref_acc_in_loop(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 1.0;
  auto g = [&]() { return 0.5 * s; };
  for (int i = 0; i < n; ++i) s += g() * a[i];
  out[0] = s;
}""", params=[("in","a",N),("out","out","1"),("val","n")])

K(name="br_same_cond_twice", why="if (flag == 0) nest; if (flag == 0) nest: not exclusive, both write u", loop=LF, pre=PF,
  src="""
DPGEN_KERNEL void r4_br_same_cond_twice(DPGEN_IN const double* a, DPGEN_OUT double* u, int n, int flag) {
  if (flag == 0)
    for (int i = 0; i < n; ++i) u[i] = a[i] * a[i];
  if (flag == 0)
    for (int i = 0; i < n; ++i) u[i] = a[i] * 3.0;
}""", params=[("in","a",N),("out","u",N),("val","n"),("val","flag")])

K(name="br_local_changes_between", why="int d = dir; if (d == 1) nest; d = 2; if (d == 2) nest: both run", loop=LF, pre=PF,
  src="""
DPGEN_KERNEL void r4_br_local_changes_between(DPGEN_IN const double* a, DPGEN_OUT double* u, int n, int flag) {
  int d = flag;
  if (d == 1)
    for (int i = 0; i < n; ++i) u[i] = a[i] * a[i];
  d = 2;
  if (d == 2)
    for (int i = 0; i < n; ++i) u[i] = a[i] + u[i] * 0.0 + 1.0;
}""", params=[("in","a",N),("out","u",N),("val","n"),("val","flag")])

K(name="br_local_changes_between_w", why="int d = dir; if (d == 1) nest; d = 2; if (d == 2) nest (overwrite, no readback)", loop=LF, pre=PF,
  src="""
DPGEN_KERNEL void r4_br_local_changes_between_w(DPGEN_IN const double* a, DPGEN_OUT double* u, int n, int flag) {
  int d = flag;
  if (d == 1)
    for (int i = 0; i < n; ++i) u[i] = a[i] * a[i];
  d = 2;
  if (d == 2)
    for (int i = 0; i < n; ++i) u[i] = 3.0 * a[i];
}""", params=[("in","a",N),("out","u",N),("val","n"),("val","flag")])

K(name="br_param_assigned_in_arm", why="if (flag == 0) { nest; flag = 1; } if (flag == 1) nest: both run for flag 0", loop=LF, pre=PF,
  src="""
DPGEN_KERNEL void r4_br_param_assigned_in_arm(DPGEN_IN const double* a, DPGEN_OUT double* u, int n, int flag) {
  if (flag == 0) {
    for (int i = 0; i < n; ++i) u[i] = a[i] * a[i];
    flag = 1;
  }
  if (flag == 1)
    for (int i = 0; i < n; ++i) u[i] = 3.0 * a[i];
}""", params=[("in","a",N),("out","u",N),("val","n"),("val","flag")])

K(name="br_param_assigned_before", why="flag = 1 - flag before two exclusive ifs", loop="for (int flag : {0, 1}) for (int n : {0, 1, 2, 3, 7})", pre=PF,
  src="""
DPGEN_KERNEL void r4_br_param_assigned_before(DPGEN_IN const double* a, DPGEN_OUT double* u, DPGEN_OUT double* v, int n, int flag) {
  flag = 1 - flag;
  if (flag == 0)
    for (int i = 0; i < n; ++i) u[i] = a[i] * a[i];
  else
    for (int i = 0; i < n; ++i) u[i] = 2.0 * a[i];
  for (int i = 0; i < n; ++i) v[i] = flag * a[i] * a[i];
}""", params=[("in","a",N),("out","u",N),("out","v",N),("val","n"),("val","flag")])

K(name="par_negative_mod_start", why="start 1 + (j - 1) % 2: C++ % is -1 at j = 0, so the start is 0, 1, 2, 1, 2, ...", loop=L2,
  src="""
DPGEN_KERNEL void r4_par_negative_mod_start(DPGEN_IN const double* a, DPGEN_OUT double* e, int n, int m) {
  for (int j = 0; j < m; ++j)
    for (int i = 1 + (j - 1) % 2; i < n; i += 2)
      e[j * n + i] = a[j * n + i] * a[j * n + i] + 1.0;
}""", params=[("in","a","n*m"),("out","e","n*m"),("val","n"),("val","m")])

K(name="par_negative_mod_start_acc", why="accumulator over i = 1 + (j - 2) % 3, step 3 (start -1 +1 = 0 at j = 1)", loop=L2,
  src="""
DPGEN_KERNEL void r4_par_negative_mod_start_acc(DPGEN_IN const double* a, DPGEN_OUT double* r, int n, int m) {
  for (int j = 0; j < m; ++j) {
    double s = 0;
    for (int i = 2 + (j - 2) % 3; i < n; i += 3) s += a[j * n + i] * a[j * n + i];
    r[j] = s;
  }
}""", params=[("in","a","n*m"),("out","r","m"),("val","n"),("val","m")])

K(name="tri_half_bound", why="bound j <= i / 2",
  src="""
DPGEN_KERNEL void r4_tri_half_bound(DPGEN_IN const double* a, DPGEN_OUT double* r, int n) {
  for (int i = 0; i < n; ++i) {
    double s = 0;
    for (int j = 0; j <= i / 2; ++j) s += a[j] * a[i - j];
    r[i] = s;
  }
}""", params=[("in","a",N),("out","r",N),("val","n")])

K(name="tri_n_minus_2i", why="bound j < n - 2 * i (negative trip counts)",
  src="""
DPGEN_KERNEL void r4_tri_n_minus_2i(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n - 2 * i; ++j)
      e[i * n + j] = a[j + i] * a[j + 2 * i];
}""", params=[("in","a",N),("out","e","n*n"),("val","n")])

# ---------------------------------------------------------------- fourth wave
K(name="acc_one_arm_only", why="accumulator updated only in one if arm on a parameter, read after the if", loop=LF, pre=PF,
  src="""
DPGEN_KERNEL void r4_acc_one_arm_only(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, int flag) {
  double s = 1.0;
  if (flag == 0)
    for (int i = 0; i < n; ++i) s += a[i] * a[i];
  out[0] = s * s;
}""", params=[("in","a",N),("out","out","1"),("val","n"),("val","flag")])

K(name="acc_per_row_read_later_nest", why="per-row accumulator in a triangle, stored, and the stored value read in a later nest", 
  src="""
DPGEN_KERNEL void r4_acc_per_row_read_later_nest(DPGEN_IN const double* a, DPGEN_OUT double* r,
                                                 DPGEN_OUT double* q, int n) {
  for (int i = 0; i < n; ++i) {
    double s = 0;
    for (int j = 0; j <= i; ++j) s += a[j];
    r[i] = s * s;
  }
  for (int i = 0; i < n; ++i) q[i] = r[i] * a[i];
}""", params=[("in","a",N),("out","r",N),("out","q",N),("val","n")])

K(name="acc_rowptr", why="accumulator over a constant row of a double** input", loop=LR,
  src="""
DPGEN_KERNEL void r4_acc_rowptr(DPGEN_IN double** a, DPGEN_OUT double* out, int n, int m) {
  double s = 0;
  for (int i = 0; i < n; ++i) s += a[0][i] * a[m - 1][i];
  out[0] = s * s;
}""", params=[("inr","a","m","n"),("out","out","1"),("val","n"),("val","m")])

K(name="acc_macro_locals", why="accumulator over an index macro with kernel-level locals", loop=L2p,
  includes="#define IDX(i, j) ((i) + (j) * ld)\n",
  src="""
DPGEN_KERNEL void r4_acc_macro_locals(DPGEN_IN const double* a, DPGEN_OUT double* r, int n, int m) {
  const int ld = n;
  for (int j = 0; j < m; ++j) {
    double s = 0;
    for (int i = 0; i < n; ++i) s += a[IDX(i, j)] * a[IDX(i, j)];
    r[j] = s;
  }
}""", params=[("in","a","n*m"),("out","r","m"),("val","n"),("val","m")])

K(name="acc_lambda_term", why="accumulating a lambda's value",
  src="""
DPGEN_KERNEL void r4_acc_lambda_term(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  auto e = [&](int i) { return a[i] * a[i + 1]; };
  double s = 0;
  for (int i = 0; i + 1 < n; ++i) s += e(i);
  out[0] = s * s;
}""", params=[("in","a",N),("out","out","1"),("val","n")])

K(name="arr_parity_table", why="std::array table read at a moving-parity counter", includes=AR, loop=L2,
  src="""
DPGEN_KERNEL void r4_arr_parity_table(DPGEN_IN const double* a, DPGEN_OUT double* e, int n, int m) {
  const std::array<double, 2> w{0.5, 2.0};
  for (int j = 0; j < m; ++j)
    for (int i = j % 2; i < n; i += 2)
      e[j * n + i] = w[j % 2] * a[j * n + i] * a[j * n + i];
}""", params=[("in","a","n*m"),("out","e","n*m"),("val","n"),("val","m")])

K(name="arr_unroll_strided_store", why="std::array filled by an unrolled step-2 loop, read after", includes=AR,
  src="""
DPGEN_KERNEL void r4_arr_unroll_strided_store(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    std::array<double, 4> b{};
    for (int m = 0; m < 4; m += 2) b[m] = u[i + m] * u[i + m];
    out[i] = b[0] + b[1] + b[2] * b[0] + b[3];
  }
}""", params=[("in","u","n+4"),("out","out",N),("val","n")])

K(name="br_elseif_accum_rows", why="exclusive arms: one a triangular nest, the other a parity nest, same output", loop="for (int flag : {0, 1, 2}) for (int n : {0, 1, 2, 3, 6})", pre=PF,
  src="""
DPGEN_KERNEL void r4_br_elseif_accum_rows(DPGEN_IN const double* a, DPGEN_OUT double* e, int n, int flag) {
  if (flag == 0) {
    for (int i = 0; i < n; ++i)
      for (int j = 0; j <= i; ++j) e[i * n + j] = a[i] * a[j];
  } else if (flag == 1) {
    for (int i = 0; i < n; ++i)
      for (int j = i % 2; j < n; j += 2) e[i * n + j] = a[j] * a[j] * a[i];
  }
}""", params=[("in","a",N),("out","e","n*n"),("val","n"),("val","flag")])

K(name="rp_ghost_rows_triangle", why="double** with a triangular interior and constant ghost rows", loop="for (auto [n, m] : {std::pair{1, 2}, {3, 3}, {4, 5}})",
  src="""
DPGEN_KERNEL void r4_rp_ghost_rows_triangle(DPGEN_IN double** a, DPGEN_OUT double** b, int n, int m) {
  for (int i = 0; i < n; ++i) b[0][i] = a[m - 1][i] * a[0][i];
  for (int j = 1; j < m; ++j)
    for (int i = 0; i < n && i < j; ++i) b[j][i] = a[j][i] * a[j - 1][i];
}""", params=[("inr","a","m","n"),("outr","b","m","n"),("val","n"),("val","m")])

K(name="rp_ghost_rows_triangle_min", why="double** with a std::min triangular interior and constant row 0", includes=CM, loop="for (auto [n, m] : {std::pair{1, 2}, {3, 3}, {4, 5}})",
  src="""
DPGEN_KERNEL void r4_rp_ghost_rows_triangle_min(DPGEN_IN double** a, DPGEN_OUT double** b, int n, int m) {
  for (int i = 0; i < n; ++i) b[0][i] = a[m - 1][i] * a[0][i];
  for (int j = 1; j < m; ++j)
    for (int i = 0; i < std::min(n, j); ++i) b[j][i] = a[j][i] * a[j - 1][i];
}""", params=[("inr","a","m","n"),("outr","b","m","n"),("val","n"),("val","m")])
