#include "support/adjoint_check.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include "a22_rows_fixed_adjoint.hpp"
#include "a22_rows_fixed_tangent.hpp"

DPGEN_KERNEL void a22_rows_fixed(DPGEN_IN const double (*a)[8], DPGEN_OUT double o[][8], int n);
TEST_CASE("adversary: a22_rows_fixed") {
  for (int n : {0, 1, 2, 3, 5, 8}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(8*n)};
    p.out_sizes = {size_t(8*n)};
    p.forward = [&](auto in, auto out) { a22_rows_fixed((const double(*)[8])in[0], (double(*)[8])out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { a22_rows_fixed_adjoint((const double(*)[8])in[0], (double(*)[8])adj[0], (const double(*)[8])seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { a22_rows_fixed_tangent((const double(*)[8])in[0], (const double(*)[8])dir[0], (double(*)[8])out[0], (double(*)[8])outd[0], n); };
    dpgen_test::check_adjoint(p);
  }
  {
    std::vector<double> a(8 * 12, 1.0), aa(8 * 12, 0.0), s(8 * 12, 1.0);
    CHECK_THROWS_AS(a22_rows_fixed_adjoint((const double(*)[8])a.data(), (double(*)[8])aa.data(), (const double(*)[8])s.data(), 11), std::invalid_argument);
  }
}
