// cond_operand_calls (tests/styles/): each kernel's adjoint and tangent
// against the checker's differences (and the dot-product test), then the
// parallel forward and the tangent's primal bit for bit against the kernel,
// every function on arrays of exactly n values (what the sanitizer build
// checks: the generator of session 23 read a[-1] in all of them).
#include "support/adjoint_check.hpp"

#include "cond_operand_calls_adjoint.hpp"
#include "cond_operand_calls_kernels.hpp"
#include "cond_operand_calls_tangent.hpp"
#include "dpgen/annotate.hpp"
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

// (a kernel with a line buffer has no parallel forward)
#define DPGEN_CASE_NO_PARALLEL(k)                                                                  \
  Case { #k, k, nullptr, k##_adjoint, k##_tangent }

const Case cases[] = {DPGEN_CASE(sq_left),       DPGEN_CASE(lambda_right),
                      DPGEN_CASE(index_lambda),  DPGEN_CASE(and_guard),
                      DPGEN_CASE(or_guard),      DPGEN_CASE(last_value),
                      DPGEN_CASE(nested_select), DPGEN_CASE_NO_PARALLEL(buffer_arm),
                      DPGEN_CASE(c89_limited)};
} // namespace

TEST_CASE("styles: calls in conditional operands") {
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
      if (c.parallel)
        c.parallel(a.data(), bp.data(), n);
      else
        bp = b;
      c.tangent(a.data(), dir.data(), bt.data(), bd.data(), n);
      CHECK(dpgen_test::same_values(b, bp));
      CHECK(dpgen_test::same_values(b, bt));
    }
}
