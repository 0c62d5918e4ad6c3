// view_field1d (tests/styles/): a deep-const field class (an AthenaArray-like
// const operator() returning a value) read by const reference and written
// by reference; its size from a method.
#include "dpgen/annotate.hpp"

#include "include/user_views.hpp"

#include <cmath>

DPGEN_KERNEL void view_field1d(DPGEN_IN const grid::Field& a, DPGEN_OUT grid::Field& b, double c) {
  for (int i = 1; i < a.size() - 1; ++i)
    b(i) = std::sin(a(i)) * (a(i + 1) - a(i - 1)) + c * a(i);
}
