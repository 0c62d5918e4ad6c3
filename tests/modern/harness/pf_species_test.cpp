#include "corpus_check.hpp"

#include "pf_species.cpp"
#include "pf_species_adjoint.hpp"
#if CORPUS_TANGENT
#include "pf_species_tangent.hpp"
#endif

using namespace corpus;

TEST_CASE("modern: species_diffusion") {
  for (int nspec : {1, 3}) {
    const amrex::Box bx = box3(0, 1, 0, 3, 4, 0);
    const amrex::Box gbx = amrex::grow(amrex::grow(bx, 0, 1), 1, 1);
    Problem<double> p;
    p.in_sizes = {npts(gbx, nspec), npts(gbx, nspec)};
    p.in_ranges = {{-1, 1}, {0.5, 1.5}};
    p.out_sizes = {npts(bx, nspec)};
    p.forward = [&](auto in, auto out) {
      species_diffusion(bx, nspec, a4(in[0], gbx, nspec), a4(in[1], gbx, nspec),
                        a4(out[0], bx, nspec), 4.0);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      species_diffusion_adjoint(bx, nspec, a4(in[0], gbx, nspec), a4(adj[0], gbx, nspec),
                                a4(in[1], gbx, nspec), a4(adj[1], gbx, nspec),
                                a4(seed[0], bx, nspec), 4.0);
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      species_diffusion_tangent(bx, nspec, a4(in[0], gbx, nspec), a4(d[0], gbx, nspec),
                                a4(in[1], gbx, nspec), a4(d[1], gbx, nspec), a4(out[0], bx, nspec),
                                a4(dout[0], bx, nspec), 4.0);
    };
#endif
    check_adjoint(p);
  }
}
