// For the style tests that compare a kernel's parallel forward (printed from
// dpgen's IR) with the kernel itself.
#pragma once

#include <doctest/doctest.h>

#include <cmath>
#include <cstddef>
#include <cstring>
#include <vector>

namespace dpgen_test {

/// `kernel(in, out)` and `parallel(in, out)` on the same input of `n` values (both signs),
/// their `m` outputs prefilled with NaN (an element one writes and the other does not
/// shows), bit for bit.
template <typename K, typename P> void same_bits(size_t n, size_t m, K kernel, P parallel) {
  std::vector<double> in(n), a(m, std::nan("")), b(m, std::nan(""));
  for (size_t i = 0; i < n; ++i)
    in[i] = std::sin(1.0 + 1.7 * double(i));
  kernel(in.data(), a.data());
  parallel(in.data(), b.data());
  CHECK((m == 0 || std::memcmp(a.data(), b.data(), sizeof(double) * m) == 0));
}

} // namespace dpgen_test
