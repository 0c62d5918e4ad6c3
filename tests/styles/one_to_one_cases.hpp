// Kernels `k(a, b, n)` of one input and one output of n values, and what
// dpgen generated for each, checked alike (cond_operand_calls_test.cpp,
// early_returns_test.cpp): the adjoint and the tangent against the checker's
// differences and the dot-product test, then the parallel forward and the
// tangent's primal bit for bit against the kernel, every function on arrays
// of exactly n values (what the sanitizer build checks).
#pragma once

#include "support/adjoint_check.hpp"

#include "same_bits.hpp"

#include <cmath>
#include <initializer_list>
#include <string>
#include <vector>

namespace dpgen_test {

struct OneToOneCase {
  const char* name;
  void (*kernel)(const double*, double*, int);
  void (*parallel)(const double*, double*, int); // (none for a kernel with a line buffer)
  void (*adjoint)(const double*, double*, const double*, int);
  void (*tangent)(const double*, const double*, double*, double*, int);
};

#define DPGEN_CASE(k)                                                                              \
  dpgen_test::OneToOneCase { #k, k, k##_parallel_forward, k##_adjoint, k##_tangent }
#define DPGEN_CASE_NO_PARALLEL(k)                                                                  \
  dpgen_test::OneToOneCase { #k, k, nullptr, k##_adjoint, k##_tangent }

inline void check_cases(std::initializer_list<OneToOneCase> cases) {
  for (const OneToOneCase& c : cases)
    for (int n : {0, 1, 2, 3, 5, 9}) {
      const std::string name = c.name;
      CAPTURE(name);
      CAPTURE(n);
      const size_t N = size_t(n);
      check_one_to_one(
          N, N, [&](auto a, auto b) { c.kernel(a, b, n); },
          [&](auto a, auto adj, auto seed) { c.adjoint(a, adj, seed, n); },
          [&](auto a, auto d, auto b, auto bd) { c.tangent(a, d, b, bd, n); });
      // the forward forms, outputs prefilled with NaN: every element written, the same bits
      const std::vector<double> a = wavy(N, 0.3), dir = wavy(N, 1.1);
      std::vector<double> b(N, std::nan("")), bp = b, bt = b, bd = b;
      c.kernel(a.data(), b.data(), n);
      if (c.parallel)
        c.parallel(a.data(), bp.data(), n);
      else
        bp = b;
      c.tangent(a.data(), dir.data(), bt.data(), bd.data(), n);
      CHECK(same_values(b, bp));
      CHECK(same_values(b, bt));
    }
}

} // namespace dpgen_test
