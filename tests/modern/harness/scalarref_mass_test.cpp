#include "corpus_check.hpp"

#include "scalarref_mass.cpp"
#include "scalarref_mass_adjoint.hpp"
#if CORPUS_TANGENT
#include "scalarref_mass_tangent.hpp"
#endif

using namespace corpus;

TEST_CASE("modern: total_mass") {
  for (auto [nx, ny] : {std::pair{1, 1}, {4, 3}}) {
    const double dx = 0.5, dy = 0.25;
    Problem<double> p;
    p.in_sizes = {size_t(nx * ny)};
    p.out_sizes = {1};
    p.linear = true;
    p.forward = [&](auto in, auto out) { total_mass(in[0], nx, ny, dx, dy, out[0][0]); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      total_mass_adjoint(in[0], adj[0], nx, ny, dx, dy, seed[0][0]);
    };
#if CORPUS_TANGENT
    // tangent (assumed): the output by reference, then its direction by reference
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      total_mass_tangent(in[0], d[0], nx, ny, dx, dy, out[0][0], dout[0][0]);
    };
#endif
    check_adjoint(p);
  }
}
