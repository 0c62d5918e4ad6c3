// Heat step on std::vector fields, size taken from the input vector.
#include "dpgen/annotate.hpp"

#include <vector>

DPGEN_KERNEL void heat_vector(DPGEN_IN const std::vector<double>& u,
                              DPGEN_OUT std::vector<double>& u_new, double r) {
  const int n = static_cast<int>(u.size());
  for (int i = 1; i < n - 1; ++i)
    u_new[i] = u[i] + r * (u[i + 1] - 2.0 * u[i] + u[i - 1]);
}
