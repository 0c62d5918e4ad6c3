// Accessor objects the kernel makes over its raw arrays, as C++ codes wrap a
// pointer and a row length to write U(i, j) (operator() returns the element
// by value): an aggregate (`Grid2 U{u, nx}`) and a class whose constructor
// copies its parameters into private members (`Field2 U(u, nx)`); a
// variable-coefficient Laplacian with face averages, and a nonlinear update;
// accessors whose operator() returns a reference, written through as well as
// read: fluxes added to both cells of a face (`R(i, j) += f; R(i + 1, j) -=
// f;`), an element stored then scaled (`V(i, j) *= ...`), and a class with a
// const and a non-const overload, as containers write them; a span-like row whose
// operator[] returns a reference or a value; accessors passed to helpers and lambdas, made
// over a row (`ConstSpan row(u + j * nx)`) or at an offset (`Grid2 U{u + nx, nx}`).
#include "dpgen/annotate.hpp"

struct Grid2 {
  const double* p;
  int nx;
  double operator()(int i, int j) const { return p[j * nx + i]; }
};

DPGEN_KERNEL void accessor_local(DPGEN_IN const double* u, DPGEN_IN const double* k,
                                 DPGEN_OUT double* out, int nx, int ny) {
  const Grid2 U{u, nx}, K{k, nx};
  for (int j = 1; j < ny - 1; ++j)
    for (int i = 1; i < nx - 1; ++i) {
      const double ke = 0.5 * (K(i, j) + K(i + 1, j)), kw = 0.5 * (K(i, j) + K(i - 1, j));
      const double kn = 0.5 * (K(i, j) + K(i, j + 1)), ks = 0.5 * (K(i, j) + K(i, j - 1));
      out[j * nx + i] = ke * (U(i + 1, j) - U(i, j)) - kw * (U(i, j) - U(i - 1, j)) +
                        kn * (U(i, j + 1) - U(i, j)) - ks * (U(i, j) - U(i, j - 1));
    }
}

class Field2 {
public:
  Field2(const double* data, int stride) : data_(data), stride_(stride) {}
  double operator()(int i, int j) const { return data_[j * stride_ + i]; }

private:
  const double* data_;
  int stride_;
};

DPGEN_KERNEL void accessor_ctor(DPGEN_IN const double* u, DPGEN_OUT double* out, int nx, int ny) {
  const Field2 U(u, nx);
  for (int j = 1; j < ny - 1; ++j)
    for (int i = 1; i < nx - 1; ++i)
      out[j * nx + i] = U(i, j) * (U(i + 1, j) + U(i - 1, j) + U(i, j + 1) + U(i, j - 1));
}

// An aggregate whose operator() returns the element by reference (const: the pointer is
// not changed, the element may be).
struct Cells {
  double* p;
  int nx;
  double& operator()(int i, int j) const { return p[j * nx + i]; }
};

struct ConstCells {
  const double* p;
  int nx;
  const double& operator()(int i, int j) const { return p[j * nx + i]; }
};

// x-fluxes between neighbours added to both cells, then a second output stored and scaled.
DPGEN_KERNEL void accessor_writes(DPGEN_IN const double* u, DPGEN_OUT double* res,
                                  DPGEN_OUT double* v, int nx, int ny) {
  const ConstCells U{u, nx};
  const Cells R{res, nx}, V{v, nx};
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      R(i, j) = 0.0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx - 1; ++i) {
      const double f = 0.5 * (U(i + 1, j) * U(i + 1, j) - U(i, j) * U(i, j));
      R(i, j) += f;
      R(i + 1, j) -= f;
    }
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      V(i, j) = U(i, j) + 1.0;
      V(i, j) *= U(i, j);
    }
}

// A grid class with private members, a constructor, and both overloads: the const object
// reads through `const double& operator() const`, the other writes through `double&
// operator()`.
class Grid {
public:
  Grid(double* data, int stride) : data_(data), stride_(stride) {}
  double& operator()(int i, int j) { return data_[j * stride_ + i]; }
  const double& operator()(int i, int j) const { return data_[j * stride_ + i]; }

private:
  double* data_;
  int stride_;
};

DPGEN_KERNEL void accessor_overloads(DPGEN_IN double* u, DPGEN_OUT double* out, int nx, int ny) {
  const Grid U(u, nx);
  Grid Out(out, nx);
  for (int j = 1; j < ny - 1; ++j)
    for (int i = 1; i < nx - 1; ++i)
      Out(i, j) = U(i, j) * (U(i + 1, j) - 2.0 * U(i, j) + U(i - 1, j)) + U(i, j + 1) * U(i, j - 1);
}

// A sum spelled out through the accessor (`R(i, j) = R(i, j) + x - y`), in a later loop nest.
DPGEN_KERNEL void accessor_chain(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                 DPGEN_OUT double* res, int nx, int ny) {
  const Cells R{res, nx};
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      R(i, j) = b[j * nx + i];
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      R(i, j) = R(i, j) + a[j * nx + i] * a[j * nx + i] - b[j * nx + i] * a[j * nx + i];
}

// A span-like row with operator[]: by reference (written through, fluxes added to both cells
// of a face) and by value (read), as containers and span classes spell it.
struct Span {
  double* p;
  double& operator[](int i) const { return p[i]; }
};

class ConstSpan {
public:
  explicit ConstSpan(const double* p) : p_(p) {}
  double operator[](int i) const { return p_[i]; }

private:
  const double* p_;
};

DPGEN_KERNEL void accessor_subscript(DPGEN_IN const double* u, DPGEN_OUT double* res, int n) {
  const ConstSpan U(u);
  const Span R{res};
  for (int i = 0; i < n; ++i)
    R[i] = U[i];
  for (int i = 0; i < n - 1; ++i) {
    const double f = U[i] * U[i + 1];
    R[i] -= f;
    R[i + 1] += f;
  }
}

// Accessors passed to helpers and lambdas, by const reference and by value: a Laplacian of a
// helper, a store through a helper's reference-returning accessor, a lambda's difference.
static double laplacian_at(const Grid2& U, int i, int j) {
  return U(i + 1, j) + U(i - 1, j) + U(i, j + 1) + U(i, j - 1) - 4.0 * U(i, j);
}

static void store_at(const Cells& R, int i, int j, double v) { R(i, j) = v; }

static double second_difference(ConstSpan s, int i) { return s[i + 1] - 2.0 * s[i] + s[i - 1]; }

DPGEN_KERNEL void accessor_helpers(DPGEN_IN const double* u, DPGEN_OUT double* lap,
                                   DPGEN_OUT double* dxx, int nx, int ny) {
  const Grid2 U{u, nx};
  const Cells L{lap, nx};
  auto dx = [](const Grid2& G, int i, int j) { return 0.5 * (G(i + 1, j) - G(i - 1, j)); };
  for (int j = 1; j < ny - 1; ++j)
    for (int i = 1; i < nx - 1; ++i)
      store_at(L, i, j, laplacian_at(U, i, j) * dx(U, i, j));
  for (int j = 0; j < ny; ++j) {
    const ConstSpan row(u + j * nx);
    for (int i = 1; i < nx - 1; ++i)
      dxx[j * nx + i] = second_difference(row, i);
  }
}

// An accessor made over the kernel's array at an offset (`u + nx`: its row 1 is U's row 0).
DPGEN_KERNEL void accessor_offset(DPGEN_IN const double* u, DPGEN_OUT double* out, int nx, int ny) {
  const Grid2 U{u + nx, nx};
  for (int j = 0; j < ny - 1; ++j)
    for (int i = 0; i < nx; ++i)
      out[j * nx + i] = U(i, j) * u[j * nx + i];
}
