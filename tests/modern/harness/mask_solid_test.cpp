#include "corpus_check.hpp"

#include "mask_solid.cpp"
#include "mask_solid_adjoint.hpp"
#if CORPUS_TANGENT
#include "mask_solid_tangent.hpp"
#endif

#include <memory>

using namespace corpus;

TEST_CASE("modern: ib_diffuse") {
  for (auto [nx, ny] : {std::pair{1, 1}, {3, 3}, {7, 6}}) {
    const size_t N = size_t(nx * ny);
    std::unique_ptr<bool[]> solid(new bool[N]);
    for (size_t c = 0; c < N; ++c)
      solid[c] = (c * 5 + 1) % 7 < 2;
    Problem<double> p;
    p.in_sizes = {N};
    p.out_sizes = {N};
    p.linear = true;
    p.forward = [&](auto in, auto out) { ib_diffuse(in[0], solid.get(), out[0], nx, ny, 0.2); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      ib_diffuse_adjoint(in[0], adj[0], solid.get(), seed[0], nx, ny, 0.2);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      ib_diffuse_tangent(in[0], d[0], solid.get(), out[0], dout[0], nx, ny, 0.2);
    };
#endif
    check_adjoint(p);
  }
}

TEST_CASE("modern: wetdry_flux") {
  for (int n : {1, 3, 12}) {
    std::vector<std::uint8_t> wet(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i)
      wet[size_t(i)] = (i % 5) != 3;
    Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { wetdry_flux(in[0], wet.data(), out[0], n, 0.4); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      wetdry_flux_adjoint(in[0], adj[0], wet.data(), seed[0], n, 0.4);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      wetdry_flux_tangent(in[0], d[0], wet.data(), out[0], dout[0], n, 0.4);
    };
#endif
    check_adjoint(p);
  }
}
