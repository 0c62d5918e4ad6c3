// Array views as users write them for their own codes (tests/styles/view_*):
// a pointer and strides with an inline operator(), in three layouts.
#pragma once

namespace grid {

/// A 2D view, row-major: u(j, i) is p[j * nx + i]. Shallow: a const view
/// still writes its elements (as Kokkos::View, amrex::Array4).
template <typename T> struct View2D {
  T* p;
  int nx, ny;
  T& operator()(int j, int i) const { return p[j * nx + i]; }
  int cols() const { return nx; }
  int rows() const { return ny; }
};

/// A 3D view in Fortran (column-major) order with a first index that may
/// start below 0 (ghost cells), Horner-style offset as Athena++ and many
/// Fortran ports write it.
struct FortranView3D {
  double* p;
  int ilo, ni, nj, nk;
  double& operator()(int i, int j, int k) const { return p[(i - ilo) + ni * (j + nj * k)]; }
};

/// Populations of a lattice (q, y, x), row-major, the population first (as
/// lattice Boltzmann codes lay out f(q, y, x)).
template <typename T> struct Pops3D {
  T* p;
  int nq, ny, nx;
  T& operator()(int q, int y, int x) const { return p[(q * ny + y) * nx + x]; }
};

/// A deep-const field, as Athena++'s AthenaArray: the const operator() reads
/// a value, the non-const one returns the element.
class Field {
public:
  Field(double* data, int n) : data_(data), n_(n) {}
  double& operator()(int i) { return data_[i]; }
  double operator()(int i) const { return data_[i]; }
  int size() const { return n_; }

private:
  double* data_;
  int n_;
};

/// Grid constants passed as one object.
struct Spacing {
  double dx, dy;
  double inv_dx2() const { return 1.0 / (dx * dx); }
};

} // namespace grid
