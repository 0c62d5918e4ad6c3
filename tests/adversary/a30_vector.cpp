// adversary: std::vector<double>& with u.size()
#include "dpgen/annotate.hpp"

#include <vector>
DPGEN_KERNEL void a30_vector(DPGEN_IN const std::vector<double>& u, DPGEN_OUT std::vector<double>& o) {
  for (std::size_t i = 1; i + 1 < u.size(); ++i) o[i] = u[i - 1] * u[i + 1];
}
