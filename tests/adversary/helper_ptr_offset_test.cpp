// helper_ptr_offset (tests/adversary/): see helper_ptr_offset.cpp; sizes n in {0, 1, 2, 3, 6}.
#include "adv.hpp"
#include "helper_ptr_offset_adjoint.hpp"
#include "helper_ptr_offset_tangent.hpp"
void helper_ptr_offset(const double*, double*, int n);
TEST_CASE("adversary: helper_ptr_offset") {
  for (int n : {0, 1, 2, 3, 6}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { helper_ptr_offset(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { helper_ptr_offset_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { helper_ptr_offset_tangent(in[0], dir[0], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      helper_ptr_offset_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
