#include "corpus_check.hpp"

#include "functor_amrex.cpp"
#include "functor_amrex_adjoint.hpp"
#if CORPUS_TANGENT
#include "functor_amrex_tangent.hpp"
#endif

using namespace corpus;

TEST_CASE("modern: grad_magnitude") {
  for (auto b : {box3(0, 0, 0, 0, 0, 0), box3(1, -2, 0, 5, 1, 1)}) {
    const amrex::Box bx = b, gbx = amrex::grow(amrex::grow(b, 0, 1), 1, 1);
    Problem<double> p;
    p.in_sizes = {npts(gbx)};
    p.out_sizes = {npts(bx)};
    p.forward = [&](auto in, auto out) { grad_magnitude(bx, a4(in[0], gbx), a4(out[0], bx), 2.0); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      grad_magnitude_adjoint(bx, a4(in[0], gbx), a4(adj[0], gbx), a4(seed[0], bx), 2.0);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      grad_magnitude_tangent(bx, a4(in[0], gbx), a4(d[0], gbx), a4(out[0], bx), a4(dout[0], bx),
                             2.0);
    };
#endif
    check_adjoint(p);
  }
}
