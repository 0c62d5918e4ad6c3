// Shared by the harnesses of the modern-C++ corpus (tests/modern/): the
// checker of tests/support/adjoint_check.hpp (dot-product test against the
// forward kernel, FD gradient, += contract, guard cells, tangent: J v against
// central differences and <w, J v> = <v, J^T w>), and views of its guarded
// flat arrays in the stand-in types. A harness includes its kernel file (the
// forward kernels and the types they use) and then the generated headers.
#pragma once

#include <doctest/doctest.h>

#include "support/adjoint_check.hpp"

#include "amrex_lite.hpp"
#include "athena_array.hpp"
#include "kokkos_lite.hpp"
#include "mdspan_lite.hpp"

#include <cstddef>

#ifndef CORPUS_TANGENT
#define CORPUS_TANGENT 1
#endif

namespace corpus {

using dpgen_test::check_adjoint;
using dpgen_test::Problem;

/// The checker hands seeds as const pointers; views of them are views of
/// non-const elements, which convert to whatever the adjoint takes
/// (Array4<Real> -> Array4<Real const>, View<double**> -> View<const double**>).
template <class T> T* mut(const T* p) { return const_cast<T*>(p); }

/// An Array4 over `box` (bounds inclusive) with ncomp components.
inline amrex::Array4<double> a4(const double* p, amrex::Box const& box, int ncomp = 1) {
  const auto lo = amrex::lbound(box), hi = amrex::ubound(box);
  return amrex::Array4<double>(mut(p), lo, amrex::Dim3{hi.x + 1, hi.y + 1, hi.z + 1}, ncomp);
}
inline std::size_t npts(amrex::Box const& box, int ncomp = 1) {
  return std::size_t(box.numPts()) * std::size_t(ncomp);
}
inline amrex::Box box3(int ilo, int jlo, int klo, int ihi, int jhi, int khi) {
  return amrex::Box(amrex::IntVect(ilo, jlo, klo), amrex::IntVect(ihi, jhi, khi));
}

template <class T = double> using MD2 = stdex::mdspan<T, stdex::dextents<int, 2>>;
template <class T = double> using MD3 = stdex::mdspan<T, stdex::dextents<int, 3>>;

} // namespace corpus
