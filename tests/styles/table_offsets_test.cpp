// table_offsets (tests/styles/): adjoint and tangent of kernels whose
// offsets come from constant tables indexed by an unrolled counter.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "include/user_views.hpp"
#include "table_offsets_adjoint.hpp"
#include "table_offsets_kernels.hpp"
#include "table_offsets_tangent.hpp"

namespace {

// A kernel of one Pops3D view in (9 planes of ny x nx) and one out, given
// as its three entry points over the views: adjoint against finite
// differences and the dot-product test, and the tangent.
template <typename F, typename A, typename T>
void check_pops(int nx, int ny, F forward, A adjoint, T tangent) {
  const size_t n = 9 * size_t(nx) * size_t(ny);
  auto cv = [&](const double* p) { return grid::Pops3D<const double>{p, 9, ny, nx}; };
  auto mv = [&](double* p) { return grid::Pops3D<double>{p, 9, ny, nx}; };
  dpgen_test::Problem<double> p;
  p.in_sizes = {n};
  p.out_sizes = {n};
  p.forward = [&](auto in, auto out) { forward(cv(in[0]), mv(out[0])); };
  p.adjoint = [&](auto in, auto adj, auto seed) {
    adjoint(cv(in[0]), mv(adj[0]), mv(const_cast<double*>(seed[0])));
  };
  p.tangent = [&](auto in, auto dir, auto out, auto outd) {
    tangent(cv(in[0]), cv(dir[0]), mv(out[0]), mv(outd[0]));
  };
  dpgen_test::check_adjoint(p);
}

} // namespace

TEST_CASE("styles: table_stream, table_relax") {
  for (auto [nx, ny] : {std::pair{1, 1}, std::pair{2, 3}, std::pair{5, 4}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    check_pops(
        nx, ny, [](auto f, auto g) { table_stream(f, g); },
        [](auto f, auto f_adj, auto g_adj) { table_stream_adjoint(f, f_adj, g_adj); },
        [](auto f, auto f_dot, auto g, auto g_dot) { table_stream_tangent(f, f_dot, g, g_dot); });
    check_pops(
        nx, ny, [](auto f, auto g) { table_relax(f, g, 0.7); },
        [](auto f, auto f_adj, auto g_adj) { table_relax_adjoint(f, f_adj, g_adj, 0.7); },
        [](auto f, auto f_dot, auto g, auto g_dot) {
          table_relax_tangent(f, f_dot, g, g_dot, 0.7);
        });
  }
}

TEST_CASE("styles: table_shift1d") {
  for (int n : {1, 2, 6}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {3 * size_t(n)};
    p.forward = [&](auto in, auto out) { table_shift1d(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      table_shift1d_adjoint(in[0], adj[0], seed[0], n);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      table_shift1d_tangent(in[0], d[0], out[0], dout[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: planes_first_last") {
  for (auto [nx, ny] : {std::pair{1, 1}, std::pair{3, 2}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    check_pops(
        nx, ny, [](auto f, auto g) { planes_first_last(f, g); },
        [](auto f, auto f_adj, auto g_adj) { planes_first_last_adjoint(f, f_adj, g_adj); },
        [](auto f, auto f_dot, auto g, auto g_dot) {
          planes_first_last_tangent(f, f_dot, g, g_dot);
        });
  }
}
