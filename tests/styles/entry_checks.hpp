// For the style tests of kernels with one input array and one output array: the kernel,
// its parallel forward, adjoint and tangent with the sizes bound (Entry), checked on small
// sizes against the checker's differences and the dot-product test (check_small) and on
// large ones, where the nests run on every thread, the parallel forward and the tangent's
// primal against the kernel bit for bit on 1 and 2 threads (check_large).
#pragma once

#include "same_bits.hpp"
#include "support/adjoint_check.hpp"

#include <omp.h>

#include <cmath>
#include <cstddef>
#include <functional>
#include <vector>

namespace dpgen_test {

struct Entry {
  size_t in_size, out_size;
  std::function<void(const double*, double*)> kernel, parallel;
  std::function<void(const double*, double*, const double*)> adjoint; // (in, in_adj, seed)
  std::function<void(const double*, const double*, double*, double*)> tangent;
};

inline void check_small(const Entry& e) {
  check_one_to_one(e.in_size, e.out_size, e.kernel, e.adjoint, e.tangent);
}

inline void check_large(const Entry& e) {
  const int saved = omp_get_max_threads();
  for (int threads : {1, 2}) {
    CAPTURE(threads);
    omp_set_num_threads(threads);
    same_bits(e.in_size, e.out_size, e.kernel, e.parallel);
    const std::vector<double> a = wavy(e.in_size, 0.3), dir = wavy(e.in_size, 1.1);
    std::vector<double> b(e.out_size, std::nan("")), bt = b, bdot = b;
    e.kernel(a.data(), b.data());
    e.tangent(a.data(), dir.data(), bt.data(), bdot.data());
    CHECK(same_values(b, bt));
  }
  omp_set_num_threads(saved);
}

// Calls `check(nx, ny, nz, large)` for 3D grids of 1 to 10,240 cells: small ones (large
// false: check them with check_small) and one of 32 x 16 x 20 (large: check_large).
template <typename Check> void for_3d_grids(Check&& check) {
  const int dims[][3] = {{1, 1, 1}, {3, 2, 2}, {2, 4, 3}, {32, 16, 20}};
  for (const auto& d : dims) {
    CAPTURE(d[0]);
    CAPTURE(d[2]);
    check(d[0], d[1], d[2], d[0] == 32);
  }
}

} // namespace dpgen_test

// The Entry of kernel `k(a, b, args...)`: `in` input and `out` output values, the other
// arguments bound (captured by reference).
#define DPGEN_TEST_ENTRY(k, in, out, ...)                                                          \
  dpgen_test::Entry {                                                                              \
    size_t(in), size_t(out), [&](const double* a, double* b) { k(a, b, __VA_ARGS__); },            \
        [&](const double* a, double* b) { k##_parallel_forward(a, b, __VA_ARGS__); },              \
        [&](const double* a, double* adj, const double* seed) {                                    \
          k##_adjoint(a, adj, seed, __VA_ARGS__);                                                  \
        },                                                                                         \
        [&](const double* a, const double* d, double* b, double* bd) {                             \
          k##_tangent(a, d, b, bd, __VA_ARGS__);                                                   \
        }                                                                                          \
  }

// A kernel `k(a, b, nx, ny)` on an nx-by-ny grid.
#define DPGEN_TEST_GRID_ENTRY(k, nx, ny)                                                           \
  DPGEN_TEST_ENTRY(k, size_t(nx) * size_t(ny), size_t(nx) * size_t(ny), nx, ny)
