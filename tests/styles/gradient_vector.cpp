// Flux-weighted forward difference on std::vector fields with a size_t
// counter bounded by the vector size (the last cell is left alone).
#include "dpgen/annotate.hpp"

#include <cstddef>
#include <vector>

DPGEN_KERNEL void gradient_vector(DPGEN_IN const std::vector<double>& p,
                                  DPGEN_IN const std::vector<double>& k,
                                  DPGEN_OUT std::vector<double>& g, double inv_h) {
  for (std::size_t i = 0; i + 1 < p.size(); ++i)
    g[i] = -k[i] * (p[i + 1] - p[i]) * inv_h;
}
