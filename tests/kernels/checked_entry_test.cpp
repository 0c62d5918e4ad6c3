// <kernel>_adjoint_checked: each array followed by its number of elements;
// sizes that fit give exactly the raw adjoint, a short array throws
// std::invalid_argument naming it, its size, the elements the kernel touches
// and the sizes.
#include <doctest/doctest.h>

#include "support/thrown.hpp"

#include "laplacian2d_adjoint.hpp"
#include "semi_lagrangian_adjoint.hpp"
#include "shifted_read_adjoint.hpp"
#include "size_checks_adjoint.hpp"
#include "upwind_step_adjoint.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace {
std::vector<double> wave(size_t n, double f) {
  std::vector<double> v(n);
  for (size_t i = 0; i < n; ++i)
    v[i] = std::sin(f * double(i) + 0.3);
  return v;
}

using dpgen_test::thrown;
} // namespace

TEST_CASE("checked adjoint: right sizes give the raw adjoint") {
  const int nx = 6, ny = 5;
  const size_t n = size_t(nx * ny);
  auto a = wave(n, 0.3), seed = wave(n, 0.7);
  std::vector<double> raw(n, 0.0), checked(n, 0.0);
  laplacian2d_adjoint(a.data(), raw.data(), seed.data(), nx, ny, 0.1);
  laplacian2d_adjoint_checked(a.data(), n, checked.data(), n, seed.data(), n, nx, ny, 0.1);
  CHECK(checked == raw);
  // An inactive input: a null adjoint with size 0 is fine.
  CHECK_NOTHROW(
      laplacian2d_adjoint_checked(a.data(), n, nullptr, 0, seed.data(), n, nx, ny, 0.1));
}

TEST_CASE("checked adjoint: a short array throws and names it") {
  const int nx = 6, ny = 5;
  const size_t n = size_t(nx * ny);
  auto a = wave(n, 0.3), seed = wave(n, 0.7);
  std::vector<double> adj(n, 0.0);
  std::string m = thrown([&] {
    laplacian2d_adjoint_checked(a.data(), n, adj.data(), n, seed.data(), n - 1, nx, ny, 0.1);
  });
  CHECK(m.find("laplacian2d_adjoint_checked: 'out_adj' has 29 elements") != std::string::npos);
  CHECK(m.find("nx = 6, ny = 5") != std::string::npos);
  for (double v : adj)
    CHECK(v == 0.0); // checked before anything is written
  m = thrown([&] {
    upwind_step_adjoint_checked(a.data(), 10, adj.data(), 10, a.data(), 9, adj.data(), 10,
                                seed.data(), 10, 10, 0.1, 0.5);
  });
  CHECK(m.find("'u' has 9 elements, but the kernel touches elements 0 to 9") != std::string::npos);
  // A leading dimension given separately: the rows x_min..x_max of ny rows.
  int x_min = 2, x_max = 5;
  m = thrown([&] {
    leading_dim_adjoint_checked(a.data(), 20, adj.data(), 30, seed.data(), 30, &x_min, 1,
                                &x_max, 1, 3, 8);
  });
  CHECK(m.find("'a' has 20 elements, but the kernel touches elements 2 to 21") !=
        std::string::npos);
}

TEST_CASE("checked adjoint: data-dependent reads are checked where the data takes them") {
  const int n = 12;
  auto q = wave(n, 0.4), vel = wave(n, 0.9), seed = wave(n, 0.6);
  std::vector<double> qa(n, 0.0), va(n, 0.0), raw_q(n, 0.0), raw_v(n, 0.0);
  semi_lagrangian_adjoint(q.data(), raw_q.data(), vel.data(), raw_v.data(), seed.data(), n, 0.3,
                          0.5);
  semi_lagrangian_adjoint_checked(q.data(), n, qa.data(), n, vel.data(), n, va.data(), n,
                                  seed.data(), n, n, 0.3, 0.5);
  CHECK(qa == raw_q);
  CHECK(va == raw_v);
  CHECK_THROWS_AS(semi_lagrangian_adjoint_checked(q.data(), n, qa.data(), n, vel.data(), n - 1,
                                                  va.data(), n, seed.data(), n, n, 0.3, 0.5),
                  std::invalid_argument);
  // The departure points (periodic) read q at 0..n-1, each cell's own with zero velocity:
  // q of n - 1 values throws, naming the element the data reaches; nothing is written.
  const std::vector<double> rest(n, 0.0), q_short(q.begin(), q.end() - 1);
  std::vector<double> adj(n, 0.0);
  std::string m = thrown([&] {
    semi_lagrangian_adjoint_checked(q_short.data(), n - 1, adj.data(), n, rest.data(), n, nullptr,
                                    0, seed.data(), n, n, 0.3, 0.5);
  });
  CHECK(m.find("semi_lagrangian_adjoint_checked: 'q' has 11 elements, but the kernel touches "
               "element 11 (n = 12)") != std::string::npos);
  for (double v : adj)
    CHECK(v == 0.0);
}

TEST_CASE("checked adjoint: an index below 0 throws, from either end of the range") {
  // out[i] = f(a[i + shift], a[i + shift + 1]) for i in 1..n-1
  const int n = 6;
  auto a = wave(8, 0.3), seed = wave(size_t(n), 0.7);
  std::vector<double> adj(8, 0.0), raw(8, 0.0);
  for (int shift : {-1, 0, 1}) {
    CAPTURE(shift);
    std::fill(adj.begin(), adj.end(), 0.0);
    std::fill(raw.begin(), raw.end(), 0.0);
    shifted_read_adjoint(a.data(), raw.data(), seed.data(), n, shift);
    shifted_read_adjoint_checked(a.data(), 8, adj.data(), 8, seed.data(), size_t(n), n, shift);
    CHECK(adj == raw);
  }
  std::fill(adj.begin(), adj.end(), 0.0);
  std::string m = thrown([&] {
    shifted_read_adjoint_checked(a.data(), 8, adj.data(), 8, seed.data(), size_t(n), n, -2);
  });
  CHECK(m.find("shifted_read_adjoint_checked: 'a' has 8 elements, but the kernel touches "
               "elements -1 to 4 (n = 6, shift = -2)") != std::string::npos);
  m = thrown([&] {
    shifted_read_adjoint_checked(a.data(), 8, adj.data(), 8, seed.data(), size_t(n), n, 2);
  });
  CHECK(m.find("'a' has 8 elements, but the kernel touches elements 3 to 8") != std::string::npos);
  for (double v : adj)
    CHECK(v == 0.0);
}
