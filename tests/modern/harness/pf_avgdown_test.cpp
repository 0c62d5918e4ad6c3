#include "corpus_check.hpp"

#include "pf_avgdown.cpp"
#include "pf_avgdown_adjoint.hpp"
#if CORPUS_TANGENT
#include "pf_avgdown_tangent.hpp"
#endif

using namespace corpus;

TEST_CASE("modern: avgdown") {
  for (auto r : {amrex::IntVect(1, 1, 1), amrex::IntVect(2, 2, 2), amrex::IntVect(4, 2, 1),
                 amrex::IntVect(3, 1, 2)}) {
    const amrex::IntVect ratio = r;
    const amrex::Box cbx = box3(1, 0, 2, 3, 1, 3);
    const amrex::Box fbx = box3(1 * r[0], 0, 2 * r[2], 4 * r[0] - 1, 2 * r[1] - 1, 4 * r[2] - 1);
    Problem<double> p;
    p.in_sizes = {npts(fbx)};
    p.out_sizes = {npts(cbx)};
    p.linear = true;
    p.forward = [&](auto in, auto out) { avgdown(cbx, a4(in[0], fbx), a4(out[0], cbx), ratio); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      avgdown_adjoint(cbx, a4(in[0], fbx), a4(adj[0], fbx), a4(seed[0], cbx), ratio);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      avgdown_tangent(cbx, a4(in[0], fbx), a4(d[0], fbx), a4(out[0], cbx), a4(dout[0], cbx), ratio);
    };
#endif
    check_adjoint(p);
  }
}
