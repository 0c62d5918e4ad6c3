// strided_loops (tests/kernels/): loops stepping by 2 and 3.
#include "support/adjoint_check.hpp"

#include "strided_loops_adjoint.hpp"
#include "strided_loops_tangent.hpp"
#include "test_kernels.hpp"

TEST_CASE("restrict_full_weighting adjoint") {
  for (int nf : {0, 1, 2, 3, 4, 5, 9, 16, 17}) {
    CAPTURE(nf);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(nf)};
    p.out_sizes = {size_t(nf / 2 + 1)};
    p.linear = true;
    p.forward = [&](auto in, auto out) { restrict_full_weighting(in[0], out[0], nf); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      restrict_full_weighting_adjoint(in[0], adj[0], seed[0], nf);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      restrict_full_weighting_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], nf);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      restrict_full_weighting_tangent(in[0], dir[0], out[0], outd[0], nf);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("every_third adjoint") {
  for (auto [n, first] : {std::pair{0, 0}, {1, 0}, {7, 0}, {7, 1}, {10, 2}, {4, 5}}) {
    CAPTURE(n);
    CAPTURE(first);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { every_third(in[0], out[0], n, first); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      every_third_adjoint(in[0], adj[0], seed[0], n, first);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      every_third_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n, first);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      every_third_tangent(in[0], dir[0], out[0], outd[0], n, first);
    };
    dpgen_test::check_adjoint(p);
  }
}
