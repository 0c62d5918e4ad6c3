// lambdas (tests/styles/): lambdas called in the kernel, inlined (issue 20).
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "lambdas_adjoint.hpp"
#include "lambdas_kernels.hpp"
#include "lambdas_tangent.hpp"

TEST_CASE("styles: lambdas") {
  for (int n : {1, 3, 10, 33}) {
    CAPTURE(n);
    size_t N = size_t(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {N};
    p.out_sizes = {N};
    p.forward = [&](auto in, auto out) { lambda_laplacian(in[0], out[0], n, 0.3); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      lambda_laplacian_adjoint(in[0], adj[0], seed[0], n, 0.3);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      lambda_laplacian_tangent(in[0], d[0], out[0], dout[0], n, 0.3);
    };
    dpgen_test::check_adjoint(p);

    dpgen_test::Problem<double> q;
    q.in_sizes = {N, N};
    q.out_sizes = {N};
    q.forward = [&](auto in, auto out) { lambda_flux(in[0], in[1], out[0], n, 0.2); };
    q.adjoint = [&](auto in, auto adj, auto seed) {
      lambda_flux_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n, 0.2);
    };
    q.tangent = [&](auto in, auto d, auto out, auto dout) {
      lambda_flux_tangent(in[0], d[0], in[1], d[1], out[0], dout[0], n, 0.2);
    };
    dpgen_test::check_adjoint(q);

    dpgen_test::Problem<double> r;
    r.in_sizes = {N};
    r.out_sizes = {N};
    r.forward = [&](auto in, auto out) { lambda_limiter(in[0], out[0], n); };
    r.adjoint = [&](auto in, auto adj, auto seed) {
      lambda_limiter_adjoint(in[0], adj[0], seed[0], n);
    };
    r.tangent = [&](auto in, auto d, auto out, auto dout) {
      lambda_limiter_tangent(in[0], d[0], out[0], dout[0], n);
    };
    dpgen_test::check_adjoint(r);

    dpgen_test::Problem<double> e;
    e.in_sizes = {N};
    e.out_sizes = {N};
    e.forward = [&](auto in, auto out) { lambda_for_each(in[0], out[0], n, 0.3); };
    e.adjoint = [&](auto in, auto adj, auto seed) {
      lambda_for_each_adjoint(in[0], adj[0], seed[0], n, 0.3);
    };
    e.tangent = [&](auto in, auto d, auto out, auto dout) {
      lambda_for_each_tangent(in[0], d[0], out[0], dout[0], n, 0.3);
    };
    dpgen_test::check_adjoint(e);

    dpgen_test::Problem<double> w;
    w.in_sizes = {N};
    w.out_sizes = {N};
    w.forward = [&](auto in, auto out) { lambda_window_sum(in[0], out[0], n, 1); };
    w.adjoint = [&](auto in, auto adj, auto seed) {
      lambda_window_sum_adjoint(in[0], adj[0], seed[0], n, 1);
    };
    w.tangent = [&](auto in, auto d, auto out, auto dout) {
      lambda_window_sum_tangent(in[0], d[0], out[0], dout[0], n, 1);
    };
    dpgen_test::check_adjoint(w);

    dpgen_test::Problem<double> s;
    s.in_sizes = {N};
    s.out_sizes = {N};
    s.forward = [&](auto in, auto out) { lambda_sets_then_returns(in[0], out[0], n); };
    s.adjoint = [&](auto in, auto adj, auto seed) {
      lambda_sets_then_returns_adjoint(in[0], adj[0], seed[0], n);
    };
    s.tangent = [&](auto in, auto d, auto out, auto dout) {
      lambda_sets_then_returns_tangent(in[0], d[0], out[0], dout[0], n);
    };
    dpgen_test::check_adjoint(s);

    dpgen_test::Problem<double> u;
    u.in_sizes = {N, N};
    u.out_sizes = {N};
    u.forward = [&](auto in, auto out) { lambda_direction_then_returns(in[0], in[1], out[0], n); };
    u.adjoint = [&](auto in, auto adj, auto seed) {
      lambda_direction_then_returns_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n);
    };
    u.tangent = [&](auto in, auto d, auto out, auto dout) {
      lambda_direction_then_returns_tangent(in[0], d[0], in[1], d[1], out[0], dout[0], n);
    };
    dpgen_test::check_adjoint(u);

    dpgen_test::Problem<double> r2;
    r2.in_sizes = {N};
    r2.out_sizes = {N};
    r2.forward = [&](auto in, auto out) { lambda_reassigned(in[0], out[0], n); };
    r2.adjoint = [&](auto in, auto adj, auto seed) {
      lambda_reassigned_adjoint(in[0], adj[0], seed[0], n);
    };
    r2.tangent = [&](auto in, auto d, auto out, auto dout) {
      lambda_reassigned_tangent(in[0], d[0], out[0], dout[0], n);
    };
    dpgen_test::check_adjoint(r2);
  }
}
