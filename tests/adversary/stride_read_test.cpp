// stride_read (tests/adversary/): see stride_read.cpp; sizes n in {0, 1, 2, 5}.
#include "adv.hpp"
#include "stride_read_adjoint.hpp"
#include "stride_read_tangent.hpp"
void stride_read(const double*, double*, int n);
TEST_CASE("adversary: stride_read") {
  for (int n : {0, 1, 2, 5}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(3 * n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { stride_read(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { stride_read_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { stride_read_tangent(in[0], dir[0], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      stride_read_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
