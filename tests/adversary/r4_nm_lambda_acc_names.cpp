// adversary: lambda named edge/interior, local named acc/hit
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_nm_lambda_acc_names(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  auto edge = [&](int i) { return u[i] * u[i]; };
  auto interior = [&](int i) { return edge(i) + u[i]; };
  double acc = 0.0;
  for (int i = 0; i < n; ++i) acc += interior(i);
  for (int i = 0; i < n; ++i) {
    const double hit = acc * u[i];
    out[i] = hit + edge(i);
  }
}
