// size_checks (tests/kernels/): sizes for which the write-once rule holds give
// a correct adjoint; sizes that break it stop the adjoint with
// std::invalid_argument naming the rule, the kernel line and the sizes.
#include "support/adjoint_check.hpp"

#include "size_checks_adjoint.hpp"
#include "size_checks_tangent.hpp"
#include "test_kernels.hpp"

#include <stdexcept>
#include <string>

TEST_CASE("leading_dim adjoint: valid leading dimensions") {
  for (auto [x_min, x_max, ny, ld] : {std::array{0, 3, 2, 4}, {1, 4, 3, 6}, {2, 2, 1, 3}}) {
    CAPTURE(ld);
    size_t n = size_t(ny * ld);
    dpgen_test::Problem<double> p;
    p.in_sizes = {n};
    p.out_sizes = {n};
    p.forward = [&](auto in, auto out) { leading_dim(in[0], out[0], &x_min, &x_max, ny, ld); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      leading_dim_adjoint(in[0], adj[0], seed[0], &x_min, &x_max, ny, ld);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      leading_dim_tangent(in[0], dir[0], out[0], outd[0], &x_min, &x_max, ny, ld);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("leading_dim adjoint: a leading dimension shorter than the row throws") {
  int x_min = 0, x_max = 5, ny = 3, ld = 4; // rows of 6 elements, 4 apart: they overlap
  std::vector<double> a(64, 1.0), a_adj(64, 0.0), seed(64, 1.0);
  try {
    leading_dim_adjoint(a.data(), a_adj.data(), seed.data(), &x_min, &x_max, ny, ld);
    FAIL("no exception");
  } catch (const std::invalid_argument& e) {
    std::string m = e.what();
    CHECK(m.find("size_checks.cpp:12: leading_dim_adjoint") != std::string::npos);
    CHECK(m.find("output 'b' is written once per element") != std::string::npos);
    CHECK(m.find("ld = 4") != std::string::npos);
  }
  for (double v : a_adj)
    CHECK(v == 0.0); // nothing was accumulated before the check
  ny = 0; // no row runs: nothing to check
  CHECK_NOTHROW(leading_dim_adjoint(a.data(), a_adj.data(), seed.data(), &x_min, &x_max, ny, ld));
}

TEST_CASE("fixed_rows adjoint: n <= 8 is checked") {
  for (int n : {0, 1, 5, 8}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {64};
    p.out_sizes = {64};
    using Rows = double (*)[8];
    using CRows = const double (*)[8];
    p.forward = [&](auto in, auto out) {
      fixed_rows(reinterpret_cast<CRows>(in[0]), reinterpret_cast<Rows>(out[0]), n);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      fixed_rows_adjoint(reinterpret_cast<CRows>(in[0]), reinterpret_cast<Rows>(adj[0]),
                         reinterpret_cast<CRows>(seed[0]), n);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      fixed_rows_tangent(reinterpret_cast<CRows>(in[0]), reinterpret_cast<CRows>(dir[0]), reinterpret_cast<Rows>(out[0]), reinterpret_cast<Rows>(outd[0]), n);
    };
    dpgen_test::check_adjoint(p);
  }
  double a[9][8] = {}, a_adj[9][8] = {}, seed[9][8] = {};
  CHECK_THROWS_AS(fixed_rows_adjoint(a, a_adj, seed, 9), std::invalid_argument);
}
