#include "support/adjoint_check.hpp"
#include "styles/styles_support.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#define IDX(i, j) ((j) * nx + (i))
#include "r5_ip_2d_fluxes_omp_adjoint.hpp"
#include "r5_ip_2d_fluxes_omp_tangent.hpp"

DPGEN_KERNEL void r5_ip_2d_fluxes_omp(DPGEN_INOUT double* q, DPGEN_OUT double* fx, DPGEN_OUT double* fy, int nx, int ny, double c);
TEST_CASE("adversary: r5_ip_2d_fluxes_omp") {
  for (auto [n, m] : {std::pair{0, 0}, {1, 1}, {1, 3}, {3, 1}, {2, 2}, {4, 3}, {5, 6}}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n*m)};
    p.out_sizes = {size_t(n*m), size_t(n*m), size_t(n*m)};
    p.forward = [&](auto in, auto out) { std::copy(in[0], in[0] + size_t(n*m), out[0]); r5_ip_2d_fluxes_omp(out[0], out[1], out[2], n, m, 0.2); };
    p.adjoint = [&](auto in, auto adj, auto seed) { std::vector<double> t0(seed[0], seed[0] + size_t(n*m)); r5_ip_2d_fluxes_omp_adjoint(in[0], t0.data(), seed[1], seed[2], n, m, 0.2); for (size_t z = 0; z < t0.size(); ++z) adj[0][z] += t0[z]; };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { std::copy(in[0], in[0] + size_t(n*m), out[0]); std::copy(dir[0], dir[0] + size_t(n*m), outd[0]); r5_ip_2d_fluxes_omp_tangent(out[0], outd[0], out[1], outd[1], out[2], outd[2], n, m, 0.2); };
    dpgen_test::check_adjoint(p);
  }
}
