// Lambdas defined in the kernel and called in it (issue 20), inlined like
// helper functions: a Laplacian captured by reference, a flux with a value
// capture called twice per cell, a limiter with return arms defined inside
// the loop body, ones that set a variable of their caller before they return
// inside a branch.
#include "dpgen/annotate.hpp"

#include <cmath>

DPGEN_KERNEL void lambda_laplacian(DPGEN_IN const double* u, DPGEN_OUT double* out, int n,
                                   double h) {
  const double inv_h2 = 1.0 / (h * h);
  auto lap = [&](int i) { return (u[i - 1] - 2.0 * u[i] + u[i + 1]) * inv_h2; };
  for (int i = 1; i < n - 1; ++i)
    out[i] = lap(i) * u[i];
}

DPGEN_KERNEL void lambda_flux(DPGEN_IN const double* q, DPGEN_IN const double* vel,
                              DPGEN_OUT double* dq, int n, double dt) {
  const double half = 0.5;
  auto flux = [=](int f, double c) { return half * c * (q[f] + q[f + 1]) * vel[f]; };
  for (int i = 1; i < n - 1; ++i)
    dq[i] = q[i] - dt * (flux(i, 1.0) - flux(i - 1, 1.0));
}

DPGEN_KERNEL void lambda_limiter(DPGEN_IN const double* q, DPGEN_OUT double* slope, int n) {
  for (int i = 1; i < n - 1; ++i) {
    auto minmod = [](double a, double b) -> double {
      if (a * b <= 0.0)
        return 0.0;
      return std::fabs(a) < std::fabs(b) ? a : b;
    };
    slope[i] = minmod(q[i] - q[i - 1], q[i + 1] - q[i]);
  }
}

// A lambda handed to a helper of the user's that runs it over a range (a
// parallel-for of their own): the helper's loop is the kernel's.
template <typename Body> void for_interior(int n, const Body& body) {
  for (int i = 1; i < n - 1; ++i)
    body(i);
}

DPGEN_KERNEL void lambda_for_each(DPGEN_IN const double* u, DPGEN_OUT double* out, int n,
                                  double c) {
  auto square = [](double x) { return x * x; };
  for_interior(n, [&](int i) { out[i] = c * square(u[i + 1] - u[i - 1]) + u[i]; });
}

// A sum inside one iteration of the helper's loop (a window of half-width w
// <= 1 per cell, a loop dpgen does not unroll): an accumulator of the body,
// as in a loop nest of the kernel.
DPGEN_KERNEL void lambda_window_sum(DPGEN_IN const double* u, DPGEN_OUT double* out, int n, int w) {
  for_interior(n, [&](int i) {
    double s = 0.0;
    for (int m = -w; m <= w; ++m)
      s += u[i + m] * u[i + m];
    out[i] = std::sqrt(1.0 + s);
  });
}

// Lambdas that set a variable of the caller and then return inside a branch:
// the assignment comes first (at the lambda's top level, or in an if/else
// whose arms both go on, merged per arm), so it holds on every path. (One
// after such a return, or in an if one of whose arms returns, is an error:
// tests/diagnostics/lambda_rules.cpp.)
DPGEN_KERNEL void lambda_sets_then_returns(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    double weight = 1.0;
    auto damped = [&](double x) {
      weight = 0.5 * x;
      if (x < 0.0)
        return 0.0;
      const double y = x * x;
      return y + weight;
    };
    const double v = damped(u[i]);
    out[i] = v + weight * u[i];
  }
}

DPGEN_KERNEL void lambda_direction_then_returns(DPGEN_IN const double* vel,
                                                DPGEN_IN const double* q, DPGEN_OUT double* out,
                                                int n) {
  for (int i = 1; i < n - 1; ++i) {
    double dir = 0.0;
    auto upwind = [&](double v) {
      if (v > 0.0) {
        dir = 1.0;
      } else {
        dir = -1.0;
      }
      if (std::fabs(v) < 0.05)
        return 0.0;
      return v * (dir > 0.0 ? q[i] - q[i - 1] : q[i + 1] - q[i]);
    };
    const double f = upwind(vel[i]);
    out[i] = f + 0.5 * dir * q[i];
  }
}

// A local assigned again from a lambda or helper with branches inside (`s =
// minmod(...)` after `double s = 1.0;`, `s += ...`, a local array's element):
// until 2026-11-30 the assignment was lost (the forward kept `s = 1.0`, the
// gradient was 0): lowering the call reassigned the table of bindings, and a
// reference into it taken before pointed at another variable.
static double clip_opposite(double x, double y) {
  double r = x;
  if (x * y <= 0.0)
    r = 0.0;
  return r;
}

DPGEN_KERNEL void lambda_reassigned(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n - 1; ++i) {
    double s = 1.0, t = 2.0;
    double w[2] = {1.0, 2.0};
    auto minmod = [](double x, double y) {
      if (x * y <= 0.0)
        return 0.0;
      return std::fabs(x) < std::fabs(y) ? x : y;
    };
    s = minmod(a[i], a[i + 1]);
    t += minmod(a[i + 1], a[i]) * a[i];
    w[1] = clip_opposite(a[i], a[i + 1]);
    out[i] = s + 10.0 * t + 100.0 * w[1] + w[0];
  }
}
