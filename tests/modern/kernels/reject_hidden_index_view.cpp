// corpus: form=reject expect=reject
// reason: the view's operator() calls a function defined in another translation unit (a
//   space-filling-curve index): dpgen cannot see the index, so it cannot invert it or prove
//   the stores write each element once
//
// A view over data laid out along a space-filling curve, whose index
// function lives in a library.
#include "dpgen/annotate.hpp"

int curve_index(int i, int j, int order); // defined elsewhere

struct CurveView {
  double* p;
  int order;
  double& operator()(int i, int j) const { return p[curve_index(i, j, order)]; }
};

DPGEN_KERNEL void curve_smooth(DPGEN_IN const double* u, DPGEN_OUT CurveView out, int n) {
  for (int j = 1; j < n - 1; ++j)
    for (int i = 1; i < n - 1; ++i)
      out(i, j) =
          0.25 * (u[j * n + i - 1] + u[j * n + i + 1] + u[(j - 1) * n + i] + u[(j + 1) * n + i]);
}
