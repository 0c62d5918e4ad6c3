// Inactive inputs: a null adjoint pointer skips that input's loops (fused or
// not, gather or scatter) and leaves the other inputs' adjoints exactly as a
// run with every adjoint would.
#include <doctest/doctest.h>

#include "scaled_rows_adjoint.hpp"
#include "semi_lagrangian_adjoint.hpp"
#include "test_kernels.hpp"
#include "upwind_step_adjoint.hpp"

#include <cmath>
#include <vector>

namespace {
std::vector<double> wave(size_t n, double f, double shift = 0) {
  std::vector<double> v(n);
  for (size_t i = 0; i < n; ++i)
    v[i] = std::sin(f * double(i) + shift);
  return v;
}
} // namespace

TEST_CASE("a null adjoint skips that input (fused upwind loop)") {
  const int n = 20000; // enough cells for the threaded interior
  auto d = wave(n, 0.01), u = wave(n, 0.003, 1.0), seed = wave(n, 0.02, 2.0);
  std::vector<double> d_all(n, 0.0), u_all(n, 0.0), d_only(n, 0.0), u_only(n, 0.0);
  upwind_step_adjoint(d.data(), d_all.data(), u.data(), u_all.data(), seed.data(), n, 0.1, 0.5);
  upwind_step_adjoint(d.data(), d_only.data(), u.data(), nullptr, seed.data(), n, 0.1, 0.5);
  upwind_step_adjoint(d.data(), nullptr, u.data(), u_only.data(), seed.data(), n, 0.1, 0.5);
  CHECK(d_only == d_all);
  CHECK(u_only == u_all);
  upwind_step_adjoint(d.data(), nullptr, u.data(), nullptr, seed.data(), n, 0.1, 0.5); // no-op
}

TEST_CASE("a null adjoint skips that input (separate loops, scatter form)") {
  const int nx = 7, ny = 5, n = nx * ny;
  auto a = wave(n, 0.3), c = wave(nx, 0.7), nu = wave(1, 1.0, 0.5), mask = wave(n, 0.2, 0.3);
  auto seed = wave(n, 0.5, 0.1);
  std::vector<double> aa(n, 0.0), ca(nx, 0.0), na(1, 0.0), ca2(nx, 0.0);
  scaled_rows_adjoint(a.data(), aa.data(), c.data(), ca.data(), nu.data(), na.data(), mask.data(),
                      seed.data(), nx, ny);
  scaled_rows_adjoint(a.data(), nullptr, c.data(), ca2.data(), nu.data(), nullptr, mask.data(),
                      seed.data(), nx, ny);
  CHECK(ca2 == ca);

  const int m = 12;
  auto q = wave(m, 0.4), vel = wave(m, 0.9, 0.2), s = wave(m, 0.6);
  std::vector<double> qa(m, 0.0), va(m, 0.0), qa2(m, 0.0);
  semi_lagrangian_adjoint(q.data(), qa.data(), vel.data(), va.data(), s.data(), m, 0.3, 0.5);
  semi_lagrangian_adjoint(q.data(), qa2.data(), vel.data(), nullptr, s.data(), m, 0.3, 0.5);
  CHECK(qa2 == qa);
}
