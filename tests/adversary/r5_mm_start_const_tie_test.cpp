#include "support/adjoint_check.hpp"
#include "styles/styles_support.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#include "r5_mm_start_const_tie_adjoint.hpp"
#include "r5_mm_start_const_tie_tangent.hpp"

DPGEN_KERNEL void r5_mm_start_const_tie(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n);
TEST_CASE("adversary: r5_mm_start_const_tie") {
  for (int n : {0, 1, 2, 3, 4, 7, 16}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n), size_t(n)};
    p.out_sizes = {size_t(1)};
    p.forward = [&](auto in, auto out) { r5_mm_start_const_tie(in[0], in[1], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { r5_mm_start_const_tie_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { r5_mm_start_const_tie_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], n); };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("adversary: r5_mm_start_const_tie ties") {
  const auto n = 2;
  std::vector<double> a = {1.0, -1.0};
  std::vector<double> a_adj(2, 0), a_dir(2, 0);
  std::vector<double> b = {1.0, 0.5};
  std::vector<double> b_adj(2, 0), b_dir(2, 0);
  std::vector<double> out(size_t(1), 0), out_seed(size_t(1), 0), out_t(size_t(1), 0), out_dot(size_t(1), 0);
  out_seed[0] = 1;
  r5_mm_start_const_tie(a.data(), b.data(), out.data(), n);
  CHECK(double(out[0]) == doctest::Approx(1.0).epsilon(1e-12));
  r5_mm_start_const_tie_adjoint(a.data(), a_adj.data(), b.data(), b_adj.data(), out_seed.data(), n);
  CHECK_MESSAGE(double(a_adj[0]) == doctest::Approx(1.0).epsilon(1e-12), "adjoint a[0]");
  CHECK_MESSAGE(double(a_adj[1]) == doctest::Approx(0.0).epsilon(1e-12), "adjoint a[1]");
  CHECK_MESSAGE(double(b_adj[0]) == doctest::Approx(-1.0).epsilon(1e-12), "adjoint b[0]");
  CHECK_MESSAGE(double(b_adj[1]) == doctest::Approx(0.0).epsilon(1e-12), "adjoint b[1]");
  { std::fill(out_dot.begin(), out_dot.end(), double(0)); a_dir[0] = 1; r5_mm_start_const_tie_tangent(a.data(), a_dir.data(), b.data(), b_dir.data(), out_t.data(), out_dot.data(), n); a_dir[0] = 0;
    CHECK_MESSAGE(double(out_dot[0]) == doctest::Approx(1.0).epsilon(1e-12), "tangent along a[0]"); }
  { std::fill(out_dot.begin(), out_dot.end(), double(0)); a_dir[1] = 1; r5_mm_start_const_tie_tangent(a.data(), a_dir.data(), b.data(), b_dir.data(), out_t.data(), out_dot.data(), n); a_dir[1] = 0;
    CHECK_MESSAGE(double(out_dot[0]) == doctest::Approx(0.0).epsilon(1e-12), "tangent along a[1]"); }
  { std::fill(out_dot.begin(), out_dot.end(), double(0)); b_dir[0] = 1; r5_mm_start_const_tie_tangent(a.data(), a_dir.data(), b.data(), b_dir.data(), out_t.data(), out_dot.data(), n); b_dir[0] = 0;
    CHECK_MESSAGE(double(out_dot[0]) == doctest::Approx(-1.0).epsilon(1e-12), "tangent along b[0]"); }
  { std::fill(out_dot.begin(), out_dot.end(), double(0)); b_dir[1] = 1; r5_mm_start_const_tie_tangent(a.data(), a_dir.data(), b.data(), b_dir.data(), out_t.data(), out_dot.data(), n); b_dir[1] = 0;
    CHECK_MESSAGE(double(out_dot[0]) == doctest::Approx(0.0).epsilon(1e-12), "tangent along b[1]"); }
}
