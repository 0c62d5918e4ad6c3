// A user's names that dpgen's generated code also wants (issue 20, defect 2):
// locals `acc`, `hit`, `c_i`, `lo_i`, `in_hi_i`, `parallel_ok`, `exp_v0`, a
// scalar `seed` and a loop counter `edge`. Before the fix these shadowed or
// redeclared the adjoint's accumulators and cell counters; in scatter form,
// the local `seed` of the generated code silently replaced the parameter in
// the partials.
#include "dpgen/annotate.hpp"

#include <cmath>

DPGEN_KERNEL void names_like_generated(DPGEN_IN const double* u, DPGEN_OUT double* out, int n,
                                       double seed) {
  for (int edge = 1; edge < n - 1; ++edge) {
    const double acc = u[edge - 1] * seed;
    const double hit = u[edge + 1] - acc;
    const double c_i = std::exp(hit * 0.25);
    const double lo_i = c_i * u[edge], in_hi_i = lo_i + acc;
    const double exp_v0 = std::exp(in_hi_i * 0.1);
    const bool parallel_ok = u[edge] > 0.0;
    out[edge] = parallel_ok ? exp_v0 * hit : exp_v0 + hit;
  }
}

// Scatter form (a data-dependent read index), with the parameter `seed`.
DPGEN_KERNEL void names_like_generated_sl(DPGEN_IN const double* q, DPGEN_IN const double* vel,
                                          DPGEN_OUT double* q_next, int n, double seed) {
  for (int i = 0; i < n; ++i) {
    double x = i - seed * vel[i];
    double fl = std::floor(x);
    double w = x - fl;
    int i0 = ((int)fl % n + n) % n;
    int i1 = (i0 + 1) % n;
    q_next[i] = seed * ((1.0 - w) * q[i0] + w * q[i1]);
  }
}
