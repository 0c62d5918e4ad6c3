#include "corpus_check.hpp"

#include "planes_miniweather.cpp"
#include "planes_miniweather_adjoint.hpp"
#if CORPUS_TANGENT
#include "planes_miniweather_tangent.hpp"
#endif

using namespace corpus;

TEST_CASE("modern: compute_tendencies_x") {
  for (auto [x, z] : {std::pair{1, 1}, {4, 3}}) {
    nx = x;
    nz = z;
    dx = 0.5;
    std::vector<double> hd(size_t(nz + 2 * hs)), ht(size_t(nz + 2 * hs));
    for (int k = 0; k < nz + 2 * hs; ++k) {
      hd[size_t(k)] = 1.0 + 0.1 * k;
      ht[size_t(k)] = 1.0 + 0.05 * k;
    }
    hy_dens_cell = hd.data();
    hy_dens_theta_cell = ht.data();
    Problem<double> p;
    p.in_sizes = {size_t(NUM_VARS * (nz + 2 * hs) * (nx + 2 * hs))};
    p.in_ranges = {{-0.1, 0.1}};
    p.out_sizes = {size_t(NUM_VARS * (nz + 1) * (nx + 1)), size_t(NUM_VARS * nz * nx)};
    p.forward = [&](auto in, auto out) { compute_tendencies_x(mut(in[0]), out[0], out[1], 0.2); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      compute_tendencies_x_adjoint(mut(in[0]), adj[0], seed[0], seed[1], 0.2);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      compute_tendencies_x_tangent(mut(in[0]), mut(d[0]), out[0], dout[0], out[1], dout[1], 0.2);
    };
#endif
    check_adjoint(p);
  }
}
