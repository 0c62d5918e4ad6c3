// line_buffers_c (tests/styles/line_buffers_c.c): VLA line buffers and C99
// pointers to VLA rows (issue 20), adjoint and tangent of each C kernel.
#include "support/adjoint_check.hpp"

#include "line_buffers_c_adjoint.hpp"
#include "line_buffers_c_kernels.hpp" // the generated declarations of the C kernels
#include "line_buffers_c_tangent.hpp"

#include <tuple>

TEST_CASE("styles: sweep2d_vla (double flux[nx] in the row loop)") {
  for (auto [nx, ny] : {std::tuple{1, 1}, {2, 3}, {7, 4}, {33, 2}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t N = size_t(nx) * size_t(ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {N};
    p.out_sizes = {N};
    p.forward = [&](auto in, auto out) { sweep2d_vla(in[0], out[0], nx, ny, 0.3); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      sweep2d_vla_adjoint(in[0], adj[0], seed[0], nx, ny, 0.3);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      sweep2d_vla_tangent(in[0], d[0], out[0], dout[0], nx, ny, 0.3);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      sweep2d_vla_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], nx, ny, 0.3);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: smooth_twice_read (a VLA outside every loop)") {
  for (int n : {1, 2, 3, 10, 100}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n), size_t(n)};
    p.forward = [&](auto in, auto out) { smooth_twice_read(in[0], out[0], out[1], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      smooth_twice_read_adjoint(in[0], adj[0], seed[0], seed[1], n);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      smooth_twice_read_tangent(in[0], d[0], out[0], dout[0], out[1], dout[1], n);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: padded_rows (ends and interior of a VLA buffer)") {
  for (auto [nx, ny] : {std::tuple{1, 1}, {2, 2}, {6, 3}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t N = size_t(nx) * size_t(ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {N};
    p.out_sizes = {N};
    p.forward = [&](auto in, auto out) { padded_rows(in[0], out[0], nx, ny); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      padded_rows_adjoint(in[0], adj[0], seed[0], nx, ny);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      padded_rows_tangent(in[0], d[0], out[0], dout[0], nx, ny);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: laplace3d_vla_cast (double (*u)[n][n] = (double (*)[n][n]) u_flat)") {
  for (int n : {1, 3, 4, 7}) {
    CAPTURE(n);
    const size_t N = size_t(n) * size_t(n) * size_t(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {N, N};
    p.out_sizes = {N};
    p.forward = [&](auto in, auto out) { laplace3d_vla_cast(in[0], in[1], out[0], n, 2.0); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      laplace3d_vla_cast_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n, 2.0);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      laplace3d_vla_cast_tangent(in[0], d[0], in[1], d[1], out[0], dout[0], n, 2.0);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      laplace3d_vla_cast_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1],
                                         in_n[1], seed[0], out_n[0], n, 2.0);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: grad_rows_cast (VLA row pointers and a VLA buffer)") {
  for (auto [nx, ny] : {std::tuple{1, 1}, {3, 2}, {8, 5}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t N = size_t(nx) * size_t(ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {N};
    p.out_sizes = {N};
    p.forward = [&](auto in, auto out) { grad_rows_cast(in[0], out[0], nx, ny); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      grad_rows_cast_adjoint(in[0], adj[0], seed[0], nx, ny);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      grad_rows_cast_tangent(in[0], d[0], out[0], dout[0], nx, ny);
    };
    dpgen_test::check_adjoint(p);
  }
}
