// pdv_predict_branches, advect_dir_branches (tests/styles/): loop nests in
// exclusive arms of an `if` on a scalar parameter (issue 20, defect 4), each
// arm checked (adjoint, tangent).
#include "support/adjoint_check.hpp"

#include "advect_dir_branches_adjoint.hpp"
#include "advect_dir_branches_kernels.hpp"
#include "advect_dir_branches_tangent.hpp"
#include "dpgen/annotate.hpp"
#include "pdv_predict_branches_adjoint.hpp"
#include "pdv_predict_branches_kernels.hpp"
#include "pdv_predict_branches_tangent.hpp"

#include <tuple>

TEST_CASE("styles: pdv_predict_branches") {
  for (auto [n, predict] : {std::tuple{1, 0}, {6, 0}, {6, 1}, {17, 0}, {17, 3}}) {
    CAPTURE(n);
    CAPTURE(predict);
    size_t N = size_t(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {N, N};
    p.out_sizes = {N, N};
    p.forward = [&](auto in, auto out) {
      pdv_predict_branches(in[0], in[1], out[0], out[1], n, 0.3, predict);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      pdv_predict_branches_adjoint(in[0], adj[0], in[1], adj[1], seed[0], seed[1], n, 0.3,
                                   predict);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto dout) {
      pdv_predict_branches_tangent(in[0], dir[0], in[1], dir[1], out[0], dout[0], out[1],
                                   dout[1], n, 0.3, predict);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: advect_dir_branches") {
  for (auto [nx, ny, dir] : {std::tuple{3, 4, 1}, {3, 4, 2}, {5, 2, 1}, {5, 2, 2}, {4, 4, 7}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    CAPTURE(dir);
    size_t X = size_t(nx), Y = size_t(ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {X * Y};
    p.out_sizes = {X * Y, Y};
    p.forward = [&](auto in, auto out) { advect_dir_branches(in[0], out[0], out[1], nx, ny, dir); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      advect_dir_branches_adjoint(in[0], adj[0], seed[0], seed[1], nx, ny, dir);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      advect_dir_branches_tangent(in[0], d[0], out[0], dout[0], out[1], dout[1], nx, ny, dir);
    };
    dpgen_test::check_adjoint(p);
  }
}
