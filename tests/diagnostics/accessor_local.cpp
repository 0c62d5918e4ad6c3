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

DPGEN_KERNEL void offset_pointer(DPGEN_IN const double* u, DPGEN_OUT double* out, int nx, int ny) {
  // CHECK-DAG: accessor_local.cpp:[[@LINE+1]]:17: error: member 'p' of functor 'Grid2' must be made from an array or view parameter of the kernel [dpgen-lambda]
  const Grid2 U{u + nx, nx};
  for (int j = 0; j < ny - 1; ++j)
    for (int i = 0; i < nx; ++i)
      out[j * nx + i] = U(i, j);
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
