#include "corpus_check.hpp"

#include "pf_mask.cpp"
#include "pf_mask_adjoint.hpp"
#if CORPUS_TANGENT
#include "pf_mask_tangent.hpp"
#endif

using namespace corpus;

TEST_CASE("modern: masked_smooth") {
  const amrex::Box bx = box3(0, 0, 0, 5, 4, 0);
  const amrex::Box gbx = amrex::grow(amrex::grow(bx, 0, 1), 1, 1);
  std::vector<int> mask(npts(bx));
  for (size_t c = 0; c < mask.size(); ++c)
    mask[c] = (c * 7 + 3) % 5 < 2;
  const amrex::Array4<int const> covered(mask.data(), amrex::lbound(bx), amrex::Dim3{6, 5, 1}, 1);
  Problem<double> p;
  p.in_sizes = {npts(gbx)};
  p.out_sizes = {npts(bx)};
  p.linear = true;
  p.forward = [&](auto in, auto out) {
    masked_smooth(bx, covered, a4(in[0], gbx), a4(out[0], bx), 0.6);
  };
  p.adjoint = [&](auto in, auto adj, auto seed) {
    masked_smooth_adjoint(bx, covered, a4(in[0], gbx), a4(adj[0], gbx), a4(seed[0], bx), 0.6);
  };
#if CORPUS_TANGENT
  p.tangent = [&](auto in, auto d, auto out, auto dout) {
    masked_smooth_tangent(bx, covered, a4(in[0], gbx), a4(d[0], gbx), a4(out[0], bx),
                          a4(dout[0], bx), 0.6);
  };
#endif
  check_adjoint(p);
}
