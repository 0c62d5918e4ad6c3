/* A 1D shallow-water step as C hydro codes write it: a Rusanov flux helper
 * that returns both flux components through pointers, a wave-speed helper,
 * C89 counters, fluxes into work arrays, then the conservative update. */
#include "dpgen/annotate.hpp"

#include <math.h>

static double wave_speed(double h, double q, double g) {
  double u = q / h;
  return fabs(u) + sqrt(g * h);
}

static void rusanov(double hl, double ql, double hr, double qr, double g, double* fh,
                    double* fq) {
  double s, sl, sr;
  sl = wave_speed(hl, ql, g);
  sr = wave_speed(hr, qr, g);
  s = sl > sr ? sl : sr;
  *fh = 0.5 * (ql + qr) - 0.5 * s * (hr - hl);
  *fq = 0.5 * (ql * ql / hl + 0.5 * g * hl * hl + qr * qr / hr + 0.5 * g * hr * hr) -
        0.5 * s * (qr - ql);
}

DPGEN_KERNEL void riemann_outparams(DPGEN_IN const double* h, DPGEN_IN const double* q,
                                    DPGEN_OUT double* fh, DPGEN_OUT double* fq,
                                    DPGEN_OUT double* hn, DPGEN_OUT double* qn, int n, double g,
                                    double dtdx) {
  int i;
  double a, b;
  for (i = 0; i < n - 1; i++) {
    rusanov(h[i], q[i], h[i + 1], q[i + 1], g, &a, &b);
    fh[i] = a;
    fq[i] = b;
  }
  for (i = 1; i < n - 1; i++) {
    hn[i] = h[i] - dtdx * (fh[i] - fh[i - 1]);
    qn[i] = q[i] - dtdx * (fq[i] - fq[i - 1]);
  }
}
