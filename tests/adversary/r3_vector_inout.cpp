// r3: DPGEN_INOUT std::vector<double>& updated element by element
#include "dpgen/annotate.hpp"
#include <vector>
DPGEN_KERNEL void r3_vector_inout(DPGEN_INOUT std::vector<double>& u, DPGEN_IN const std::vector<double>& c) {
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = u[i] * c[u.size() - 1 - i] + u[i] * u[i];
}
