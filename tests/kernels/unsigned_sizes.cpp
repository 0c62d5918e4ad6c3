// Unsigned sizes as C and STL code has them. The adjoint's index algebra goes
// below zero (a reversed read a[n - 1 - i] gathers over cells -n + 1 ... 0),
// which unsigned arithmetic would wrap: dpgen reads unsigned parameters and
// vector sizes through signed copies (before, these adjoints were silently
// zero: the wrapped loop bound skipped the loop).
#include "dpgen/annotate.hpp"

#include <cstddef>
#include <vector>

DPGEN_KERNEL void reverse_unsigned(DPGEN_IN const double* a, DPGEN_OUT double* out, unsigned n) {
  for (unsigned i = 0; i < n; ++i)
    out[i] = a[i] * a[n - 1 - i];
}

// The unsigned count-down idiom, and an unsigned local index.
DPGEN_KERNEL void countdown_size_t(DPGEN_IN const double* a, DPGEN_OUT double* out,
                                   std::size_t n) {
  for (std::size_t i = n; i-- > 0;) {
    std::size_t k = n - 1 - i;
    out[k] = 2.0 * a[i] - a[k] * a[k];
  }
}

DPGEN_KERNEL void reverse_vector(DPGEN_IN const std::vector<double>& a, DPGEN_OUT std::vector<double>& out) {
  for (std::size_t i = 0; i < a.size(); ++i)
    out[i] = a[a.size() - 1 - i] * a[i] + a[i];
}
