// prolong1d_size_t (tests/styles/): size_t counters and parameter, two loops
// writing the even and odd fine points; linear.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "prolong1d_size_t_adjoint.hpp"
#include "prolong1d_size_t_tangent.hpp"

#include <cstddef>

DPGEN_KERNEL void prolong1d_size_t(DPGEN_IN const double* coarse, DPGEN_OUT double* fine,
                                   std::size_t nc);

TEST_CASE("styles: prolong1d_size_t") {
  for (size_t nc : {1, 2, 3, 8}) {
    CAPTURE(nc);
    dpgen_test::Problem<double> p;
    p.in_sizes = {nc};
    p.out_sizes = {2 * nc - 1};
    p.linear = true;
    p.forward = [&](auto in, auto out) { prolong1d_size_t(in[0], out[0], nc); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      prolong1d_size_t_adjoint(in[0], adj[0], seed[0], nc);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      prolong1d_size_t_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], nc);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      prolong1d_size_t_tangent(in[0], dir[0], out[0], outd[0], nc);
    };
    dpgen_test::check_adjoint(p);
  }
}
