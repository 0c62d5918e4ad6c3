#include "corpus_check.hpp"

#include "member_kokkos.cpp"
#include "member_kokkos_adjoint.hpp"
#if CORPUS_TANGENT
#include "member_kokkos_tangent.hpp"
#endif

using namespace corpus;
using V2 = Kokkos::View<double**>;

TEST_CASE("modern: UpwindAdvection::advance") {
  for (auto [nx, ny] : {std::pair{1, 1}, {2, 2}, {5, 4}}) {
    const size_t N = size_t(nx) * size_t(ny);
    auto v = [&](const double* q) { return V2(mut(q), nx, ny); };
    auto make = [&](const double* q, const double* s, double* qn) {
      UpwindAdvection a;
      a.q = v(q);
      a.speed = v(s);
      a.q_new = V2(qn, nx, ny);
      a.cx = 0.3;
      a.cy = 0.2;
      return a;
    };
    Problem<double> p;
    p.in_sizes = {N, N};
    p.in_ranges = {{-1, 1}, {0.5, 1.5}};
    p.out_sizes = {N};
    p.forward = [&](auto in, auto out) { make(in[0], in[1], out[0]).advance(); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      const UpwindAdvection self = make(in[0], in[1], nullptr);
      V2 q_adj = v(adj[0]), speed_adj = v(adj[1]), q_new_adj = v(seed[0]);
      UpwindAdvection_advance_adjoint(self, q_adj, speed_adj, q_new_adj);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      const UpwindAdvection self = make(in[0], in[1], out[0]);
      V2 q_dot = v(d[0]), speed_dot = v(d[1]), q_new_dot = v(dout[0]);
      UpwindAdvection_advance_tangent(self, q_dot, speed_dot, q_new_dot);
    };
#endif
    check_adjoint(p);
  }
}
