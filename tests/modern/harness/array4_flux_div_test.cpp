#include "corpus_check.hpp"

#include "array4_flux_div.cpp"
#include "array4_flux_div_adjoint.hpp"
#if CORPUS_TANGENT
#include "array4_flux_div_tangent.hpp"
#endif

using namespace corpus;

TEST_CASE("modern: flux_divergence") {
  for (int ncomp : {1, 3}) {
    const amrex::Box bx = box3(1, 0, -1, 4, 2, 1);
    const amrex::Box xbx = amrex::surroundingNodes(bx, 0), ybx = amrex::surroundingNodes(bx, 1),
                     zbx = amrex::surroundingNodes(bx, 2);
    std::vector<double> vol(npts(bx));
    for (size_t c = 0; c < vol.size(); ++c)
      vol[c] = 0.5 + 0.01 * double(c % 7);
    Problem<double> p;
    p.in_sizes = {npts(xbx, ncomp), npts(ybx, ncomp), npts(zbx, ncomp)};
    p.out_sizes = {npts(bx, ncomp)};
    p.linear = true;
    p.forward = [&](auto in, auto out) {
      flux_divergence(bx, ncomp, a4(in[0], xbx, ncomp), a4(in[1], ybx, ncomp),
                      a4(in[2], zbx, ncomp), a4(vol.data(), bx), a4(out[0], bx, ncomp), 0.3);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      flux_divergence_adjoint(bx, ncomp, a4(in[0], xbx, ncomp), a4(adj[0], xbx, ncomp),
                              a4(in[1], ybx, ncomp), a4(adj[1], ybx, ncomp), a4(in[2], zbx, ncomp),
                              a4(adj[2], zbx, ncomp), a4(vol.data(), bx), a4(seed[0], bx, ncomp),
                              0.3);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      flux_divergence_tangent(bx, ncomp, a4(in[0], xbx, ncomp), a4(d[0], xbx, ncomp),
                              a4(in[1], ybx, ncomp), a4(d[1], ybx, ncomp), a4(in[2], zbx, ncomp),
                              a4(d[2], zbx, ncomp), a4(vol.data(), bx), a4(out[0], bx, ncomp),
                              a4(dout[0], bx, ncomp), 0.3);
    };
#endif
    check_adjoint(p);
  }
}
