// `return` and `continue` nested inside an if (or a switch case): what
// follows the outer if runs only where the arm that ran went on to its end.
// Until this test, the condition of an escape two levels deep was dropped
// (the stores after it ran everywhere: wrong values and derivatives), and
// a kernel-level `if (kind == 1) { if (n < 3) return; }` became the guard
// `n >= 3` for every kind. Found by a helper's corpus (session 19).
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void ret_nested_if(DPGEN_IN const double* u, DPGEN_OUT double* v, int n, int kind) {
  if (kind == 1) {
    if (n < 3)
      return;
  }
  for (int i = 0; i < n; ++i)
    v[i] = u[i] * u[i] * (kind + 2);
}

DPGEN_KERNEL void ret_between_nests(DPGEN_IN const double* u, DPGEN_OUT double* v,
                                    DPGEN_OUT double* w, int n, int kind) {
  for (int i = 0; i < n; ++i)
    w[i] = u[i] * u[i];
  if (kind >= 1) {
    if (n < 3 || kind == 2)
      return;
  }
  for (int i = 0; i < n; ++i)
    v[i] = u[i] * (kind + 2) * u[i];
}

DPGEN_KERNEL void ret_switch_case(DPGEN_IN const double* u, DPGEN_OUT double* v, int n, int kind) {
  switch (kind) {
  case 0:
    return;
  case 1:
    if (n < 3)
      return;
    break;
  default:
    break;
  }
  for (int i = 0; i < n; ++i)
    v[i] = u[i] * u[i] * (kind + 2);
}

DPGEN_KERNEL void cont_else_if(DPGEN_IN const double* u, DPGEN_OUT double* v, int n, int kind) {
  for (int i = 0; i < n; ++i) {
    double r = u[i];
    if (kind == 1) {
      r = r * 2.0;
    } else if (i == 1 || kind == 2) {
      continue;
    }
    v[i] = r * u[i];
  }
}

DPGEN_KERNEL void cont_inner_2d(DPGEN_IN const double* u, DPGEN_OUT double* v, int nx, int ny,
                                int kind) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      if (i == kind)
        continue;
      if (j > 0) {
        if (i + j == 3 || kind == 2)
          continue;
      }
      v[j * nx + i] = u[j * nx + i] * u[j * nx + i];
    }
}

DPGEN_KERNEL void cont_switch_case_if(DPGEN_IN const double* u, DPGEN_OUT double* v, int n,
                                      int kind) {
  for (int i = 0; i < n; ++i) {
    switch (kind) {
    case 0:
      if (u[i] < 0.0)
        continue;
      break;
    case 1:
      if (i > 1)
        continue;
      break;
    default:
      break;
    }
    v[i] = u[i] * u[i] * u[i];
  }
}

DPGEN_KERNEL void cont_local_in_arm(DPGEN_IN const double* u, DPGEN_OUT double* v, int n) {
  for (int i = 0; i < n; ++i) {
    if (i > 0) {
      const double d = u[i] - u[i - 1]; // (read only where i > 0)
      if (d < 0.0)
        continue;
    }
    v[i] = u[i] * u[i];
  }
}

// A store in an arm ahead of an escape nested in it, and a store after the
// if: their paths exclude each other (the second runs where the escape did
// not), which dpgen decides on a truth table over the conditions; it refused
// both kernels as "may be written twice" until session 21 (corpus 22).
DPGEN_KERNEL void store_nested_continue(DPGEN_IN const double* u, DPGEN_OUT double* v, int n,
                                        int kind) {
  for (int i = 0; i < n; ++i) {
    if (i > kind) {
      if (i > 4) {
        v[i] = u[i] * u[i];
        continue;
      }
    }
    v[i] = 2.0 * u[i];
  }
}

DPGEN_KERNEL void edge_store_else_if(DPGEN_IN const double* u, DPGEN_OUT double* v, int n,
                                     int kind) {
  for (int i = 0; i < n; ++i) {
    int im = i - 1, ip = i + 1;
    if (kind == 1) {
      im = i == 0 ? n - 1 : i - 1;
      ip = i == n - 1 ? 0 : i + 1;
    } else if (i == 0 || i == n - 1) {
      v[i] = u[i] * u[i];
      continue;
    }
    v[i] = u[im] * u[ip] + u[i];
  }
}
