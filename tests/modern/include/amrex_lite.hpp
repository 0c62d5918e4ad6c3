// amrex_lite.hpp: a small, faithful stand-in for the parts of AMReX that a
// stencil kernel touches (AMReX is not a Debian package). Same names, same
// semantics as AMReX_Array4.H, AMReX_Box.H, AMReX_Dim3.H and the CPU
// AMReX_GpuLaunchFunctsC.H: an Array4 is a pointer, strides and index bounds
// with an inline affine operator(); ParallelFor is a loop nest calling the
// lambda (k outermost, i innermost; the component n outermost of all).
#pragma once

#include <cstddef>
#include <type_traits>

#define AMREX_SPACEDIM 3
#define AMREX_GPU_DEVICE
#define AMREX_GPU_HOST_DEVICE
#define AMREX_FORCE_INLINE inline
#define AMREX_RESTRICT __restrict__
#define AMREX_PRAGMA_SIMD

namespace amrex {

using Real = double;
using Long = long long;

struct Dim3 {
  int x, y, z;
};

class IntVect {
public:
  constexpr IntVect() noexcept : vect{0, 0, 0} {}
  constexpr IntVect(int i, int j, int k) noexcept : vect{i, j, k} {}
  constexpr int operator[](int dir) const noexcept { return vect[dir]; }
  int& operator[](int dir) noexcept { return vect[dir]; }
  constexpr Dim3 dim3() const noexcept { return {vect[0], vect[1], vect[2]}; }

private:
  int vect[AMREX_SPACEDIM];
};

/// Cell-centered (type 0) or nodal (type 1) per direction; bounds inclusive.
class Box {
public:
  constexpr Box() noexcept : smallend(), bigend(-1, -1, -1), btype() {}
  constexpr Box(IntVect const& small, IntVect const& big) noexcept
      : smallend(small), bigend(big), btype() {}
  constexpr Box(IntVect const& small, IntVect const& big, IntVect const& typ) noexcept
      : smallend(small), bigend(big), btype(typ) {}
  constexpr const IntVect& smallEnd() const noexcept { return smallend; }
  constexpr const IntVect& bigEnd() const noexcept { return bigend; }
  constexpr int smallEnd(int dir) const noexcept { return smallend[dir]; }
  constexpr int bigEnd(int dir) const noexcept { return bigend[dir]; }
  constexpr IntVect type() const noexcept { return btype; }
  constexpr int length(int dir) const noexcept { return bigend[dir] - smallend[dir] + 1; }
  constexpr Long numPts() const noexcept {
    return Long(length(0)) * Long(length(1)) * Long(length(2));
  }
  Box& grow(int n) noexcept {
    for (int d = 0; d < AMREX_SPACEDIM; ++d) {
      smallend[d] -= n;
      bigend[d] += n;
    }
    return *this;
  }
  Box& grow(int dir, int n) noexcept {
    smallend[dir] -= n;
    bigend[dir] += n;
    return *this;
  }
  /// Cell-centered to nodal in direction dir: one more point.
  Box& surroundingNodes(int dir) noexcept {
    if (btype[dir] == 0) {
      bigend[dir] += 1;
      btype[dir] = 1;
    }
    return *this;
  }

private:
  IntVect smallend, bigend, btype;
};

inline Box grow(Box b, int n) noexcept { return b.grow(n); }
inline Box grow(Box b, int dir, int n) noexcept { return b.grow(dir, n); }
inline Box surroundingNodes(Box b, int dir) noexcept { return b.surroundingNodes(dir); }

AMREX_FORCE_INLINE Dim3 lbound(Box const& box) noexcept {
  return {box.smallEnd(0), box.smallEnd(1), box.smallEnd(2)};
}
AMREX_FORCE_INLINE Dim3 ubound(Box const& box) noexcept {
  return {box.bigEnd(0), box.bigEnd(1), box.bigEnd(2)};
}
AMREX_FORCE_INLINE Dim3 length(Box const& box) noexcept {
  return {box.length(0), box.length(1), box.length(2)};
}

/// A view of a 3D array with ncomp components, Fortran order (i fastest),
/// over the index range [begin, end) (end exclusive, as in AMReX).
template <class T> struct Array4 {
  T* AMREX_RESTRICT p;
  Long jstride;
  Long kstride;
  Long nstride;
  Dim3 begin;
  Dim3 end;
  int ncomp;

  constexpr Array4() noexcept
      : p(nullptr), jstride(0), kstride(0), nstride(0), begin{1, 1, 1}, end{0, 0, 0}, ncomp(0) {}

  constexpr Array4(T* a_p, Dim3 const& a_begin, Dim3 const& a_end, int a_ncomp) noexcept
      : p(a_p), jstride(a_end.x - a_begin.x), kstride(jstride * (a_end.y - a_begin.y)),
        nstride(kstride * (a_end.z - a_begin.z)), begin(a_begin), end(a_end), ncomp(a_ncomp) {}

  /// Array4<Real> -> Array4<Real const>, as in AMReX.
  template <class U,
            std::enable_if_t<
                std::is_same<std::remove_const_t<T>, U>::value && std::is_const<T>::value, int> = 0>
  constexpr Array4(Array4<U> const& rhs) noexcept
      : p(rhs.p), jstride(rhs.jstride), kstride(rhs.kstride), nstride(rhs.nstride),
        begin(rhs.begin), end(rhs.end), ncomp(rhs.ncomp) {}

  AMREX_GPU_HOST_DEVICE AMREX_FORCE_INLINE T& operator()(int i, int j, int k) const noexcept {
    return p[(i - begin.x) + (j - begin.y) * jstride + (k - begin.z) * kstride];
  }
  AMREX_GPU_HOST_DEVICE AMREX_FORCE_INLINE T& operator()(int i, int j, int k,
                                                         int n) const noexcept {
    return p[(i - begin.x) + (j - begin.y) * jstride + (k - begin.z) * kstride + n * nstride];
  }
  AMREX_GPU_HOST_DEVICE AMREX_FORCE_INLINE T* ptr(int i, int j, int k) const noexcept {
    return p + ((i - begin.x) + (j - begin.y) * jstride + (k - begin.z) * kstride);
  }
  constexpr int nComp() const noexcept { return ncomp; }
  constexpr std::size_t size() const noexcept { return std::size_t(nstride) * ncomp; }
};

/// CPU ParallelFor over a box: k, j, i (i innermost, vectorized in AMReX).
template <class F> void ParallelFor(Box const& box, F&& f) noexcept {
  const auto lo = lbound(box);
  const auto hi = ubound(box);
  for (int k = lo.z; k <= hi.z; ++k)
    for (int j = lo.y; j <= hi.y; ++j) {
      AMREX_PRAGMA_SIMD
      for (int i = lo.x; i <= hi.x; ++i)
        f(i, j, k);
    }
}

/// ParallelFor over a box and ncomp components: n outermost.
template <class T, class F, typename = std::enable_if_t<std::is_integral<T>::value>>
void ParallelFor(Box const& box, T ncomp, F&& f) noexcept {
  const auto lo = lbound(box);
  const auto hi = ubound(box);
  for (T n = 0; n < ncomp; ++n)
    for (int k = lo.z; k <= hi.z; ++k)
      for (int j = lo.y; j <= hi.y; ++j) {
        AMREX_PRAGMA_SIMD
        for (int i = lo.x; i <= hi.x; ++i)
          f(i, j, k, n);
      }
}

} // namespace amrex
