#include "corpus_check.hpp"

#include "array4_upwind.cpp"
#include "array4_upwind_adjoint.hpp"
#if CORPUS_TANGENT
#include "array4_upwind_tangent.hpp"
#endif

using namespace corpus;

TEST_CASE("modern: advect_upwind") {
  for (auto b : {box3(0, 0, 0, 0, 0, 0), box3(-2, 1, 0, 3, 5, 0)}) {
    const amrex::Box bx = b;
    const amrex::Box gbx = amrex::grow(amrex::grow(b, 0, 1), 1, 1); // ghosts in x and y
    const amrex::Box xbx = amrex::surroundingNodes(bx, 0), ybx = amrex::surroundingNodes(bx, 1);
    Problem<double> p;
    p.in_sizes = {npts(gbx), npts(xbx), npts(ybx)};
    p.out_sizes = {npts(bx)};
    p.forward = [&](auto in, auto out) {
      advect_upwind(bx, a4(in[0], gbx), a4(in[1], xbx), a4(in[2], ybx), a4(out[0], bx), 0.2, 0.3);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      advect_upwind_adjoint(bx, a4(in[0], gbx), a4(adj[0], gbx), a4(in[1], xbx), a4(adj[1], xbx),
                            a4(in[2], ybx), a4(adj[2], ybx), a4(seed[0], bx), 0.2, 0.3);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      advect_upwind_tangent(bx, a4(in[0], gbx), a4(d[0], gbx), a4(in[1], xbx), a4(d[1], xbx),
                            a4(in[2], ybx), a4(d[2], ybx), a4(out[0], bx), a4(dout[0], bx), 0.2,
                            0.3);
    };
#endif
    check_adjoint(p);
  }
}
