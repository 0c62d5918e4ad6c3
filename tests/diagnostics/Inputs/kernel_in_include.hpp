// (tests/diagnostics/kernel_in_include.cpp includes this file)
#pragma once
#include "dpgen/annotate.hpp"

DPGEN_KERNEL inline void included_square(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i)
    b[i] = a[i] * a[i];
}
