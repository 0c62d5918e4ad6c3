// std_array_table (tests/styles/): std::array coefficient tables and buffers.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "std_array_table_adjoint.hpp"
#include "std_array_table_kernels.hpp"
#include "std_array_table_tangent.hpp"

TEST_CASE("styles: std_array_table") {
  for (int n : {1, 4, 5, 19}) {
    CAPTURE(n);
    size_t N = size_t(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {N};
    p.out_sizes = {N};
    p.linear = true;
    p.forward = [&](auto in, auto out) { fd4_std_array(in[0], out[0], n, 2.0); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      fd4_std_array_adjoint(in[0], adj[0], seed[0], n, 2.0);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      fd4_std_array_tangent(in[0], d[0], out[0], dout[0], n, 2.0);
    };
    dpgen_test::check_adjoint(p);

    dpgen_test::Problem<double> q;
    q.in_sizes = {N};
    q.out_sizes = {N};
    q.forward = [&](auto in, auto out) { limiter_std_array(in[0], out[0], n); };
    q.adjoint = [&](auto in, auto adj, auto seed) {
      limiter_std_array_adjoint(in[0], adj[0], seed[0], n);
    };
    q.tangent = [&](auto in, auto d, auto out, auto dout) {
      limiter_std_array_tangent(in[0], d[0], out[0], dout[0], n);
    };
    dpgen_test::check_adjoint(q);
  }
}
