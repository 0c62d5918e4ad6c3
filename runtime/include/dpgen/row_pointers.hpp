// For the generated entry points of kernels that take rows as
// `std::vector<std::vector<T>>&` (a[j][i]): the flat twin they call takes
// row pointers, one per row (each row's data()), and an adjoint or tangent
// must have the rows of the array it belongs to, row by row.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace dpgen {

/// Each row's data(), in order: the `T* const*` of row-pointer code. The
/// vector returned lives until the end of the full expression around it (the
/// call it is an argument of).
template <class T> std::vector<const T*> row_pointers(const std::vector<std::vector<T>>& a) {
  std::vector<const T*> rows(a.size());
  for (std::size_t j = 0; j < a.size(); ++j)
    rows[j] = a[j].data();
  return rows;
}
template <class T> std::vector<T*> row_pointers(std::vector<std::vector<T>>& a) {
  std::vector<T*> rows(a.size());
  for (std::size_t j = 0; j < a.size(); ++j)
    rows[j] = a[j].data();
  return rows;
}

/// Throws std::invalid_argument (naming `fn`, both arrays and the first row
/// that differs) unless `a` has as many rows as `b`, each as long as b's.
template <class T, class U>
void check_same_rows(const char* fn, const char* a_name, const std::vector<std::vector<T>>& a,
                     const char* b_name, const std::vector<std::vector<U>>& b) {
  if (a.size() != b.size())
    throw std::invalid_argument(std::string(fn) + ": " + a_name + " has " +
                                std::to_string(a.size()) + " rows but " + b_name + " has " +
                                std::to_string(b.size()));
  for (std::size_t j = 0; j < a.size(); ++j)
    if (a[j].size() != b[j].size())
      throw std::invalid_argument(std::string(fn) + ": row " + std::to_string(j) + " of " + a_name +
                                  " has " + std::to_string(a[j].size()) + " elements but that of " +
                                  b_name + " has " + std::to_string(b[j].size()));
}

} // namespace dpgen
