// gradient_vector (tests/styles/): std::vector parameters, size_t counter
// bounded by p.size(). Assumed adjoint signature:
//   gradient_vector_adjoint(const std::vector<double>& p, std::vector<double>& p_adj,
//                           const std::vector<double>& k, std::vector<double>& k_adj,
//                           const std::vector<double>& g_adj, double inv_h)
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "gradient_vector_adjoint.hpp"
#include "styles_support.hpp"

#include <vector>

DPGEN_KERNEL void gradient_vector(DPGEN_IN const std::vector<double>& p,
                                  DPGEN_IN const std::vector<double>& k,
                                  DPGEN_OUT std::vector<double>& g, double inv_h);

TEST_CASE("styles: gradient_vector") {
  for (int n : {0, 1, 2, 5, 17}) {
    CAPTURE(n);
    size_t N = size_t(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {N, N};
    p.out_sizes = {N};
    p.forward = [&](auto in, auto out) {
      std::vector<double> pv = styles::to_vec(in[0], N), kv = styles::to_vec(in[1], N),
                          g = styles::to_vec(out[0], N);
      gradient_vector(pv, kv, g, 4.0);
      styles::from_vec(g, out[0]);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      std::vector<double> pv = styles::to_vec(in[0], N), pa = styles::to_vec(adj[0], N),
                          kv = styles::to_vec(in[1], N), ka = styles::to_vec(adj[1], N),
                          ga = styles::to_vec(seed[0], N);
      gradient_vector_adjoint(pv, pa, kv, ka, ga, 4.0);
      styles::from_vec(pa, adj[0]);
      styles::from_vec(ka, adj[1]);
    };
    dpgen_test::check_adjoint(p);
  }
}
