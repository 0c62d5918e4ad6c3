// r3: std::vector work array then neighbour read, int counter against (int)u.size()
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>
DPGEN_KERNEL void r3_vector_work(DPGEN_IN const std::vector<double>& u, DPGEN_OUT std::vector<double>& w, DPGEN_OUT std::vector<double>& o) {
  const int n = (int)u.size();
  for (int i = 0; i < n; ++i) w[i] = u[i] * u[i];
  for (int i = 1; i < n; ++i) o[i] = w[i] * w[i - 1] + w[n - 1 - i];
}
