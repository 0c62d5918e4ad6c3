#include "corpus_check.hpp"

#include "return_kinetic_energy.cpp"
#include "return_kinetic_energy_adjoint.hpp"
#if CORPUS_TANGENT
#include "return_kinetic_energy_tangent.hpp"
#endif

using namespace corpus;

TEST_CASE("modern: kinetic_energy") {
  for (auto [ny, nx] : {std::pair{1, 1}, {3, 5}}) {
    const size_t N = size_t(nx) * size_t(ny);
    auto m = [&](const double* q) { return MD2<>(mut(q), ny, nx); };
    Problem<double> p;
    p.in_sizes = {N, N, N};
    p.in_ranges = {{0.5, 1.5}};
    p.out_sizes = {1};
    p.forward = [&](auto in, auto out) {
      out[0][0] = kinetic_energy(m(in[0]), m(in[1]), m(in[2]), 0.3);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      kinetic_energy_adjoint(m(in[0]), m(adj[0]), m(in[1]), m(adj[1]), m(in[2]), m(adj[2]), 0.3,
                             seed[0][0]);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      out[0][0] = kinetic_energy_tangent(m(in[0]), m(d[0]), m(in[1]), m(d[1]), m(in[2]), m(d[2]),
                                         0.3, dout[0][0]);
    };
#endif
    check_adjoint(p);
  }
}
