// The user's language flags win (issue 20, defect 3): a C kernel kept in a
// `.cpp` file (C-only code: `restrict`, `new` as a name) is parsed as C with
// `-x c`, `-xc`, `--language=c` after `--`, with the user's C standard, and
// its adjoint gets C linkage; without the flag it is C++ and Clang's errors
// point at the file.
// RUN: rm -rf %t && mkdir -p %t/a %t/b %t/c %t/d
// RUN: %dpgen %s --out-dir %t/a -- -I%runtime_inc -x c 2>&1 | FileCheck %s --check-prefix=QUIET --allow-empty
// RUN: FileCheck %s --check-prefix=HDR --input-file %t/a/language_flags_adjoint.hpp
// RUN: FileCheck %s --check-prefix=LOCAL --input-file %t/a/language_flags_adjoint.cpp
// RUN: %dpgen %s --out-dir %t/b -- -I%runtime_inc -std=c99 -xc -std=c++20 2>&1 | FileCheck %s --check-prefix=QUIET --allow-empty
// RUN: FileCheck %s --check-prefix=HDR --input-file %t/b/language_flags_adjoint.hpp
// RUN: %dpgen %s --out-dir %t/c -- -I%runtime_inc --language=c 2>&1 | FileCheck %s --check-prefix=QUIET --allow-empty
// RUN: %not %dpgen %s --out-dir %t/d -- -I%runtime_inc 2>&1 | FileCheck %s --check-prefix=CXX
// RUN: ls %t/d | %count 0
// QUIET-NOT: error
// HDR: extern "C" {
// HDR: void scale_c_adjoint(
// The local `new` (a C++ keyword; the adjoint is C++) is renamed.
// LOCAL: const double new_1 = w * a[i];
// CXX: language_flags.cpp:[[@LINE+3]]:{{[0-9]+}}: error:
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void scale_c(DPGEN_IN const double* restrict a, DPGEN_OUT double* restrict out,
                          int n, double w) {
  int i;
  for (i = 0; i < n; i++) {
    double new = w * a[i];
    out[i] = new * a[i];
  }
}
