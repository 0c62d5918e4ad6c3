#include "support/adjoint_check.hpp"
#include <algorithm>
#include <stdexcept>
#include "dpgen/annotate.hpp"
#include "a14_unsigned_adjoint.hpp"
#include "a14_unsigned_tangent.hpp"

DPGEN_KERNEL void a14_unsigned(DPGEN_IN const double* a, DPGEN_OUT double* o, DPGEN_OUT double* p, std::size_t n);
TEST_CASE("adversary: a14_unsigned") {
  for (int n : {0, 1, 2, 3, 4, 7, 16}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n), size_t(n)};
    p.forward = [&](auto in, auto out) { a14_unsigned(in[0], out[0], out[1], size_t(n)); };
    p.adjoint = [&](auto in, auto adj, auto seed) { a14_unsigned_adjoint(in[0], adj[0], seed[0], seed[1], size_t(n)); };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) { a14_unsigned_tangent(in[0], dir[0], out[0], outd[0], out[1], outd[1], size_t(n)); };
    dpgen_test::check_adjoint(p);
  }
}
