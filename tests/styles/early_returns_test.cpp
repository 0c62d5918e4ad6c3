// early_returns (tests/styles/): each kernel's adjoint and tangent against
// the checker's differences (and the dot-product test), then the parallel
// forward and the tangent's primal bit for bit against the kernel, every
// function on arrays of exactly n values (what the sanitizer build checks).
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "early_returns_adjoint.hpp"
#include "early_returns_kernels.hpp"
#include "early_returns_tangent.hpp"
#include "same_bits.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace {
using Vec = std::vector<double>;

// A kernel (a, b, n) of one input and one output of n values, and what dpgen
// generated for it.
struct Case {
  const char* name;
  void (*kernel)(const double*, double*, int);
  void (*parallel)(const double*, double*, int);
  void (*adjoint)(const double*, double*, const double*, int);
  void (*tangent)(const double*, const double*, double*, double*, int);
};
#define DPGEN_CASE(k)                                                                              \
  Case { #k, k, k##_parallel_forward, k##_adjoint, k##_tangent }

const Case cases[] = {DPGEN_CASE(flux_early),      DPGEN_CASE(slopes_early),
                      DPGEN_CASE(nested_early),    DPGEN_CASE(guarded_early),
                      DPGEN_CASE(store_early),     DPGEN_CASE(lambda_sets_after),
                      DPGEN_CASE(lambda_arm_sets), DPGEN_CASE(lambda_helper_sets)};
} // namespace

TEST_CASE("styles: early returns of helpers and lambdas") {
  for (const Case& c : cases)
    for (int n : {0, 1, 2, 3, 5, 9}) {
      const std::string name = c.name;
      CAPTURE(name);
      CAPTURE(n);
      const size_t N = size_t(n);
      dpgen_test::check_one_to_one(
          N, N, [&](auto a, auto b) { c.kernel(a, b, n); },
          [&](auto a, auto adj, auto seed) { c.adjoint(a, adj, seed, n); },
          [&](auto a, auto d, auto b, auto bd) { c.tangent(a, d, b, bd, n); });
      // the forward forms, outputs prefilled with NaN: every element written, the same bits
      const Vec a = dpgen_test::wavy(N, 0.3), dir = dpgen_test::wavy(N, 1.1);
      Vec b(N, std::nan("")), bp = b, bt = b, bd = b;
      c.kernel(a.data(), b.data(), n);
      c.parallel(a.data(), bp.data(), n);
      c.tangent(a.data(), dir.data(), bt.data(), bd.data(), n);
      CHECK(dpgen_test::same_values(b, bp));
      CHECK(dpgen_test::same_values(b, bt));
    }
}
