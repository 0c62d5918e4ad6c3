// Calls in an operand that C++ evaluates only under a condition: a `?:` arm,
// the right side of `&&` / `||`, with an argument read at an index that the
// condition guards (`i > 0 ? sq(a[i - 1]) : a[i]`). dpgen lowers the call as
// if it always ran and selects its value after; up to session 23 the helper's
// parameter (`x = a[i - 1]`, or a local of a lambda's body) was computed
// before the select in the parallel forward and the tangent, and before every
// loop where the call was at the kernel's top level, so the generated code
// read a[-1] at i = 0 (the adjoint of the top-level case too). The tests call
// every generated function on arrays of exactly the kernel's sizes, so the
// sanitizer build sees any read out of bounds.
#include "dpgen/annotate.hpp"

#include <cmath>

static double sq(double x) { return x * x; }
static bool positive(double x) { return x > 0.0; }

// A slope limiter with a branch of its own (its returns merge into a select).
static double minmod(double l, double r) {
  if (l * r <= 0.0)
    return 0.0;
  return std::fabs(l) < std::fabs(r) ? l : r;
}

template <class T> T central(const T& l, const T& r) { return 0.5 * (l + r); }

// A helper in the true arm.
DPGEN_KERNEL void sq_left(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i)
    b[i] = i > 0 ? sq(a[i - 1]) : a[i];
}

// A lambda in the true arm, reading to the right.
DPGEN_KERNEL void lambda_right(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  auto f = [](double x) { return x * std::sin(x); };
  for (int i = 0; i < n; ++i)
    b[i] = i + 1 < n ? f(a[i + 1]) : 2.0 * a[i];
}

// The index passed, the element read into a local of the lambda's body.
DPGEN_KERNEL void index_lambda(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  auto at = [&](int k) {
    const double y = a[k];
    return y * y + a[k];
  };
  for (int i = 0; i < n; ++i)
    b[i] = i == 0 ? a[i] : at(i - 1);
}

// A predicate on the right of `&&` in an if.
DPGEN_KERNEL void and_guard(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i) {
    if (i > 0 && positive(a[i - 1]))
      b[i] = a[i] * a[i];
    else
      b[i] = 3.0 * a[i];
  }
}

// On the right of `||`, in a `?:` condition.
DPGEN_KERNEL void or_guard(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i)
    b[i] = (i == 0 || sq(a[i - 1]) > 1.0) ? a[i] : a[i] * a[i];
}

// At the kernel's top level: computed before the loop, a[-1] at n = 0.
DPGEN_KERNEL void last_value(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  const double last = n > 0 ? sq(a[n - 1]) : 0.0;
  for (int i = 0; i < n; ++i)
    b[i] = last * a[i];
}

// Nested conditionals, each arm a call.
DPGEN_KERNEL void nested_select(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i)
    b[i] = i > 1 ? (a[i] > 0.0 ? sq(a[i - 1]) : sq(a[i - 2])) : a[i];
}

// A line buffer read in an arm at an index only the arm's condition keeps
// written (w[0] is never written): the condition is a fact of the operand,
// so the read is proven (refused until the operand was lowered under it).
DPGEN_KERNEL void buffer_arm(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  double w[128]; // (n <= 128: the generated functions check it)
  for (int i = 1; i < n; ++i)
    w[i] = a[i] * a[i] + a[i - 1];
  for (int i = 0; i < n; ++i)
    b[i] = a[i] * (i > 0 ? sq(w[i]) * a[i] : 1.0);
}

// C89 counter, a branching helper in an arm, a template helper with const&.
DPGEN_KERNEL void c89_limited(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  int i;
  for (i = 0; i < n; i++) {
    b[i] = (i >= 2) ? minmod(a[i - 1] - a[i - 2], a[i] - a[i - 1])
                    : (i + 1 < n ? central(a[i], a[i + 1]) : a[i]);
  }
}
