// jacobi2d_array2d (tests/styles/): `double a[][JN]` parameters; linear.
// Assumed adjoint signature: the 2D array type kept, i.e.
//   jacobi2d_array2d_adjoint(const double a[][8], double a_adj[][8],
//                            const double f[][8], double f_adj[][8],
//                            const double b_adj[][8], int ny, double h2)
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "jacobi2d_array2d_adjoint.hpp"
#include "jacobi2d_array2d_tangent.hpp"

constexpr int kJN = 8;
DPGEN_KERNEL void jacobi2d_array2d(DPGEN_IN const double a[][kJN], DPGEN_IN const double f[][kJN],
                                   DPGEN_OUT double b[][kJN], int ny, double h2);

namespace {
using Row = double[kJN];
const Row* cr(const double* p) { return reinterpret_cast<const Row*>(p); }
Row* mr(double* p) { return reinterpret_cast<Row*>(p); }
} // namespace

TEST_CASE("styles: jacobi2d_array2d") {
  for (int ny : {1, 2, 3, 4, 9}) {
    CAPTURE(ny);
    size_t n = size_t(ny * kJN);
    dpgen_test::Problem<double> p;
    p.in_sizes = {n, n};
    p.out_sizes = {n};
    p.linear = true;
    p.forward = [&](auto in, auto out) {
      jacobi2d_array2d(cr(in[0]), cr(in[1]), mr(out[0]), ny, 0.05);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      jacobi2d_array2d_adjoint(cr(in[0]), mr(adj[0]), cr(in[1]), mr(adj[1]), cr(seed[0]), ny,
                               0.05);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      jacobi2d_array2d_tangent(cr(in[0]), cr(dir[0]), cr(in[1]), cr(dir[1]), mr(out[0]), mr(outd[0]), ny,
                               0.05);
    };
    dpgen_test::check_adjoint(p);
  }
}
