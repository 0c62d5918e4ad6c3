// Unsigned arithmetic that wraps past the type's largest value, which dpgen's
// signed 64-bit integers do not: a multiplicative hash (also as `h *= c`), a
// subtraction written as the addition of 2^32 - 1, a 64-bit hash constant.
// Refused; an unsigned literal past 2^31 in a comparison or a conversion is
// accepted with its value (tests/styles/wide_constants.cpp).
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void hash32(DPGEN_IN const double* u, DPGEN_OUT double* v, unsigned n) {
  for (unsigned i = 0; i < n; ++i) {
    // CHECK-DAG: unsigned_wrap.cpp:[[@LINE+1]]:26: error: unsigned arithmetic 'i * 2654435761u' with the constant 2654435761 may wrap around past the type's largest value (a hash, or a subtraction written as an addition), where dpgen's index arithmetic (signed, 64 bits) does not; outside the kernel subset [dpgen-unsupported]
    const unsigned h = i * 2654435761u;
    v[i] = u[i] * static_cast<double>(h % 1000u);
  }
}

DPGEN_KERNEL void minus_one(DPGEN_IN const double* u, DPGEN_OUT double* v, unsigned n) {
  for (unsigned i = 0; i < n; ++i) {
    // CHECK-DAG: unsigned_wrap.cpp:[[@LINE+1]]:26: error: unsigned arithmetic 'i + 4294967295u' with the constant 4294967295
    const unsigned h = i + 4294967295u;
    v[i] = h < 10u ? u[i] : 2.0 * u[i];
  }
}

DPGEN_KERNEL void hash_compound(DPGEN_IN const double* u, DPGEN_OUT double* v, unsigned n) {
  for (unsigned i = 0; i < n; ++i) {
    unsigned h = i + 1u;
    // CHECK-DAG: unsigned_wrap.cpp:[[@LINE+1]]:7: error: unsigned arithmetic 'h *= 2654435761u' with the constant 2654435761 may wrap around
    h *= 2654435761u;
    v[i] = u[i] * static_cast<double>(h % 1000u);
  }
}

DPGEN_KERNEL void hash64(DPGEN_IN const double* u, DPGEN_OUT double* v, int n) {
  for (int i = 0; i < n; ++i) {
    // CHECK-DAG: unsigned_wrap.cpp:[[@LINE+1]]:64: error: this integer constant (64 bits) is outside the range of long long, in which dpgen computes integers [dpgen-unsupported]
    const unsigned long long h = (unsigned long long)(i + 1) * 0x9E3779B97F4A7C15ull;
    v[i] = u[i] * static_cast<double>(h >> 60);
  }
}
