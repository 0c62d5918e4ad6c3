// For the style tests that compare a kernel's parallel forward (printed from
// dpgen's IR) with the kernel itself.
#pragma once

#include <doctest/doctest.h>

#include <cmath>
#include <cstddef>
#include <cstring>
#include <vector>

namespace dpgen_test {

/// `n` inputs of both signs, sin(phase + 1.7 i); with `spread`, scaled by up to 1 + 6 spread
/// (magnitudes apart, so that sums regrouped round otherwise).
inline std::vector<double> wavy(size_t n, double phase, double spread = 0.0) {
  std::vector<double> v(n);
  for (size_t i = 0; i < n; ++i)
    v[i] = std::sin(phase + 1.7 * double(i)) * (1.0 + spread * double(i % 7));
  return v;
}

/// Bit for bit (NaN payloads included).
inline bool same_values(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), sizeof(double) * a.size()) == 0);
}

/// `kernel(in, out)` and `parallel(in, out)` on the same input of `n` values (both signs),
/// their `m` outputs prefilled with NaN (an element one writes and the other does not
/// shows), bit for bit.
template <typename K, typename P> void same_bits(size_t n, size_t m, K kernel, P parallel) {
  const std::vector<double> in = wavy(n, 1.0);
  std::vector<double> a(m, std::nan("")), b(m, std::nan(""));
  kernel(in.data(), a.data());
  parallel(in.data(), b.data());
  CHECK(same_values(a, b));
}

} // namespace dpgen_test
