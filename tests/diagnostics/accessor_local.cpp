// Accessors a kernel makes over its arrays (accepted forms:
// tests/styles/accessor_local.cpp) must hold a kernel array as it is, with
// their members given in order or by a constructor that only copies its
// parameters; what is refused:
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

struct Grid2 {
  const double* p;
  int nx;
  double operator()(int i, int j) const { return p[j * nx + i]; }
};

class Shifted {
public:
  Shifted(const double* data, int stride) : data_(data + stride), stride_(stride) {}
  double operator()(int i, int j) const { return data_[j * stride_ + i]; }

private:
  const double* data_;
  int stride_;
};

// (over the kernel's array at an offset, `Grid2 U{u + nx, nx}`, it is accepted:
// tests/styles/accessor_local.cpp, accessor_offset)
DPGEN_KERNEL void local_array(DPGEN_IN const double* u, DPGEN_OUT double* out, int nx, int ny) {
  double tmp[4] = {0.0, 1.0, 2.0, 3.0};
  // CHECK-DAG: accessor_local.cpp:[[@LINE+1]]:17: error: member 'p' of functor 'Grid2' must be made from an array or view parameter of the kernel [dpgen-lambda]
  const Grid2 U{tmp, 2};
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      out[j * nx + i] = u[j * nx + i] * U(i % 2, j % 2);
}

DPGEN_KERNEL void computing_constructor(DPGEN_IN const double* u, DPGEN_OUT double* out, int nx,
                                        int ny) {
  // CHECK-DAG: accessor_local.cpp:[[@LINE+1]]:17: error: functor 'Shifted' must be made here from the kernel's views, arrays and values (Shifted{...}, members in order, or a constructor that copies its parameters into the members), or be '*this' of a member kernel [dpgen-lambda]
  const Shifted U(u, nx);
  for (int j = 0; j < ny - 1; ++j)
    for (int i = 0; i < nx; ++i)
      out[j * nx + i] = U(i, j);
}

struct Counting {
  const double* p;
  int nx;
  double operator()(int i, int j) { return p[j * nx + i]; } // (not const)
};

DPGEN_KERNEL void non_const_call(DPGEN_IN const double* u, DPGEN_OUT double* out, int nx, int ny) {
  Counting U{u, nx};
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      // CHECK-DAG: accessor_local.cpp:[[@LINE+1]]:25: error: 'U' is called through a non-const operator() of 'Counting': an object that may change itself from call to call is outside the kernel subset; declare the operator() const
      out[j * nx + i] = U(i, j);
}

// Written through: an accessor's reference-returning operator() is followed where its body is
// `return p[<index>];`, and what it writes must be an output.
struct TwoStep {
  double* p;
  int nx;
  double& operator()(int i, int j) const {
    const int k = j * nx + i;
    return p[k];
  }
};

struct Cells {
  double* p;
  int nx;
  double& operator()(int i, int j) const { return p[j * nx + i]; }
};

DPGEN_KERNEL void two_step_reference(DPGEN_IN const double* u, DPGEN_OUT double* out, int nx,
                                     int ny) {
  const TwoStep Out{out, nx};
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      // CHECK-DAG: accessor_local.cpp:[[@LINE+1]]:7: error: 'operator()' of 'TwoStep' returns a reference: dpgen follows one whose body is the one statement 'return p[<index>];', the element of an array it holds
      Out(i, j) = u[j * nx + i];
}

DPGEN_KERNEL void writes_input(DPGEN_IN double* u, DPGEN_OUT double* out, int nx, int ny) {
  const Cells U{u, nx};
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      out[j * nx + i] = U(i, j);
      // CHECK-DAG: accessor_local.cpp:[[@LINE+1]]:7: error: 'u' is written but is not a DPGEN_OUT parameter
      U(i, j) = 0.0;
    }
}

// A sum spelled out through an accessor whose term reads the element it adds to (its value
// before the statement, which the adjoint does not have).
DPGEN_KERNEL void chain_reads_itself(DPGEN_IN const double* u, DPGEN_OUT double* out, int nx,
                                     int ny) {
  const Cells Out{out, nx};
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      Out(i, j) = 0.0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      // CHECK-DAG: accessor_local.cpp:[[@LINE+1]]:53: error: output 'out' is read here after line [[@LINE-3]] wrote it, and written again on line [[@LINE+1]]
      Out(i, j) = Out(i, j) + u[j * nx + i] - 0.5 * out[j * nx + i];
}

// The same through operator[] (a span-like row): its body must be the one return.
struct CheckedSpan {
  double* p;
  int n;
  double& operator[](int i) const {
    const int k = i < n ? i : n - 1;
    return p[k];
  }
};

DPGEN_KERNEL void checked_subscript(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  const CheckedSpan O{out, n};
  for (int i = 0; i < n; ++i)
    // CHECK-DAG: accessor_local.cpp:[[@LINE+1]]:5: error: 'operator[]' of 'CheckedSpan' returns a reference: dpgen follows one whose body is the one statement 'return p[<index>];'
    O[i] = 2.0 * u[i];
}

// Passed to a helper: an accessor the kernel made over its arrays (a local), not a temporary.
static double centre(const Grid2& U, int i, int j) { return U(i, j); }

DPGEN_KERNEL void temporary_argument(DPGEN_IN const double* u, DPGEN_OUT double* out, int nx,
                                     int ny) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      // CHECK-DAG: accessor_local.cpp:[[@LINE+1]]:32: error: argument for view parameter 'U' of helper 'centre' must be a view parameter of the kernel or an accessor it made over its arrays
      out[j * nx + i] = centre(Grid2{u, nx}, i, j);
}
