// heat_vector (tests/styles/): `const std::vector<double>&` in,
// `std::vector<double>&` out. Assumed adjoint signature:
//   heat_vector_adjoint(const std::vector<double>& u, std::vector<double>& u_adj,
//                       const std::vector<double>& u_new_adj, double r)
// The checker's flat arrays are copied into vectors and back (no guard cells
// on the vector side).
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "heat_vector_adjoint.hpp"
#include "styles_support.hpp"

#include <vector>

DPGEN_KERNEL void heat_vector(DPGEN_IN const std::vector<double>& u,
                              DPGEN_OUT std::vector<double>& u_new, double r);

TEST_CASE("styles: heat_vector") {
  for (int n : {0, 1, 2, 3, 14}) {
    CAPTURE(n);
    size_t N = size_t(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {N};
    p.out_sizes = {N};
    p.linear = true;
    p.forward = [&](auto in, auto out) {
      std::vector<double> u = styles::to_vec(in[0], N), un = styles::to_vec(out[0], N);
      heat_vector(u, un, 0.3);
      styles::from_vec(un, out[0]);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      std::vector<double> u = styles::to_vec(in[0], N), ua = styles::to_vec(adj[0], N),
                          sa = styles::to_vec(seed[0], N);
      heat_vector_adjoint(u, ua, sa, 0.3);
      REQUIRE(ua.size() == N);
      styles::from_vec(ua, adj[0]);
    };
    dpgen_test::check_adjoint(p);
  }
}
