// line_buffers (tests/styles/): local arrays of more than 64 elements used as
// line buffers (issue 20), adjoint and tangent of each on random inputs.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "line_buffers_adjoint.hpp"
#include "line_buffers_kernels.hpp"
#include "line_buffers_tangent.hpp"

#include <stdexcept>
#include <tuple>
#include <vector>

TEST_CASE("styles: mg_resid (NAS MG resid, u1[M], u2[M])") {
  const std::vector<double> a = {-8.0 / 3.0, 0.0, 1.0 / 6.0, 1.0 / 12.0};
  for (auto [n1, n2, n3] : {std::tuple{3, 3, 3}, {6, 4, 5}, {130, 3, 4}, {1, 4, 4}}) {
    CAPTURE(n1);
    CAPTURE(n2);
    CAPTURE(n3);
    const size_t N = size_t(n1) * size_t(n2) * size_t(n3);
    dpgen_test::Problem<double> p;
    p.in_sizes = {N, N};
    p.out_sizes = {N};
    p.linear = true;
    p.forward = [&](auto in, auto out) { mg_resid(in[0], in[1], out[0], a.data(), n1, n2, n3); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      mg_resid_adjoint(in[0], adj[0], in[1], adj[1], seed[0], a.data(), n1, n2, n3);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      mg_resid_tangent(in[0], d[0], in[1], d[1], out[0], dout[0], a.data(), n1, n2, n3);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      mg_resid_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1],
                               seed[0], out_n[0], a.data(), a.size(), n1, n2, n3);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: mg_resid checks on entry that a line fits the buffers") {
  // n1 = 131 would overrun u1[130] in the kernel itself: the adjoint refuses
  // the sizes rather than computing with them.
  const int n1 = 131, n2 = 3, n3 = 3;
  const std::vector<double> a = {1, 0, 1, 1};
  std::vector<double> u(size_t(n1 * n2 * n3), 1.0), u_adj(u.size()), v_adj(u.size());
  CHECK_THROWS_AS(mg_resid_adjoint(u.data(), u_adj.data(), u.data(), v_adj.data(), u.data(),
                                   a.data(), n1, n2, n3),
                  std::invalid_argument);
  std::vector<double> r(u.size()), r_dot(u.size());
  CHECK_THROWS_AS(mg_resid_tangent(u.data(), u.data(), u.data(), u.data(), r.data(),
                                   r_dot.data(), a.data(), n1, n2, n3),
                  std::invalid_argument);
}

TEST_CASE("styles: mg_resid_cubic (constexpr length, buffers in the row loop)") {
  for (auto [n1, n2, n3] : {std::tuple{3, 3, 3}, {9, 5, 4}, {96, 3, 3}}) {
    CAPTURE(n1);
    CAPTURE(n2);
    CAPTURE(n3);
    const size_t N = size_t(n1) * size_t(n2) * size_t(n3);
    dpgen_test::Problem<double> p;
    p.in_sizes = {N, N};
    p.out_sizes = {N};
    p.forward = [&](auto in, auto out) { mg_resid_cubic(in[0], in[1], out[0], n1, n2, n3); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      mg_resid_cubic_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n1, n2, n3);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      mg_resid_cubic_tangent(in[0], d[0], in[1], d[1], out[0], dout[0], n1, n2, n3);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: diffuse_buffered (read at i - 1 and i + 1)") {
  for (int n : {1, 2, 3, 17, 512}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { diffuse_buffered(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      diffuse_buffered_adjoint(in[0], adj[0], seed[0], n);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      diffuse_buffered_tangent(in[0], d[0], out[0], dout[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: column_std_array (std::array<double, 128> buffer)") {
  for (auto [nx, ny] : {std::tuple{1, 1}, {3, 4}, {5, 128}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t N = size_t(nx) * size_t(ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {N};
    p.out_sizes = {N, N};
    p.forward = [&](auto in, auto out) { column_std_array(in[0], out[0], out[1], nx, ny); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      column_std_array_adjoint(in[0], adj[0], seed[0], seed[1], nx, ny);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      column_std_array_tangent(in[0], d[0], out[0], dout[0], out[1], dout[1], nx, ny);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: shifted_float (float buffer, filled counting down)") {
  for (int n : {1, 5, 198}) {
    CAPTURE(n);
    dpgen_test::Problem<float> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { shifted_float(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      shifted_float_adjoint(in[0], adj[0], seed[0], n);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      shifted_float_tangent(in[0], d[0], out[0], dout[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: filled_by_helper (a helper fills the buffer)") {
  for (int n : {1, 3, 50, 100}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { filled_by_helper(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      filled_by_helper_adjoint(in[0], adj[0], seed[0], n);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      filled_by_helper_tangent(in[0], d[0], out[0], dout[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: guarded_and_ends (guarded reads, the row's ends)") {
  for (auto [nx, ny] : {std::tuple{2, 1}, {3, 4}, {256, 2}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t N = size_t(nx) * size_t(ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {N};
    p.out_sizes = {N, size_t(ny)};
    p.forward = [&](auto in, auto out) { guarded_and_ends(in[0], out[0], out[1], nx, ny); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      guarded_and_ends_adjoint(in[0], adj[0], seed[0], seed[1], nx, ny);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      guarded_and_ends_tangent(in[0], d[0], out[0], dout[0], out[1], dout[1], nx, ny);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: strided_skip (strided reads, a skipped row)") {
  for (auto [nx, ny] : {std::tuple{1, 1}, {4, 3}, {7, 2}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t N = size_t(nx) * size_t(ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {N};
    p.out_sizes = {N};
    p.forward = [&](auto in, auto out) { strided_skip(in[0], out[0], nx, ny); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      strided_skip_adjoint(in[0], adj[0], seed[0], nx, ny);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      strided_skip_tangent(in[0], d[0], out[0], dout[0], nx, ny);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: rows16_cast (pointers to rows of 16 over flat arrays)") {
  for (int ny : {1, 3, 6}) {
    CAPTURE(ny);
    const size_t N = size_t(16) * size_t(ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {N};
    p.out_sizes = {N};
    p.forward = [&](auto in, auto out) { rows16_cast(in[0], out[0], ny); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      rows16_cast_adjoint(in[0], adj[0], seed[0], ny);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      rows16_cast_tangent(in[0], d[0], out[0], dout[0], ny);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: scratch_same_iteration (read back in the iteration that stored it)") {
  for (int n : {1, 9, 100}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { scratch_same_iteration(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      scratch_same_iteration_adjoint(in[0], adj[0], seed[0], n);
    };
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      scratch_same_iteration_tangent(in[0], d[0], out[0], dout[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
