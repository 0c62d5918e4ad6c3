#include "corpus_check.hpp"

#include "kokkos_shallow_water.cpp"
#include "kokkos_shallow_water_adjoint.hpp"
#if CORPUS_TANGENT
#include "kokkos_shallow_water_tangent.hpp"
#endif

using namespace corpus;
using V2 = Kokkos::View<double**>;

TEST_CASE("modern: swe_lax_friedrichs") {
  for (auto [nx, ny] : {std::pair{1, 1}, {3, 4}, {6, 5}}) {
    const size_t N = size_t(nx) * size_t(ny);
    auto v = [&](const double* q) { return V2(mut(q), nx, ny); };
    Problem<double> p;
    p.in_sizes = {N, N, N};
    p.in_ranges = {{1.0, 2.0}, {-0.5, 0.5}, {-0.5, 0.5}};
    p.out_sizes = {N, N, N};
    p.forward = [&](auto in, auto out) {
      swe_lax_friedrichs(v(in[0]), v(in[1]), v(in[2]), v(out[0]), v(out[1]), v(out[2]), 0.1, 0.2,
                         9.81);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      swe_lax_friedrichs_adjoint(v(in[0]), v(adj[0]), v(in[1]), v(adj[1]), v(in[2]), v(adj[2]),
                                 v(seed[0]), v(seed[1]), v(seed[2]), 0.1, 0.2, 9.81);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      swe_lax_friedrichs_tangent(v(in[0]), v(d[0]), v(in[1]), v(d[1]), v(in[2]), v(d[2]), v(out[0]),
                                 v(dout[0]), v(out[1]), v(dout[1]), v(out[2]), v(dout[2]), 0.1, 0.2,
                                 9.81);
    };
#endif
    check_adjoint(p);
  }
}
