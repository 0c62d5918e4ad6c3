// varcoef_laplace2d_rowarray (tests/styles/): `double (*a)[NX]` parameters.
// Assumed adjoint signature: same pointer-to-row types, e.g.
//   (const double (*k)[6], double (*k_adj)[6], const double (*u)[6],
//    double (*u_adj)[6], const double (*lu_adj)[6], int ny, double inv_h2)
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "varcoef_laplace2d_rowarray_adjoint.hpp"
#include "varcoef_laplace2d_rowarray_tangent.hpp"

constexpr int kNX = 6;
DPGEN_KERNEL void varcoef_laplace2d_rowarray(DPGEN_IN const double (*k)[kNX],
                                             DPGEN_IN const double (*u)[kNX],
                                             DPGEN_OUT double (*lu)[kNX], int ny, double inv_h2);

namespace {
using Row = double[kNX];
const Row* cr(const double* p) { return reinterpret_cast<const Row*>(p); }
Row* mr(double* p) { return reinterpret_cast<Row*>(p); }
} // namespace

TEST_CASE("styles: varcoef_laplace2d_rowarray") {
  for (int ny : {1, 2, 3, 5, 8}) {
    CAPTURE(ny);
    size_t n = size_t(ny * kNX);
    dpgen_test::Problem<double> p;
    p.in_sizes = {n, n};
    p.out_sizes = {n};
    p.in_ranges = {{0.5, 2.0}, {-1.0, 1.0}};
    p.forward = [&](auto in, auto out) {
      varcoef_laplace2d_rowarray(cr(in[0]), cr(in[1]), mr(out[0]), ny, 2.0);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      varcoef_laplace2d_rowarray_adjoint(cr(in[0]), mr(adj[0]), cr(in[1]), mr(adj[1]),
                                         cr(seed[0]), ny, 2.0);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      varcoef_laplace2d_rowarray_tangent(cr(in[0]), cr(dir[0]), cr(in[1]), cr(dir[1]), mr(out[0]),
                                         mr(outd[0]), ny, 2.0);
    };
    dpgen_test::check_adjoint(p);
  }
}
