// Helpers and lambdas that return early, the way C solvers write them: a
// `void` helper that sets its out-parameters (or stores) and returns inside a
// branch, and a lambda that returns inside a branch and assigns a variable of
// its caller on the path that goes on. Each return is a way out of the call:
// what the caller sees after it is, per variable, the value it had at the
// return that was taken (until 2026-11-30 the first was rejected, and the
// second was rejected, or before session 23 accepted with the assignment
// holding also where the lambda had returned: a wrong value and gradient).
#include "dpgen/annotate.hpp"

#include <cmath>

// A Riemann-solver style flux: the upwind side chosen by an early return.
static void burgers_flux(double l, double r, double* f) {
  const double s = 0.5 * (l + r);
  if (s >= 0.0) {
    *f = 0.5 * l * l;
    return;
  }
  *f = 0.5 * r * r;
}

DPGEN_KERNEL void flux_early(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i + 1 < n; ++i) {
    double f;
    burgers_flux(a[i], a[i + 1], &f);
    b[i] = f;
  }
  if (n > 0)
    b[n - 1] = a[n - 1];
}

// Two out-parameters with defaults, left where the slopes disagree.
static void limited(double d1, double d2, double& slope, double& weight) {
  slope = 0.0;
  weight = 1.0;
  if (d1 * d2 <= 0.0)
    return;
  weight = d1 * d1 / (d1 * d1 + d2 * d2);
  slope = weight * d1 + (1.0 - weight) * d2;
}

DPGEN_KERNEL void slopes_early(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i) {
    if (i == 0 || i == n - 1) {
      b[i] = a[i];
      continue;
    }
    double s, w;
    limited(a[i] - a[i - 1], a[i + 1] - a[i], s, w);
    b[i] = a[i] + 0.5 * s * w;
  }
}

// A return nested in an arm, another in the else arm, a fall-through.
static void pieces(double x, double& r) {
  if (x > 0.0) {
    if (x > 1.0) {
      r = 1.0 + std::log(x);
      return;
    }
  } else {
    r = 0.5 * x;
    return;
  }
  r = x * x;
}

DPGEN_KERNEL void nested_early(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i) {
    double r = 0.0;
    pieces(2.0 * a[i], r);
    b[i] = r * a[i];
  }
}

// An out-pointer passed on to a second helper (`inner(f, x)`), both
// returning early: one local of the caller all the way down.
static void inner_flux(double* f, double x) {
  if (x > 0.0) {
    *f = x;
    return;
  }
  *f = -x * x;
}

static void outer_flux(double* f, double x) {
  inner_flux(f, x);
  if (x > 1.0)
    return;
  *f += 1.0;
}

DPGEN_KERNEL void forwarded_early(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i) {
    double r;
    outer_flux(&r, 2.0 * a[i]);
    b[i] = r;
  }
}

// Reads after the early return are guarded by it (a[i - 1] at i = 0 never).
static void left_product(const double* a, int i, double& r) {
  if (i == 0) {
    r = a[i];
    return;
  }
  r = a[i - 1] * a[i];
}

DPGEN_KERNEL void guarded_early(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i) {
    double r;
    left_product(a, i, r);
    b[i] = r;
  }
}

// A void helper that stores and returns early; called in an if arm.
static void put(double* o, int i, double v) {
  if (v < 0.0) {
    o[i] = 0.0;
    return;
  }
  o[i] = v * v;
}

DPGEN_KERNEL void store_early(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i) {
    if (i % 2 == 0)
      put(b, i, a[i] + 0.25);
    else
      b[i] = -a[i];
  }
}

// An order chosen at compile time: `if constexpr` returns in one
// instantiation, and what follows it is code of the other.
template <int Order> void face_value(double l, double r, double& f) {
  if constexpr (Order == 1) {
    f = l;
    return;
  }
  f = 1.5 * l - 0.5 * r;
}

DPGEN_KERNEL void constexpr_early(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i) {
    if (i + 1 == n) {
      b[i] = a[i];
      continue;
    }
    double f1, f2;
    face_value<1>(a[i], a[i + 1], f1);
    face_value<2>(a[i], a[i + 1], f2);
    b[i] = f1 * f2;
  }
}

// A lambda that returns in a branch and assigns its caller's variable after
// it (session 23 rejected this: the assignment would have held also where the
// lambda returned).
DPGEN_KERNEL void lambda_sets_after(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i) {
    double d = 1.0;
    auto g = [&](double x) {
      if (x < 0.0)
        return 0.0;
      d = 2.0 * x;
      return x * x;
    };
    const double v = g(a[i]);
    b[i] = v + d * a[i];
  }
}

// Assigned in the arm that goes on, beside a return in the other.
DPGEN_KERNEL void lambda_arm_sets(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i) {
    double w[2] = {0.5, 1.5};
    auto g = [&](double x) {
      if (x > 0.0) {
        if (x > 1.0)
          return 1.0;
        w[1] = 3.0 * x;
      } else {
        w[0] = x;
      }
      return x * x;
    };
    const double v = g(a[i]);
    b[i] = v + w[0] * w[1] * a[i];
  }
}

// Through a helper the lambda calls after its return.
static void set_twice(double& d, double x) { d = 2.0 * x; }

DPGEN_KERNEL void lambda_helper_sets(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i) {
    double d = 1.0;
    auto g = [&](double x) {
      if (x < 0.0)
        return 0.0;
      set_twice(d, x);
      return x * x;
    };
    const double v = g(a[i]);
    b[i] = v + d * a[i];
  }
}
