#include "corpus_check.hpp"

#include "planes_tendencies_params.cpp"
#include "planes_tendencies_params_adjoint.hpp"
#if CORPUS_TANGENT
#include "planes_tendencies_params_tangent.hpp"
#endif

using namespace corpus;

TEST_CASE("modern: tendencies_x") {
  for (auto [nx, nz] : {std::pair{1, 1}, {4, 3}}) {
    const int hs = 2;
    std::vector<double> hd(static_cast<size_t>(nz + 2 * hs)), ht(static_cast<size_t>(nz + 2 * hs));
    for (int k = 0; k < nz + 2 * hs; ++k) {
      hd[size_t(k)] = 1.0 + 0.1 * k;
      ht[size_t(k)] = 1.0 + 0.05 * k;
    }
    Problem<double> p;
    p.in_sizes = {size_t(4 * (nz + 2 * hs) * (nx + 2 * hs))};
    p.in_ranges = {{-0.1, 0.1}};
    p.out_sizes = {size_t(4 * (nz + 1) * (nx + 1)), size_t(4 * nz * nx)};
    p.forward = [&](auto in, auto out) {
      tendencies_x(in[0], out[0], out[1], hd.data(), ht.data(), nx, nz, 0.5, 0.2);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      tendencies_x_adjoint(in[0], adj[0], seed[0], seed[1], hd.data(), ht.data(), nx, nz, 0.5, 0.2);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      tendencies_x_tangent(in[0], d[0], out[0], dout[0], out[1], dout[1], hd.data(), ht.data(), nx,
                           nz, 0.5, 0.2);
    };
#endif
    check_adjoint(p);
  }
}
