// lambda_accumulators (tests/styles/): each kernel's adjoint against differences and the
// dot-product test and its tangent (support/adjoint_check.hpp), and its value against the
// same reduction written out here, on several sizes.
#include "dpgen/annotate.hpp"
#include "lambda_accumulators_adjoint.hpp"
#include "lambda_accumulators_kernels.hpp"
#include "lambda_accumulators_tangent.hpp"
#include "support/adjoint_check.hpp"

#include "same_bits.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace {

using dpgen_test::wavy;

// One input of `n` values, `m` outputs; `expect(a)` the outputs as a plain loop computes them.
// (DPGEN_ACC_CASE(k): the name and the three functions of a kernel `k(a, out, n)`.)
#define DPGEN_ACC_CASE(k) #k, k, k##_adjoint, k##_tangent
struct Case {
  const char* name;
  std::function<void(const double*, double*, int)> kernel;
  std::function<void(const double*, double*, const double*, int)> adjoint;
  std::function<void(const double*, const double*, double*, double*, int)> tangent;
  std::function<std::vector<double>(const std::vector<double>&)> expect;
  size_t outputs; // 0: one per row (row_sums: n = rows * 4)
};

void check(const Case& c, int n) {
  INFO(c.name);
  CAPTURE(n);
  const size_t N = size_t(n), M = c.outputs ? c.outputs : N / 4;
  // the value, against the reduction written out (the same sums in the same order)
  const std::vector<double> a = wavy(N, 0.3, 1.0);
  std::vector<double> out(M, std::nan(""));
  c.kernel(a.data(), out.data(), n);
  CHECK(dpgen_test::same_values(out, c.expect(a)));
  dpgen_test::Problem<double> p;
  p.in_sizes = {N};
  p.out_sizes = {M};
  p.forward = [&](auto in, auto o) { c.kernel(in[0], o[0], n); };
  p.adjoint = [&](auto in, auto adj, auto seed) { c.adjoint(in[0], adj[0], seed[0], n); };
  p.tangent = [&](auto in, auto dir, auto o, auto od) { c.tangent(in[0], dir[0], o[0], od[0], n); };
  dpgen_test::check_adjoint(p);
}

} // namespace

TEST_CASE("styles: accumulators updated inside lambdas") {
  const std::vector<Case> cases = {
      {DPGEN_ACC_CASE(energy_lambda),
       [](const std::vector<double>& a) {
         double s = 0.0;
         for (double x : a)
           s += x * x;
         return std::vector<double>{s};
       },
       1},
      {"row_sums_lambda", [](auto a, auto o, int n) { row_sums_lambda(a, o, 4, n / 4); },
       [](auto a, auto aa, auto s, int n) { row_sums_lambda_adjoint(a, aa, s, 4, n / 4); },
       [](auto a, auto d, auto o, auto od, int n) {
         row_sums_lambda_tangent(a, d, o, od, 4, n / 4);
       },
       [](const std::vector<double>& a) {
         std::vector<double> o(a.size() / 4);
         for (size_t j = 0; j < o.size(); ++j) {
           double s = 1.0;
           for (size_t i = 0; i < 4; ++i)
             s += std::sin(a[j * 4 + i]);
           o[j] = s;
         }
         return o;
       },
       0},
      {DPGEN_ACC_CASE(max_lambda),
       [](const std::vector<double>& a) {
         double m = -1e300;
         for (double x : a)
           m = std::max(m, x * x);
         return std::vector<double>{m};
       },
       1},
      {DPGEN_ACC_CASE(moments_lambda),
       [](const std::vector<double>& a) {
         double s = 0.0, q = 0.0;
         for (double x : a)
           for (double y : {x, 0.5 * x}) {
             s += y;
             q += y * y;
           }
         return std::vector<double>{s, q};
       },
       2},
      {DPGEN_ACC_CASE(positive_lambda),
       [](const std::vector<double>& a) {
         double s = 0.0;
         for (double x : a)
           if (!(x < 0.0))
             s += x * x;
         return std::vector<double>{s};
       },
       1},
      {DPGEN_ACC_CASE(inline_lambda),
       [](const std::vector<double>& a) {
         double s = 0.0;
         for (double x : a)
           s -= x * x * x;
         return std::vector<double>{s};
       },
       1},
      {DPGEN_ACC_CASE(nested_lambda),
       [](const std::vector<double>& a) {
         double s = 0.0;
         const size_t n = a.size();
         for (size_t i = 0; i < n; ++i) {
           s += a[i] * a[i];
           s += a[n - 1 - i] * a[n - 1 - i];
         }
         return std::vector<double>{s};
       },
       1},
      {DPGEN_ACC_CASE(energy_helper),
       [](const std::vector<double>& a) {
         double s = 0.0;
         for (double x : a)
           s += x * x;
         return std::vector<double>{s};
       },
       1},
      {DPGEN_ACC_CASE(energy_c89),
       [](const std::vector<double>& a) {
         double s = 0.0;
         for (size_t i = 1; i < a.size(); ++i) {
           s += a[i] * a[i];
           s -= 0.25 * a[i - 1];
         }
         return std::vector<double>{s};
       },
       1},
      {DPGEN_ACC_CASE(energy_template),
       [](const std::vector<double>& a) {
         double s = 2.0;
         for (double x : a)
           s += x * x * x;
         return std::vector<double>{s};
       },
       1},
      {DPGEN_ACC_CASE(ref_param_lambda),
       [](const std::vector<double>& a) {
         double s = 0.0;
         for (double x : a)
           s += std::exp(x);
         return std::vector<double>{s};
       },
       1},
      {DPGEN_ACC_CASE(range_helpers),
       [](const std::vector<double>& a) {
         double hi = -1e300, lo = 1e300;
         for (double x : a) {
           hi = std::max(hi, x);
           if (x * x < lo)
             lo = x * x;
         }
         return std::vector<double>{hi, lo};
       },
       2},
      {"row_norms_ref", [](auto a, auto o, int n) { row_norms_ref(a, o, 4, n / 4); },
       [](auto a, auto aa, auto s, int n) { row_norms_ref_adjoint(a, aa, s, 4, n / 4); },
       [](auto a, auto d, auto o, auto od, int n) { row_norms_ref_tangent(a, d, o, od, 4, n / 4); },
       [](const std::vector<double>& a) {
         std::vector<double> o(a.size() / 4);
         for (size_t j = 0; j < o.size(); ++j) {
           double r = 1.0;
           for (size_t i = 0; i < 4; ++i)
             r += a[j * 4 + i] * a[j * 4 + i];
           o[j] = std::sqrt(r);
         }
         return o;
       },
       0},
  };
  for (const Case& c : cases)
    for (int n : {4, 8, 20})
      check(c, n);
}
