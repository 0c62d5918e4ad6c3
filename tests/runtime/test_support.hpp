// Helpers shared by the runtime tests.
#pragma once

#include <Eigen/Core>

#include <random>

namespace dpgen_test {

/// A vector of n uniform values in [lo, hi), reproducible from `seed`.
inline Eigen::VectorXd random_vector(Eigen::Index n, unsigned seed, double lo = -1.0,
                                     double hi = 1.0) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> dist(lo, hi);
  Eigen::VectorXd v(n);
  for (Eigen::Index i = 0; i < n; ++i)
    v[i] = dist(rng);
  return v;
}

} // namespace dpgen_test
