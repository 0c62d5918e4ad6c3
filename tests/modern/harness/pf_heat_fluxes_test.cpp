#include "corpus_check.hpp"

#include "pf_heat_fluxes.cpp"
#include "pf_heat_fluxes_adjoint.hpp"
#if CORPUS_TANGENT
#include "pf_heat_fluxes_tangent.hpp"
#endif

using namespace corpus;

TEST_CASE("modern: advance_box") {
  for (auto b : {box3(0, 0, 0, 0, 0, 0), box3(-1, 2, 0, 4, 5, 0)}) {
    const amrex::Box bx = b;
    const amrex::Box gbx = amrex::grow(amrex::grow(b, 0, 1), 1, 1);
    const amrex::Box xbx = amrex::surroundingNodes(bx, 0), ybx = amrex::surroundingNodes(bx, 1);
    Problem<double> p;
    p.in_sizes = {npts(gbx)};
    p.out_sizes = {npts(xbx), npts(ybx), npts(bx)};
    p.forward = [&](auto in, auto out) {
      advance_box(bx, a4(in[0], gbx), a4(out[0], xbx), a4(out[1], ybx), a4(out[2], bx), 0.1, 1.2,
                  0.8);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      advance_box_adjoint(bx, a4(in[0], gbx), a4(adj[0], gbx), a4(seed[0], xbx), a4(seed[1], ybx),
                          a4(seed[2], bx), 0.1, 1.2, 0.8);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      advance_box_tangent(bx, a4(in[0], gbx), a4(d[0], gbx), a4(out[0], xbx), a4(dout[0], xbx),
                          a4(out[1], ybx), a4(dout[1], ybx), a4(out[2], bx), a4(dout[2], bx), 0.1,
                          1.2, 0.8);
    };
#endif
    check_adjoint(p);
  }
}
