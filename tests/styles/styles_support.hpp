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

// Rows allocated one by one (each its own heap block with guard cells on both
// sides, allocated last row first), as codes that build `double**` grids with
// a loop of `new double[nx]` have them; copied from and back to a flat
// row-major buffer around each call.
template <typename T> class ScatteredRows {
public:
  static constexpr std::size_t pad = 4;
  ScatteredRows(std::size_t nrows, std::size_t ncols) : ncols_(ncols), store_(nrows) {
    for (std::size_t j = nrows; j-- > 0;)
      store_[j].assign(ncols + 2 * pad, guard());
    for (auto& r : store_)
      ptrs_.push_back(r.data() + pad);
  }
  static T guard() { return T(-12345.5); }
  T** data() { return ptrs_.data(); }
  void load(const T* flat) {
    for (std::size_t j = 0; j < store_.size(); ++j)
      for (std::size_t i = 0; i < ncols_; ++i)
        ptrs_[j][i] = flat[j * ncols_ + i];
  }
  void save(T* flat) const {
    for (std::size_t j = 0; j < store_.size(); ++j)
      for (std::size_t i = 0; i < ncols_; ++i)
        flat[j * ncols_ + i] = ptrs_[j][i];
  }
  bool guards_intact() const {
    for (const auto& r : store_)
      for (std::size_t i = 0; i < pad; ++i)
        if (r[i] != guard() || r[pad + ncols_ + i] != guard())
          return false;
    return true;
  }

private:
  std::size_t ncols_;
  std::vector<std::vector<T>> store_;
  std::vector<T*> ptrs_;
};

template <typename T> std::vector<T> to_vec(const T* p, std::size_t n) {
  return std::vector<T>(p, p + n);
}
template <typename T> void from_vec(const std::vector<T>& v, T* p) {
  for (std::size_t i = 0; i < v.size(); ++i)
    p[i] = v[i];
}

} // namespace styles
