// local_chains (tests/styles/): values built from locals that are each used
// more than once, in the styles users write them: a chain of named locals, a
// helper applied to its own result, a lambda, a counted loop that updates one
// local, a chain under an arm, two reads that share the chain, an output
// read back and updated again and again, conditional updates in a row, and
// stages of an in-place update. Each value is used two or three times by the
// next, so an expression printed as a tree grows as 2^depth or 3^depth:
// dpgen makes a stored value that is read back a local (`b_1`) and names a
// local's derivative that a partial uses twice (`x2_d0`); before that,
// chain14 and conditional_adds ran the generator out of memory.
#include "dpgen/annotate.hpp"

#include <cmath>

// Fourteen locals, each the one before squared plus itself.
DPGEN_KERNEL void chain14(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i) {
    const double x1 = 0.1 * a[i];
    const double x2 = x1 * x1 + x1;
    const double x3 = x2 * x2 + x2;
    const double x4 = x3 * x3 + x3;
    const double x5 = x4 * x4 + x4;
    const double x6 = x5 * x5 + x5;
    const double x7 = x6 * x6 + x6;
    const double x8 = x7 * x7 + x7;
    const double x9 = x8 * x8 + x8;
    const double x10 = x9 * x9 + x9;
    const double x11 = x10 * x10 + x10;
    const double x12 = x11 * x11 + x11;
    const double x13 = x12 * x12 + x12;
    const double x14 = x13 * x13 + x13;
    b[i] = x14;
  }
}

namespace {
inline double logistic_step(double y, double r) { return y + r * y * (1.0 - y); }
} // namespace

// A helper applied to its own result, ten times; the neighbours share it.
DPGEN_KERNEL void helper_iterates(DPGEN_IN const double* a, DPGEN_OUT double* b, double r, int n) {
  for (int i = 1; i + 1 < n; ++i) {
    double y = 0.25 * (a[i - 1] + 2.0 * a[i] + a[i + 1]);
    y = logistic_step(logistic_step(logistic_step(logistic_step(logistic_step(y, r), r), r), r), r);
    y = logistic_step(logistic_step(logistic_step(logistic_step(logistic_step(y, r), r), r), r), r);
    b[i] = y;
  }
}

// A lambda applied in a counted loop (unrolled: a constant trip count).
DPGEN_KERNEL void lambda_loop(DPGEN_IN const double* a, DPGEN_IN const double* c,
                              DPGEN_OUT double* b, int n) {
  auto step = [](double s, double k) { return s + 0.5 * k * s * s - 0.1 * s * s * s; };
  for (int i = 0; i < n; ++i) {
    double s = a[i];
    for (int k = 0; k < 12; ++k)
      s = step(s, c[i]);
    b[i] = s;
  }
}

// A chain made in an arm that reads the left neighbour, merged past the arm.
DPGEN_KERNEL void chain_in_arm(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i) {
    b[i] = a[i];
    if (i > 0) {
      double x = 0.1 * a[i - 1];
      for (int k = 0; k < 12; ++k)
        x = x * x + x;
      b[i] = a[i] + x;
    }
  }
}

// A chain made in an arm and carried past it in a local variable (merged into
// a select after the if), not in a store.
DPGEN_KERNEL void chain_merged_past_arm(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i) {
    double y = a[i];
    if (i > 0) {
      double x = 0.1 * a[i - 1];
      for (int k = 0; k < 14; ++k)
        x = x * x + x;
      y = a[i] + x * y;
    }
    b[i] = y;
  }
}

// A local named so that its derivative's local (`inv_d0`) is the name the
// adjoint gives the hoisted 1.0 / d0: the generator must keep them apart (one
// shadowing the other multiplied the partial by cos(a[i]) instead of 1 / d0).
DPGEN_KERNEL void names_like_hoisted(DPGEN_IN const double* a, DPGEN_OUT double* b, double d0,
                                     int n) {
  for (int i = 0; i < n; ++i) {
    const double inv = std::sin(a[i]);
    b[i] = (inv * inv + inv) / d0;
  }
}

// Two reads of one input feed one chain, and a math function in it.
DPGEN_KERNEL void shared_chain_2d(DPGEN_IN const double* u, DPGEN_OUT double* v, int nx, int ny) {
  for (int j = 0; j < ny; ++j)
    for (int i = 1; i < nx; ++i) {
      double w = 0.5 * (u[j * nx + i] - u[j * nx + i - 1]);
      for (int k = 0; k < 8; ++k)
        w = w + 0.25 * std::tanh(w) * w;
      v[j * nx + i] = w * w + w;
    }
}

// An output read back and updated in place, five times: `b[i] = b[i] * b[i] + b[i]`.
DPGEN_KERNEL void readback_chain(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 1; i < n; ++i) {
    b[i] = 0.05 * (a[i - 1] + a[i]);
    b[i] = b[i] * b[i] + b[i];
    b[i] = b[i] * b[i] + b[i];
    b[i] = b[i] * b[i] + b[i];
    b[i] = b[i] * b[i] + b[i];
    b[i] = b[i] * b[i] + b[i];
  }
}

// Scalings and sums under conditions, one statement per threshold (a macro
// per statement, as codes write repeated updates): each keeps the element's
// earlier value where its condition fails, so that value is in both arms.
#define DPGEN_TEST_SCALE_ABOVE(t)                                                                  \
  if (a[i] > (t))                                                                                  \
  b[i] *= 1.0 + 0.1 * a[i]
#define DPGEN_TEST_ADD_ABOVE(t)                                                                    \
  if (a[i] > (t))                                                                                  \
  c[i] += a[i] * a[i]
DPGEN_KERNEL void conditional_updates(DPGEN_IN const double* a, DPGEN_OUT double* b,
                                      DPGEN_OUT double* c, int n) {
  for (int i = 0; i < n; ++i) {
    b[i] = a[i];
    DPGEN_TEST_SCALE_ABOVE(-0.8);
    DPGEN_TEST_SCALE_ABOVE(-0.6);
    DPGEN_TEST_SCALE_ABOVE(-0.4);
    DPGEN_TEST_SCALE_ABOVE(-0.2);
    DPGEN_TEST_SCALE_ABOVE(0.0);
    DPGEN_TEST_SCALE_ABOVE(0.2);
    DPGEN_TEST_SCALE_ABOVE(0.4);
    DPGEN_TEST_SCALE_ABOVE(0.6);
    DPGEN_TEST_SCALE_ABOVE(0.8);
    DPGEN_TEST_SCALE_ABOVE(0.9);
    DPGEN_TEST_SCALE_ABOVE(0.95);
    DPGEN_TEST_SCALE_ABOVE(0.99);
    c[i] = 0.0;
    DPGEN_TEST_ADD_ABOVE(-0.8);
    DPGEN_TEST_ADD_ABOVE(-0.6);
    DPGEN_TEST_ADD_ABOVE(-0.4);
    DPGEN_TEST_ADD_ABOVE(-0.2);
    DPGEN_TEST_ADD_ABOVE(0.0);
    DPGEN_TEST_ADD_ABOVE(0.2);
    DPGEN_TEST_ADD_ABOVE(0.4);
    DPGEN_TEST_ADD_ABOVE(0.6);
    DPGEN_TEST_ADD_ABOVE(0.8);
    DPGEN_TEST_ADD_ABOVE(0.9);
    DPGEN_TEST_ADD_ABOVE(0.95);
    DPGEN_TEST_ADD_ABOVE(0.99);
  }
}

// Sums into what the caller's array holds (no `=` first), under conditions:
// the forward forms add in the kernel's order, `((d[i] + a) + b) + ...`.
#define DPGEN_TEST_ADD_TO_ABOVE(t)                                                                 \
  if (a[i] > (t))                                                                                  \
  d[i] += 0.5 * a[i] * a[i]
DPGEN_KERNEL void conditional_adds(DPGEN_IN const double* a, DPGEN_OUT double* d, int n) {
  for (int i = 0; i < n; ++i) {
    d[i] += a[i];
    DPGEN_TEST_ADD_TO_ABOVE(-0.8);
    DPGEN_TEST_ADD_TO_ABOVE(-0.6);
    DPGEN_TEST_ADD_TO_ABOVE(-0.4);
    DPGEN_TEST_ADD_TO_ABOVE(-0.2);
    DPGEN_TEST_ADD_TO_ABOVE(0.0);
    DPGEN_TEST_ADD_TO_ABOVE(0.2);
    DPGEN_TEST_ADD_TO_ABOVE(0.4);
    DPGEN_TEST_ADD_TO_ABOVE(0.6);
    DPGEN_TEST_ADD_TO_ABOVE(0.8);
    DPGEN_TEST_ADD_TO_ABOVE(0.9);
    DPGEN_TEST_ADD_TO_ABOVE(0.95);
    DPGEN_TEST_ADD_TO_ABOVE(0.99);
    DPGEN_TEST_ADD_TO_ABOVE(0.999);
    DPGEN_TEST_ADD_TO_ABOVE(0.9999);
  }
}

// Ten explicit Euler stages of u' = f - u^3 on an array updated in place.
#define DPGEN_TEST_STAGE() u[i] = u[i] + dt * (f[i] - u[i] * u[i] * u[i])
DPGEN_KERNEL void inplace_stages(DPGEN_INOUT double* u, DPGEN_IN const double* f, double dt,
                                 int n) {
  for (int i = 0; i < n; ++i) {
    DPGEN_TEST_STAGE();
    DPGEN_TEST_STAGE();
    DPGEN_TEST_STAGE();
    DPGEN_TEST_STAGE();
    DPGEN_TEST_STAGE();
    DPGEN_TEST_STAGE();
    DPGEN_TEST_STAGE();
    DPGEN_TEST_STAGE();
    DPGEN_TEST_STAGE();
    DPGEN_TEST_STAGE();
  }
}
