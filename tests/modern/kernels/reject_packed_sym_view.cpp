// corpus: form=reject expect=reject
// reason: the output view's operator() is not affine (packed symmetric storage i*(i+1)/2 +
//   j): iterations (i, j) and (j, i) store to one element, so no element is written once
//   and no gather adjoint exists
//
// A view class whose operator() is non-affine: LAPACK-style packed storage
// of a symmetric matrix, written through on every (i, j) of a full loop.
#include "dpgen/annotate.hpp"

struct Dense {
  const double* p;
  int n;
  double operator()(int i, int j) const { return p[i * n + j]; }
};

struct PackedSym {
  double* p;
  int n;
  double& operator()(int i, int j) const {
    return i >= j ? p[i * (i + 1) / 2 + j] : p[j * (j + 1) / 2 + i];
  }
};

DPGEN_KERNEL void symmetrize(DPGEN_IN Dense a, DPGEN_OUT PackedSym s) {
  for (int i = 0; i < a.n; ++i)
    for (int j = 0; j < a.n; ++j)
      s(i, j) = 0.5 * (a(i, j) + a(j, i)) * (i == j ? 1.0 : 1.0 + a(i, j) * a(j, i));
}
