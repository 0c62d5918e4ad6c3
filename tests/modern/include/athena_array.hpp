// athena_array.hpp: a stand-in for Athena++'s AthenaArray<T> (src/athena_arrays.hpp)
// and the few names of src/athena.hpp a kernel uses. Up to 5D, the last
// index contiguous: a(n, k, j, i) = pdata_[i + nx1_*(j + nx2_*(k + nx3_*n))].
// As in Athena++, the const operator() returns the value and the non-const one
// a reference. Athena++ arrays own their memory (NewAthenaArray); this
// stand-in also wraps user memory (a shallow array), as its slices do.
#pragma once

#include <cstddef>

using Real = double;

// hydro variables (src/athena.hpp)
enum { IDN = 0, IM1 = 1, IM2 = 2, IM3 = 3, IEN = 4 };
enum { IVX = 1, IVY = 2, IVZ = 3, IPR = 4 };

template <typename T> class AthenaArray {
public:
  AthenaArray() : pdata_(nullptr), nx1_(0), nx2_(0), nx3_(0), nx4_(0), nx5_(0) {}
  /// Shallow array over user memory, dimensions outermost first.
  AthenaArray(T* data, int nx4, int nx3, int nx2, int nx1)
      : pdata_(data), nx1_(nx1), nx2_(nx2), nx3_(nx3), nx4_(nx4), nx5_(1) {}
  AthenaArray(T* data, int nx3, int nx2, int nx1)
      : pdata_(data), nx1_(nx1), nx2_(nx2), nx3_(nx3), nx4_(1), nx5_(1) {}
  AthenaArray(T* data, int nx2, int nx1)
      : pdata_(data), nx1_(nx1), nx2_(nx2), nx3_(1), nx4_(1), nx5_(1) {}

  int GetDim1() const { return nx1_; }
  int GetDim2() const { return nx2_; }
  int GetDim3() const { return nx3_; }
  int GetDim4() const { return nx4_; }
  int GetSize() const { return nx1_ * nx2_ * nx3_ * nx4_ * nx5_; }
  T* data() { return pdata_; }
  const T* data() const { return pdata_; }

  // (i), (j,i), (k,j,i), (n,k,j,i), (m,n,k,j,i)
  T& operator()(const int n) { return pdata_[n]; }
  T operator()(const int n) const { return pdata_[n]; }
  T& operator()(const int n, const int i) { return pdata_[i + nx1_ * n]; }
  T operator()(const int n, const int i) const { return pdata_[i + nx1_ * n]; }
  T& operator()(const int n, const int j, const int i) { return pdata_[i + nx1_ * (j + nx2_ * n)]; }
  T operator()(const int n, const int j, const int i) const {
    return pdata_[i + nx1_ * (j + nx2_ * n)];
  }
  T& operator()(const int n, const int k, const int j, const int i) {
    return pdata_[i + nx1_ * (j + nx2_ * (k + nx3_ * n))];
  }
  T operator()(const int n, const int k, const int j, const int i) const {
    return pdata_[i + nx1_ * (j + nx2_ * (k + nx3_ * n))];
  }
  T& operator()(const int m, const int n, const int k, const int j, const int i) {
    return pdata_[i + nx1_ * (j + nx2_ * (k + nx3_ * (n + nx4_ * m)))];
  }
  T operator()(const int m, const int n, const int k, const int j, const int i) const {
    return pdata_[i + nx1_ * (j + nx2_ * (k + nx3_ * (n + nx4_ * m)))];
  }

private:
  T* pdata_;
  int nx1_, nx2_, nx3_, nx4_, nx5_;
};
