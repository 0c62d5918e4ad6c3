// Helpers shared by the MPI tests.
#pragma once

#include <Eigen/Core>
#include <mpi.h>

#include <exception>
#include <random>
#include <string>

namespace dpgen_mpi_test {

/// n uniform values in [lo, hi), the same on every rank for the same seed.
inline Eigen::VectorXd random_vector(Eigen::Index n, unsigned seed, double lo = -1.0,
                                     double hi = 1.0) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> dist(lo, hi);
  Eigen::VectorXd v(n);
  for (Eigen::Index i = 0; i < n; ++i)
    v[i] = dist(rng);
  return v;
}

/// The message of the exception `f` throws, or "" when it throws none.
template <typename F> std::string error_of(F&& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

/// True when `text` contains `part`.
inline bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

/// The largest value of x over the ranks.
inline double max_over_ranks(double x, MPI_Comm comm = MPI_COMM_WORLD) {
  double m = 0;
  MPI_Allreduce(&x, &m, 1, MPI_DOUBLE, MPI_MAX, comm);
  return m;
}

inline int world_size() {
  int n = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &n);
  return n;
}

} // namespace dpgen_mpi_test
