// special_math (tests/kernels/): the table's added functions, double and float.
#include "support/adjoint_check.hpp"

#include "special_math_adjoint.hpp"
#include "special_math_tangent.hpp"
#include "test_kernels.hpp"

TEST_CASE("special_math adjoint: atan2 hypot erf cbrt copysign fma log1p expm1") {
  for (int n : {1, 16}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n), size_t(n), size_t(n)};
    p.in_ranges = {{0.5, 2.0}, {-1.0, 1.0}, {0.5, 2.0}};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { special_math(in[0], in[1], in[2], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      special_math_adjoint(in[0], adj[0], in[1], adj[1], in[2], adj[2], seed[0], n);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      special_math_tangent(in[0], dir[0], in[1], dir[1], in[2], dir[2], out[0], outd[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("special_math_f adjoint (float, C names: atan2f ... expm1f)") {
  for (int n : {1, 16}) {
    CAPTURE(n);
    dpgen_test::Problem<float> p;
    p.in_sizes = {size_t(n), size_t(n), size_t(n)};
    p.in_ranges = {{0.5, 2.0}, {-1.0, 1.0}, {0.5, 2.0}};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { special_math_f(in[0], in[1], in[2], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      special_math_f_adjoint(in[0], adj[0], in[1], adj[1], in[2], adj[2], seed[0], n);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      special_math_f_tangent(in[0], dir[0], in[1], dir[1], in[2], dir[2], out[0], outd[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
