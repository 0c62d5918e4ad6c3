#include "support/adjoint_check.hpp"
#include "styles/styles_support.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#include "r5_mm_float_if_double_expr_adjoint.hpp"
#include "r5_mm_float_if_double_expr_tangent.hpp"

DPGEN_KERNEL void r5_mm_float_if_double_expr(DPGEN_IN const float* a, DPGEN_OUT float* out, int n);
TEST_CASE("adversary: r5_mm_float_if_double_expr") {
  for (int n : {0, 1, 2, 3, 5, 7}) {
    CAPTURE(n);
    dpgen_test::Problem<float> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(1)};
    p.in_ranges = {{-8.0, 8.0}};
    p.forward = [&](auto in, auto out) { r5_mm_float_if_double_expr(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { r5_mm_float_if_double_expr_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { r5_mm_float_if_double_expr_tangent(in[0], dir[0], out[0], outd[0], n); };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("adversary: r5_mm_float_if_double_expr ties") {
  const auto n = 2;
  std::vector<float> a = {3.0f, 7.0f};
  std::vector<float> a_adj(2, 0), a_dir(2, 0);
  std::vector<float> out(size_t(1), 0), out_seed(size_t(1), 0), out_t(size_t(1), 0), out_dot(size_t(1), 0);
  out_seed[0] = 1;
  r5_mm_float_if_double_expr(a.data(), out.data(), n);
  CHECK(double(out[0]) == doctest::Approx(3.0).epsilon(1e-5));
  r5_mm_float_if_double_expr_adjoint(a.data(), a_adj.data(), out_seed.data(), n);
  CHECK_MESSAGE(double(a_adj[0]) == doctest::Approx(1.0).epsilon(1e-5), "adjoint a[0]");
  CHECK_MESSAGE(double(a_adj[1]) == doctest::Approx(0.0).epsilon(1e-5), "adjoint a[1]");
  { std::fill(out_dot.begin(), out_dot.end(), float(0)); a_dir[0] = 1; r5_mm_float_if_double_expr_tangent(a.data(), a_dir.data(), out_t.data(), out_dot.data(), n); a_dir[0] = 0;
    CHECK_MESSAGE(double(out_dot[0]) == doctest::Approx(1.0).epsilon(1e-5), "tangent along a[0]"); }
  { std::fill(out_dot.begin(), out_dot.end(), float(0)); a_dir[1] = 1; r5_mm_float_if_double_expr_tangent(a.data(), a_dir.data(), out_t.data(), out_dot.data(), n); a_dir[1] = 0;
    CHECK_MESSAGE(double(out_dot[0]) == doctest::Approx(0.0).epsilon(1e-5), "tangent along a[1]"); }
}
