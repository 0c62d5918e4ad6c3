#include "corpus_check.hpp"

#include "pf_prolong.cpp"
#include "pf_prolong_adjoint.hpp"
#if CORPUS_TANGENT
#include "pf_prolong_tangent.hpp"
#endif

using namespace corpus;

TEST_CASE("modern: prolong_linear") {
  for (int r : {1, 2, 3, 4}) {
    const int ratio = r;
    const amrex::Box cbx = box3(1, 0, 0, 3, 2, 0);
    const amrex::Box gcbx = amrex::grow(amrex::grow(cbx, 0, 1), 1, 1);
    const amrex::Box fbx = box3(r, 0, 0, 4 * r - 1, 3 * r - 1, 0);
    Problem<double> p;
    p.in_sizes = {npts(gcbx)};
    p.out_sizes = {npts(fbx)};
    p.linear = true;
    p.forward = [&](auto in, auto out) {
      prolong_linear(cbx, a4(in[0], gcbx), a4(out[0], fbx), ratio);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      prolong_linear_adjoint(cbx, a4(in[0], gcbx), a4(adj[0], gcbx), a4(seed[0], fbx), ratio);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      prolong_linear_tangent(cbx, a4(in[0], gcbx), a4(d[0], gcbx), a4(out[0], fbx),
                             a4(dout[0], fbx), ratio);
    };
#endif
    check_adjoint(p);
  }
}
