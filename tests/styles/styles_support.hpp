// Helpers for the style-corpus tests (tests/styles/): the checker hands out
// flat arrays; these view them the way the kernels' users would pass them.
#pragma once

#include <cstddef>
#include <vector>

namespace styles {

// Row pointers into a flat row-major nrows x ncols buffer, for `double**`
// kernels. Assumption (documented for the double** kernels): rows are
// disjoint, equally long, and the adjoint takes row pointers of the same shape
// (`double** a_adj`, seeds as `double**` or `const double* const*`).
template <typename T> std::vector<T*> rows(const T* base, std::size_t nrows, std::size_t ncols) {
  std::vector<T*> r(nrows);
  for (std::size_t j = 0; j < nrows; ++j)
    r[j] = const_cast<T*>(base) + j * ncols;
  return r;
}

template <typename T> std::vector<T> to_vec(const T* p, std::size_t n) {
  return std::vector<T>(p, p + n);
}
template <typename T> void from_vec(const std::vector<T>& v, T* p) {
  for (std::size_t i = 0; i < v.size(); ++i)
    p[i] = v[i];
}

} // namespace styles
