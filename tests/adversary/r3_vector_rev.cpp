// r3: std::vector with a mirror read u[u.size() - 1 - i]
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>
DPGEN_KERNEL void r3_vector_rev(DPGEN_IN const std::vector<double>& u, DPGEN_OUT std::vector<double>& o) {
  for (std::size_t i = 0; i < u.size(); ++i) o[i] = u[u.size() - 1 - i] * u[i];
}
