#include "corpus_check.hpp"

#include "pf_laplacian.cpp"
#include "pf_laplacian_adjoint.hpp"
#if CORPUS_TANGENT
#include "pf_laplacian_tangent.hpp"
#endif

using namespace corpus;

TEST_CASE("modern: laplacian") {
  for (auto b : {box3(0, 0, 0, 0, 0, 0), box3(1, 2, 3, 4, 4, 5)}) {
    const amrex::Box bx = b, gbx = amrex::grow(b, 1);
    Problem<double> p;
    p.in_sizes = {npts(gbx)};
    p.out_sizes = {npts(bx)};
    p.linear = true;
    p.forward = [&](auto in, auto out) { laplacian(bx, a4(in[0], gbx), a4(out[0], bx), 2.5); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      laplacian_adjoint(bx, a4(in[0], gbx), a4(adj[0], gbx), a4(seed[0], bx), 2.5);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      laplacian_tangent(bx, a4(in[0], gbx), a4(d[0], gbx), a4(out[0], bx), a4(dout[0], bx), 2.5);
    };
#endif
    check_adjoint(p);
  }
}
