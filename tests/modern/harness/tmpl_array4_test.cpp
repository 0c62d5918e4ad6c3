#include "corpus_check.hpp"

#include "tmpl_array4.cpp"
#include "tmpl_array4_adjoint.hpp"
#if CORPUS_TANGENT
#include "tmpl_array4_tangent.hpp"
#endif

#ifdef CORPUS_SELFCHECK
template <class T, class... A> void smooth_box_adjoint(A&&...) {}
template <class T, class... A> void smooth_box_tangent(A&&...) {}
#endif

using namespace corpus;

TEST_CASE("modern: smooth_box") {
  for (auto b : {box3(0, 0, 0, 0, 0, 0), box3(-2, 0, 1, 3, 2, 2)}) {
    const amrex::Box bx = b, gbx = amrex::grow(b, 0, 1);
    Problem<double> p;
    p.in_sizes = {npts(gbx)};
    p.out_sizes = {npts(bx)};
    p.forward = [&](auto in, auto out) {
      smooth_box<double>(bx, a4(in[0], gbx), a4(out[0], bx), 0.4);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      smooth_box_adjoint<double>(bx, a4(in[0], gbx), a4(adj[0], gbx), a4(seed[0], bx), 0.4);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      smooth_box_tangent<double>(bx, a4(in[0], gbx), a4(d[0], gbx), a4(out[0], bx), a4(dout[0], bx),
                                 0.4);
    };
#endif
    check_adjoint(p);
  }
}
