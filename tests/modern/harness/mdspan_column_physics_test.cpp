#include "corpus_check.hpp"

#include "mdspan_column_physics.cpp"
#include "mdspan_column_physics_adjoint.hpp"
#if CORPUS_TANGENT
#include "mdspan_column_physics_tangent.hpp"
#endif

using namespace corpus;

TEST_CASE("modern: column_tendency") {
  for (auto [ncol, nlev] : {std::pair{1, 1}, {1, 3}, {4, 6}}) {
    const size_t N = size_t(ncol) * size_t(nlev);
    auto c = [&](const double* q) { return colview(mut(q), ncol, nlev); };
    Problem<double> p;
    p.in_sizes = {N, N};
    p.in_ranges = {{-1, 1}, {0.1, 1.0}};
    p.out_sizes = {N};
    p.forward = [&](auto in, auto out) {
      column_tendency(c(in[0]), c(in[1]), c(out[0]), 2.0, 0.1, 0.3);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      column_tendency_adjoint(c(in[0]), c(adj[0]), c(in[1]), c(adj[1]), c(seed[0]), 2.0, 0.1, 0.3);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      column_tendency_tangent(c(in[0]), c(d[0]), c(in[1]), c(d[1]), c(out[0]), c(dout[0]), 2.0, 0.1,
                              0.3);
    };
#endif
    check_adjoint(p);
  }
}
