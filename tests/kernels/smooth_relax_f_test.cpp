// smooth_relax_f (tests/kernels/): a float kernel; float tolerances.
#include "support/adjoint_check.hpp"

#include "smooth_relax_f_adjoint.hpp"
#include "smooth_relax_f_tangent.hpp"
#include "test_kernels.hpp"

#include <type_traits>

static_assert(std::is_same_v<decltype(&smooth_relax_f_adjoint),
                             void (*)(const float*, float*, const float*, float*, const float*,
                                      int, float)>);

TEST_CASE("smooth_relax_f adjoint (float)") {
  for (int n : {1, 2, 9, 40}) {
    CAPTURE(n);
    dpgen_test::Problem<float> p;
    p.in_sizes = {size_t(n), size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { smooth_relax_f(in[0], in[1], out[0], n, 0.4f); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      smooth_relax_f_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n, 0.4f);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      smooth_relax_f_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], n, 0.4f);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      smooth_relax_f_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], n, 0.4f);
    };
    dpgen_test::check_adjoint(p);
  }
}
