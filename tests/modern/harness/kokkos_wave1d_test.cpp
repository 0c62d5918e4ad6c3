#include "corpus_check.hpp"

#include "kokkos_wave1d.cpp"
#include "kokkos_wave1d_adjoint.hpp"
#if CORPUS_TANGENT
#include "kokkos_wave1d_tangent.hpp"
#endif

using namespace corpus;

TEST_CASE("modern: wave1d_step") {
  for (int n : {1, 2, 3, 17}) {
    Problem<double> p;
    p.in_sizes = {size_t(n), size_t(n)};
    p.out_sizes = {size_t(n)};
    p.linear = true;
    p.forward = [&](auto in, auto out) {
      wave1d_step(view_type(mut(in[0]), n), view_type(mut(in[1]), n), view_type(out[0], n), 0.3);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      wave1d_step_adjoint(view_type(mut(in[0]), n), view_type(adj[0], n), view_type(mut(in[1]), n),
                          view_type(adj[1], n), view_type(mut(seed[0]), n), 0.3);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      wave1d_step_tangent(view_type(mut(in[0]), n), view_type(mut(d[0]), n),
                          view_type(mut(in[1]), n), view_type(mut(d[1]), n), view_type(out[0], n),
                          view_type(dout[0], n), 0.3);
    };
#endif
    check_adjoint(p);
  }
}
