// adversary: double (*a)[8] and double o[][8], n <= 8 correct; n > 8 must throw
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void a22_rows_fixed(DPGEN_IN const double (*a)[8], DPGEN_OUT double o[][8], int n) {
  for (int j = 1; j < n - 1; ++j)
    for (int i = 1; i < n - 1; ++i)
      o[j][i] = a[j][i] * (a[j - 1][i] + a[j + 1][i] + a[j][i - 1] + a[j][i + 1]);
}
