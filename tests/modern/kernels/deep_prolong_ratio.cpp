// corpus: form=deep expect=accept
// Piecewise-constant prolongation of ncomp components with a runtime ratio,
// over coarse cells (a 5-deep nest): each coarse cell writes its r x r fine
// cells, fine index (jc*r + jj)*nfx + ic*r + ii: written once for r >= 1.
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void prolong_pc2d(DPGEN_IN const double* crse, DPGEN_OUT double* fine, int ncomp,
                               int ncx, int ncy, int r) {
  const int nfx = ncx * r, nfy = ncy * r;
  for (int n = 0; n < ncomp; ++n)
    for (int jc = 0; jc < ncy; ++jc)
      for (int ic = 0; ic < ncx; ++ic)
        for (int jj = 0; jj < r; ++jj)
          for (int ii = 0; ii < r; ++ii)
            fine[(n * nfy + jc * r + jj) * nfx + ic * r + ii] = crse[(n * ncy + jc) * ncx + ic];
}
