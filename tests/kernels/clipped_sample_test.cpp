// clipped_sample (tests/kernels/): reads guarded by conditional arms and a
// store guarded by a bool local; the guard cells catch any write outside.
#include "support/adjoint_check.hpp"

#include "clipped_sample_adjoint.hpp"
#include "clipped_sample_tangent.hpp"
#include "test_kernels.hpp"

TEST_CASE("clipped_sample adjoint") {
  for (int n : {1, 2, 4, 23}) {
    CAPTURE(n);
    std::vector<double> mask(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i)
      mask[size_t(i)] = i % 3 == 0 ? 0.0 : 1.0;
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n), size_t(n)};
    p.out_sizes = {size_t(n), size_t(n)};
    p.forward = [&](auto in, auto out) {
      clipped_sample(in[0], in[1], mask.data(), out[0], out[1], n);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      clipped_sample_adjoint(in[0], adj[0], in[1], adj[1], mask.data(), seed[0], seed[1], n);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      clipped_sample_tangent(in[0], dir[0], in[1], dir[1], mask.data(), out[0], outd[0], out[1], outd[1], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
