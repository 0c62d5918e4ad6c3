#include "corpus_check.hpp"

#include "athena_donor_cell.cpp"
#include "athena_donor_cell_adjoint.hpp"
#if CORPUS_TANGENT
#include "athena_donor_cell_tangent.hpp"
#endif

using namespace corpus;

TEST_CASE("modern: DonorCellX1") {
  // a mesh block of nx1 = 8 cells with 2 ghosts each side, 3 x 2 in x2, x3
  const int nx1 = 8, nx2 = 3, nx3 = 2;
  for (auto [il, iu] : {std::pair{2, 2}, {1, 6}, {0, 6}}) {
    const int k = 1, j = 2;
    Problem<double> p;
    p.in_sizes = {size_t(NHYDRO * nx3 * nx2 * nx1)};
    p.out_sizes = {size_t(NHYDRO * nx1), size_t(NHYDRO * nx1)};
    p.linear = true;
    p.forward = [&](auto in, auto out) {
      const AthenaArray<Real> w(mut(in[0]), NHYDRO, nx3, nx2, nx1);
      AthenaArray<Real> wl(out[0], NHYDRO, nx1), wr(out[1], NHYDRO, nx1);
      DonorCellX1(k, j, il, iu, w, wl, wr);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      const AthenaArray<Real> w(mut(in[0]), NHYDRO, nx3, nx2, nx1);
      AthenaArray<Real> w_adj(adj[0], NHYDRO, nx3, nx2, nx1);
      AthenaArray<Real> wl_adj(mut(seed[0]), NHYDRO, nx1), wr_adj(mut(seed[1]), NHYDRO, nx1);
      DonorCellX1_adjoint(k, j, il, iu, w, w_adj, wl_adj, wr_adj);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      const AthenaArray<Real> w(mut(in[0]), NHYDRO, nx3, nx2, nx1);
      AthenaArray<Real> w_dot(mut(d[0]), NHYDRO, nx3, nx2, nx1);
      AthenaArray<Real> wl(out[0], NHYDRO, nx1), wr(out[1], NHYDRO, nx1);
      AthenaArray<Real> wl_dot(dout[0], NHYDRO, nx1), wr_dot(dout[1], NHYDRO, nx1);
      DonorCellX1_tangent(k, j, il, iu, w, w_dot, wl, wl_dot, wr, wr_dot);
    };
#endif
    check_adjoint(p);
  }
}
