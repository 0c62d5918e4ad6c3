#include "corpus_check.hpp"

#include "array4_heat.cpp"
#include "array4_heat_adjoint.hpp"
#if CORPUS_TANGENT
#include "array4_heat_tangent.hpp"
#endif

using namespace corpus;

TEST_CASE("modern: heat_update") {
  // boxes not starting at 0, as AMReX boxes are
  for (auto b : {box3(0, 0, 0, 0, 0, 0), box3(2, -1, 3, 5, 1, 4), box3(-3, 0, 0, 3, 4, 2)}) {
    const amrex::Box bx = b, gbx = amrex::grow(b, 1);
    Problem<double> p;
    p.in_sizes = {npts(gbx)};
    p.out_sizes = {npts(bx)};
    p.linear = true;
    p.forward = [&](auto in, auto out) {
      heat_update(bx, a4(in[0], gbx), a4(out[0], bx), 0.1, 1.0, 1.5, 2.0);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      heat_update_adjoint(bx, a4(in[0], gbx), a4(adj[0], gbx), a4(seed[0], bx), 0.1, 1.0, 1.5, 2.0);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      heat_update_tangent(bx, a4(in[0], gbx), a4(d[0], gbx), a4(out[0], bx), a4(dout[0], bx), 0.1,
                          1.0, 1.5, 2.0);
    };
#endif
    check_adjoint(p);
  }
}
