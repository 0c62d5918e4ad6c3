// Values made inside an arm and used by a store that a later statement of the
// iteration merges past the arm: `b[i] = 0; if (i > 0) { double d = a[i - 1];
// b[i] = d * d; }`. The tangent and the parallel forward computed `d` before
// the arm's test (a[-1] at i = 0), and the adjoint's gather wrote a_adj[-1];
// at the kernel's top level (`if (n > 0) { double last = a[n - 1]; ... }`,
// `if (n == 0) return; double last = a[n - 1];`) the local was computed before
// every loop, a[-1] at n = 0. A math function in an arm of a conditional
// (`m[i] > 0.5 ? exp(a[i + 1] - a[i]) : 0.0`) had its value computed before
// the conditional in the tangent. A helper's or lambda's early return
// (`if (i == 0) return 0.0; const double d = a[i - 1]; return d * d;`) made
// the same select. The tests call every generated function on
// arrays of exactly the kernel's sizes, so the sanitizer build sees any read
// or write out of bounds.
#include "dpgen/annotate.hpp"

#include <cmath>

DPGEN_KERNEL void left_square(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i) {
    b[i] = 0.0;
    if (i > 0) {
      const double d = a[i - 1];
      b[i] = d * d;
    }
  }
}

// (the value the if/else leaves, nested arms reading the value stored so far)
DPGEN_KERNEL void nested_arms(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i) {
    b[i] = -a[i];
    if (i > 0) {
      const double l = a[i - 1];
      b[i] = l;
      if (i > 1) {
        const double ll = a[i - 2];
        b[i] = l * ll + b[i];
      }
    }
  }
}

// Two outputs from one arm's locals, a math function among them.
DPGEN_KERNEL void slope_energy(DPGEN_IN const double* a, DPGEN_OUT double* b, DPGEN_OUT double* e,
                               int n) {
  for (int i = 0; i < n; ++i) {
    b[i] = a[i];
    e[i] = 0.0;
    if (i + 1 < n) {
      const double g = a[i + 1] - a[i];
      const double g2 = g * g;
      b[i] = g2 + a[i];
      e[i] = std::exp(g) * g2;
    }
  }
}

// A mask the caller sets to 0 at the last cell keeps a[i + 1] in bounds.
DPGEN_KERNEL void masked_exp(DPGEN_IN const double* a, const double* mask, DPGEN_OUT double* e,
                             int n) {
  for (int i = 0; i < n; ++i)
    e[i] = mask[i] > 0.5 ? std::exp(a[i + 1] - a[i]) : 0.0;
}

DPGEN_KERNEL void last_squared(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  out[0] = 0.0;
  if (n > 0) {
    double last = a[n - 1];
    out[0] = last * last;
  }
}

DPGEN_KERNEL void after_return(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  if (n == 0)
    return;
  const double first = a[0], last = a[n - 1];
  out[0] = first * last + std::sin(last);
}

// An arm's local read by the loop inside the arm.
DPGEN_KERNEL void scaled_by_last(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  if (n > 0) {
    const double last = a[n - 1];
    for (int i = 0; i < n; ++i)
      b[i] = a[i] * last;
  }
}

// 2D: the row below, read in an arm.
DPGEN_KERNEL void row_below(DPGEN_IN const double* a, DPGEN_OUT double* b, int nx, int ny) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      b[j * nx + i] = a[j * nx + i];
      if (j > 0) {
        const double s = a[(j - 1) * nx + i];
        b[j * nx + i] = a[j * nx + i] * s;
      }
    }
}

// In place: the value an arm stored, read back after the arm.
DPGEN_KERNEL void relax_left(DPGEN_IN const double* a, DPGEN_INOUT double* u, DPGEN_OUT double* f,
                             int n) {
  for (int i = 0; i < n; ++i) {
    if (i > 0) {
      const double d = a[i - 1] * u[i];
      u[i] = d;
    }
    f[i] = u[i] * 3.0;
  }
}

// A helper and a lambda that return early at the boundary.
static double left_sq(const double* a, int i) {
  if (i == 0)
    return 0.0;
  const double d = a[i - 1];
  return d * d;
}

DPGEN_KERNEL void early_returns(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  auto right = [&](int i) {
    if (i + 1 >= n)
      return 0.0;
    const double g = a[i + 1] - a[i];
    return std::exp(g) * g;
  };
  for (int i = 0; i < n; ++i)
    b[i] = left_sq(a, i) + right(i) * a[i];
}

// A chain of values in an arm, each used twice: the guarded copies share them
// as the kernel does (inlined, the text would grow as 3^depth).
DPGEN_KERNEL void arm_chain(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i) {
    b[i] = a[i];
    if (i > 0) {
      const double x1 = 0.1 * a[i - 1];
      const double x2 = x1 * x1 + x1;
      const double x3 = x2 * x2 + x2;
      const double x4 = x3 * x3 + x3;
      const double x5 = x4 * x4 + x4;
      b[i] = 1e-3 * x5 + x3 * x2;
    }
  }
}

// An integer divided by a parameter after the guard that keeps it nonzero.
DPGEN_KERNEL void every_sth(DPGEN_IN const double* a, DPGEN_OUT double* b, int n, int s) {
  if (s <= 0)
    return;
  const int m = n / s;
  for (int i = 0; i < m; ++i)
    b[i] = a[i * s] * a[i * s];
}

// A shift by a variable after the guard that keeps it in range (`1 << sh` at
// sh = -2 is undefined): computed before the loops only where the guard holds.
DPGEN_KERNEL void pow2_after_guard(DPGEN_IN const double* a, DPGEN_OUT double* b, int n, int sh) {
  if (sh < 0 || sh > 30)
    return;
  const int m = 1 << sh;
  for (int i = 0; i < n; ++i)
    b[i] = a[i] * double(m % 7 + 1);
}

// The same in an arm, by the loop's counter (`1 << (i - 1)` at i = 0).
DPGEN_KERNEL void pow2_in_arm(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i) {
    b[i] = a[i];
    if (i >= 1 && i < 20) {
      const int s = 1 << (i - 1);
      b[i] = a[i] * double(s % 5 + 1);
    }
  }
}

// A constant shift of a value that is negative where the arm does not run
// (`(i - 1) << 2` at i = 0), used three times past the arm in a local.
DPGEN_KERNEL void neg_shift_in_arm(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i) {
    double y = a[i];
    if (i >= 1) {
      const int s = (i - 1) << 2;
      y = a[i] * double(s * s + s + 1) * 1e-3;
    }
    b[i] = y;
  }
}

// An arm's condition that reads a value of the enclosing arm (`d > 0.0`): the
// select past the arms tests a guarded copy of `d`.
DPGEN_KERNEL void cond_on_arm_value(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i) {
    b[i] = a[i];
    if (i > 0) {
      const double d = a[i - 1];
      if (d > 0.0) {
        const double e = 2.0 * a[i - 1] + a[i];
        b[i] = e * d;
      }
    }
  }
}

// The same for an in-place array read back after the arms.
DPGEN_KERNEL void damp_by_right(DPGEN_IN const double* a, DPGEN_INOUT double* u,
                                DPGEN_OUT double* f, int n) {
  for (int i = 0; i < n; ++i) {
    if (i + 1 < n) {
      const double r = a[i + 1];
      if (r < 0.5)
        u[i] = r * u[i];
    }
    f[i] = 2.0 * u[i];
  }
}
