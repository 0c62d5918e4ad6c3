// For the generated checked entry points (<kernel>_adjoint_checked): where the
// elements a kernel touches depend on the data (an index computed from values,
// a read under a condition on values), the range cannot be worked out ahead
// from the loop bounds. The entry point then runs the kernel's loops once,
// printed from its IR, with these stand-ins in place of such arrays: each
// subscript checks its index against the array's size (and its adjoint's)
// before anything is read, and nothing is written. An index out of range
// throws std::invalid_argument naming the entry point, the array, the index and
// the sizes, before the adjoint runs.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace dpgen {

/// Where a probe reports from: the entry point and its integer arguments
/// ("n = 8, m = 3"), shown in the message.
struct ProbeSite {
  const char* entry;
  const std::string& shown;
};

/// One array the kernel indexes and its size. An `optional` one is not checked
/// where `data` is null (an inactive input's adjoint, a buffer not given); any
/// other is, null or not (an empty std::vector's data() is null).
struct ProbeBound {
  const char* name;
  const void* data;
  std::size_t size;
  bool optional = false;
};

/// Throws unless index `i` is an element of every array of `bounds`.
template <typename I>
void probe_index(const ProbeSite& site, I i, std::initializer_list<ProbeBound> bounds) {
  static_assert(std::is_integral<I>::value, "an array index is an integer");
  for (const ProbeBound& b : bounds) {
    if (b.optional && b.data == nullptr)
      continue;
    const bool negative = std::is_signed<I>::value && i < I(0);
    if (negative || static_cast<unsigned long long>(i) >= b.size)
      throw std::invalid_argument(std::string(site.entry) + ": '" + b.name + "' has " +
                                  std::to_string(b.size) +
                                  " elements, but the kernel touches element " + std::to_string(i) +
                                  (site.shown.empty() ? "" : " (" + site.shown + ")"));
  }
}

/// A read-only array (an input, with its adjoint; or a constant array): a[i]
/// checks i, then reads the element.
template <typename T> class ProbeInput {
public:
  ProbeInput(const ProbeSite& site, const char* name, const T* data, std::size_t size,
             const char* adj_name = "", const void* adj = nullptr, std::size_t adj_size = 0)
      : site_(site),
        data_(data), primal_{name, data, size}, adjoint_{adj_name, adj, adj_size, true} {}
  template <typename I> T operator[](I i) const {
    probe_index(site_, i, {primal_, adjoint_});
    return data_[i];
  }

private:
  const ProbeSite& site_;
  const T* data_;
  ProbeBound primal_, adjoint_;
};

/// An output, as its seed (`<name>_adj`) stands for it: out[i] checks i
/// against the seed and gives a scratch element, so the kernel's stores
/// (=, +=, min/max scans) write nothing of the caller's. Where later loops read
/// what it holds (a work array, an accumulator's sums), `buffer` (of
/// `buffer_size` elements, allocated by the entry point) holds it instead.
template <typename T> class ProbeOutput {
public:
  ProbeOutput(const ProbeSite& site, const char* name, const T* seed, std::size_t size,
              T* buffer = nullptr, std::size_t buffer_size = 0)
      : site_(site), seed_{name, seed, size}, kept_{name, buffer, buffer_size, true},
        buffer_(buffer) {}
  template <typename I> T& operator[](I i) const {
    probe_index(site_, i, {seed_, kept_});
    return buffer_ ? buffer_[i] : scratch_;
  }

private:
  const ProbeSite& site_;
  ProbeBound seed_, kept_;
  T* buffer_;
  mutable T scratch_ = T();
};

} // namespace dpgen
