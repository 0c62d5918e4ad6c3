// corpus: form=global expect=accept
// Model parameters as namespace-scope globals (`namespace model { ... }`): a
// constexpr size, a read-only global, and a DPGEN_IN global source field
// pointer. Assumed: the adjoint's `extern double* source_adj;` is declared in
// the same namespace (model::source_adj).
#include "dpgen/annotate.hpp"

#include <cmath>

namespace model {
constexpr int nmodes = 3;
double decay = 0.5;
DPGEN_IN double* source = nullptr; // nmodes * n values
} // namespace model

DPGEN_KERNEL void forced_decay(DPGEN_IN const double* q, DPGEN_OUT double* qn, int n, double dt) {
  for (int m = 0; m < model::nmodes; ++m)
    for (int i = 0; i < n; ++i)
      qn[m * n + i] = q[m * n + i] * std::exp(-model::decay * dt) +
                      dt * model::source[m * n + i] * q[m * n + i];
}
