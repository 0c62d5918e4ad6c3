// guard_continue_times (tests/adversary/): see guard_continue_times.cpp; sizes n in {0, 1, 2, 3, 8}.
#include "adv.hpp"
#include "guard_continue_times_adjoint.hpp"
#include "guard_continue_times_tangent.hpp"
void guard_continue_times(const double*, double*, int n);
TEST_CASE("adversary: guard_continue_times") {
  for (int n : {0, 1, 2, 3, 8}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(n)};
    p.out_sizes = {ADV_SZ(n)};
    p.forward = [&](auto in, auto out) { guard_continue_times(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { guard_continue_times_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { guard_continue_times_tangent(in[0], dir[0], out[0], od[0], n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      guard_continue_times_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
