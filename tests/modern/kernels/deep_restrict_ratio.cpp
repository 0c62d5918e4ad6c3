// corpus: form=deep expect=accept
// Cell-centered 3D restriction with a runtime ratio r: three coarse loops and
// three ratio loops (a 6-deep nest), fine index (kc*r + kk, jc*r + jj, ic*r + ii).
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void restrict_avg3d(DPGEN_IN const double* fine, DPGEN_OUT double* crse, int ncx,
                                 int ncy, int ncz, int r) {
  const int nfx = ncx * r, nfy = ncy * r;
  const double inv = 1.0 / (r * r * r);
  for (int kc = 0; kc < ncz; ++kc)
    for (int jc = 0; jc < ncy; ++jc)
      for (int ic = 0; ic < ncx; ++ic) {
        double s = 0.0;
        for (int kk = 0; kk < r; ++kk)
          for (int jj = 0; jj < r; ++jj)
            for (int ii = 0; ii < r; ++ii)
              s += fine[((kc * r + kk) * nfy + jc * r + jj) * nfx + ic * r + ii];
        crse[(kc * ncy + jc) * ncx + ic] = s * inv;
      }
}
