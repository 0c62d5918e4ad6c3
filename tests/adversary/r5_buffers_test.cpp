// r5_buffers (tests/adversary): the accepted line-buffer kernels of round r5.
#include "support/adjoint_check.hpp"
#include "r5_buffers_adjoint.hpp"
#include "r5_buffers_tangent.hpp"
#include "r5_buffers_kernels.hpp"
#include <stdexcept>
TEST_CASE("r5_buffers: b01_reverse") { for (int n : {0, 1, 2, 3, 4, 7, 40}) { CAPTURE(n);
  dpgen_test::Problem<double> p; p.in_sizes = {size_t(n) + 4}; p.out_sizes = {size_t(n) + 4};
  p.forward = [&](auto in, auto out) { b01_reverse(in[0], out[0], n); };
  p.adjoint = [&](auto in, auto adj, auto seed) { b01_reverse_adjoint(in[0], adj[0], seed[0], n); };
  p.tangent = [&](auto in, auto d, auto out, auto dout) { b01_reverse_tangent(in[0], d[0], out[0], dout[0], n); };
  dpgen_test::check_adjoint(p); } }
TEST_CASE("r5_buffers: b02_countdown") { for (int n : {0, 1, 2, 3, 4, 7, 40}) { CAPTURE(n);
  dpgen_test::Problem<double> p; p.in_sizes = {size_t(n) + 4}; p.out_sizes = {size_t(n) + 4};
  p.forward = [&](auto in, auto out) { b02_countdown(in[0], out[0], n); };
  p.adjoint = [&](auto in, auto adj, auto seed) { b02_countdown_adjoint(in[0], adj[0], seed[0], n); };
  p.tangent = [&](auto in, auto d, auto out, auto dout) { b02_countdown_tangent(in[0], d[0], out[0], dout[0], n); };
  dpgen_test::check_adjoint(p); } }
TEST_CASE("r5_buffers: b03_halves") { for (int n : {0, 1, 2, 3, 4, 7, 40}) { CAPTURE(n);
  dpgen_test::Problem<double> p; p.in_sizes = {size_t(n) + 4}; p.out_sizes = {size_t(n) + 4};
  p.forward = [&](auto in, auto out) { b03_halves(in[0], out[0], n); };
  p.adjoint = [&](auto in, auto adj, auto seed) { b03_halves_adjoint(in[0], adj[0], seed[0], n); };
  p.tangent = [&](auto in, auto d, auto out, auto dout) { b03_halves_tangent(in[0], d[0], out[0], dout[0], n); };
  dpgen_test::check_adjoint(p); } }
TEST_CASE("r5_buffers: b08_chain") { for (int n : {0, 1, 2, 3, 4, 7, 40}) { CAPTURE(n);
  dpgen_test::Problem<double> p; p.in_sizes = {size_t(n) + 4}; p.out_sizes = {size_t(n) + 4};
  p.forward = [&](auto in, auto out) { b08_chain(in[0], out[0], n); };
  p.adjoint = [&](auto in, auto adj, auto seed) { b08_chain_adjoint(in[0], adj[0], seed[0], n); };
  p.tangent = [&](auto in, auto d, auto out, auto dout) { b08_chain_tangent(in[0], d[0], out[0], dout[0], n); };
  dpgen_test::check_adjoint(p); } }
TEST_CASE("r5_buffers: b13_unrolled_taps") { for (int n : {0, 1, 2, 3, 4, 7, 40}) { CAPTURE(n);
  dpgen_test::Problem<double> p; p.in_sizes = {size_t(n) + 4}; p.out_sizes = {size_t(n) + 4};
  p.forward = [&](auto in, auto out) { b13_unrolled_taps(in[0], out[0], n); };
  p.adjoint = [&](auto in, auto adj, auto seed) { b13_unrolled_taps_adjoint(in[0], adj[0], seed[0], n); };
  p.tangent = [&](auto in, auto d, auto out, auto dout) { b13_unrolled_taps_tangent(in[0], d[0], out[0], dout[0], n); };
  dpgen_test::check_adjoint(p); } }
TEST_CASE("r5_buffers: b17_local_index") { for (int n : {0, 1, 2, 3, 4, 7, 40}) { CAPTURE(n);
  dpgen_test::Problem<double> p; p.in_sizes = {size_t(n) + 4}; p.out_sizes = {size_t(n) + 4};
  p.forward = [&](auto in, auto out) { b17_local_index(in[0], out[0], n); };
  p.adjoint = [&](auto in, auto adj, auto seed) { b17_local_index_adjoint(in[0], adj[0], seed[0], n); };
  p.tangent = [&](auto in, auto d, auto out, auto dout) { b17_local_index_tangent(in[0], d[0], out[0], dout[0], n); };
  dpgen_test::check_adjoint(p); } }
TEST_CASE("r5_buffers: b16") { for (int n : {1, 3, 9}) for (int m : {0, 1, n}) { CAPTURE(n); CAPTURE(m);
  dpgen_test::Problem<double> p; p.in_sizes = {size_t(n)}; p.out_sizes = {size_t(n)};
  p.forward = [&](auto in, auto out) { b16_two_sizes(in[0], out[0], n, m); };
  p.adjoint = [&](auto in, auto adj, auto seed) { b16_two_sizes_adjoint(in[0], adj[0], seed[0], n, m); };
  p.tangent = [&](auto in, auto d, auto out, auto dout) { b16_two_sizes_tangent(in[0], d[0], out[0], dout[0], n, m); };
  dpgen_test::check_adjoint(p); }
  std::vector<double> a(10, 1.0), aa(10), s(10);
  CHECK_THROWS_AS(b16_two_sizes_adjoint(a.data(), aa.data(), s.data(), 3, 4), std::invalid_argument); }
TEST_CASE("r5_buffers: b05_inner2") { for (int nx : {1, 2, 3, 5}) for (int ny : {1, 2, 3, 4}) { CAPTURE(nx); CAPTURE(ny);
  size_t N = size_t(nx) * size_t(ny) * size_t(ny) + 8 * size_t(nx) * size_t(ny) + 8;
  dpgen_test::Problem<double> p; p.in_sizes = {N}; p.out_sizes = {N};
  p.forward = [&](auto in, auto out) { b05_inner2(in[0], out[0], nx, ny); };
  p.adjoint = [&](auto in, auto adj, auto seed) { b05_inner2_adjoint(in[0], adj[0], seed[0], nx, ny); };
  p.tangent = [&](auto in, auto d, auto out, auto dout) { b05_inner2_tangent(in[0], d[0], out[0], dout[0], nx, ny); };
  dpgen_test::check_adjoint(p); } }
TEST_CASE("r5_buffers: b09_3d") { for (int nx : {1, 2, 3, 5}) for (int ny : {1, 2, 3, 4}) { CAPTURE(nx); CAPTURE(ny);
  size_t N = size_t(nx) * size_t(ny) * size_t(ny) + 8 * size_t(nx) * size_t(ny) + 8;
  dpgen_test::Problem<double> p; p.in_sizes = {N}; p.out_sizes = {N};
  p.forward = [&](auto in, auto out) { b09_3d(in[0], out[0], nx, ny); };
  p.adjoint = [&](auto in, auto adj, auto seed) { b09_3d_adjoint(in[0], adj[0], seed[0], nx, ny); };
  p.tangent = [&](auto in, auto d, auto out, auto dout) { b09_3d_tangent(in[0], d[0], out[0], dout[0], nx, ny); };
  dpgen_test::check_adjoint(p); } }
TEST_CASE("r5_buffers: b11_rowlevel_only") { for (int nx : {1, 2, 3, 5}) for (int ny : {1, 2, 3, 4}) { CAPTURE(nx); CAPTURE(ny);
  size_t N = size_t(nx) * size_t(ny) * size_t(ny) + 8 * size_t(nx) * size_t(ny) + 8;
  dpgen_test::Problem<double> p; p.in_sizes = {N}; p.out_sizes = {N};
  p.forward = [&](auto in, auto out) { b11_rowlevel_only(in[0], out[0], nx, ny); };
  p.adjoint = [&](auto in, auto adj, auto seed) { b11_rowlevel_only_adjoint(in[0], adj[0], seed[0], nx, ny); };
  p.tangent = [&](auto in, auto d, auto out, auto dout) { b11_rowlevel_only_tangent(in[0], d[0], out[0], dout[0], nx, ny); };
  dpgen_test::check_adjoint(p); } }
TEST_CASE("r5_buffers: b18_rows_top_decl") { for (int nx : {1, 2, 3, 5}) for (int ny : {1, 2, 3, 4}) { CAPTURE(nx); CAPTURE(ny);
  size_t N = size_t(nx) * size_t(ny) * size_t(ny) + 8 * size_t(nx) * size_t(ny) + 8;
  dpgen_test::Problem<double> p; p.in_sizes = {N}; p.out_sizes = {N};
  p.forward = [&](auto in, auto out) { b18_rows_top_decl(in[0], out[0], nx, ny); };
  p.adjoint = [&](auto in, auto adj, auto seed) { b18_rows_top_decl_adjoint(in[0], adj[0], seed[0], nx, ny); };
  p.tangent = [&](auto in, auto d, auto out, auto dout) { b18_rows_top_decl_tangent(in[0], d[0], out[0], dout[0], nx, ny); };
  dpgen_test::check_adjoint(p); } }
TEST_CASE("r5_buffers: b21_row_counter_index") { for (int nx : {1, 2, 3, 5}) for (int ny : {1, 2, 3, 4}) { CAPTURE(nx); CAPTURE(ny);
  size_t N = size_t(nx) * size_t(ny) * size_t(ny) + 8 * size_t(nx) * size_t(ny) + 8;
  dpgen_test::Problem<double> p; p.in_sizes = {N}; p.out_sizes = {N};
  p.forward = [&](auto in, auto out) { b21_row_counter_index(in[0], out[0], nx, ny); };
  p.adjoint = [&](auto in, auto adj, auto seed) { b21_row_counter_index_adjoint(in[0], adj[0], seed[0], nx, ny); };
  p.tangent = [&](auto in, auto d, auto out, auto dout) { b21_row_counter_index_tangent(in[0], d[0], out[0], dout[0], nx, ny); };
  dpgen_test::check_adjoint(p); } }
TEST_CASE("r5_buffers: c18_acc") { for (int nx : {1, 2, 5}) for (int ny : {1, 3}) { CAPTURE(nx); CAPTURE(ny);
  size_t N = size_t(nx) * size_t(ny);
  dpgen_test::Problem<double> p; p.in_sizes = {N}; p.out_sizes = {N};
  p.forward = [&](auto in, auto out) { c18_acc(in[0], out[0], nx, ny); };
  p.adjoint = [&](auto in, auto adj, auto seed) { c18_acc_adjoint(in[0], adj[0], seed[0], nx, ny); };
  p.tangent = [&](auto in, auto d, auto out, auto dout) { c18_acc_tangent(in[0], d[0], out[0], dout[0], nx, ny); };
  dpgen_test::check_adjoint(p); } }
TEST_CASE("r5_buffers: c12_flag, 1") { for (int nx : {1, 2, 5}) for (int ny : {1, 3}) { CAPTURE(nx); CAPTURE(ny);
  size_t N = size_t(nx) * size_t(ny);
  dpgen_test::Problem<double> p; p.in_sizes = {N}; p.out_sizes = {N};
  p.forward = [&](auto in, auto out) { c12_flag(in[0], out[0], nx, ny, 1); };
  p.adjoint = [&](auto in, auto adj, auto seed) { c12_flag_adjoint(in[0], adj[0], seed[0], nx, ny, 1); };
  p.tangent = [&](auto in, auto d, auto out, auto dout) { c12_flag_tangent(in[0], d[0], out[0], dout[0], nx, ny, 1); };
  dpgen_test::check_adjoint(p); } }
TEST_CASE("r5_buffers: c12_flag, 0") { for (int nx : {1, 2, 5}) for (int ny : {1, 3}) { CAPTURE(nx); CAPTURE(ny);
  size_t N = size_t(nx) * size_t(ny);
  dpgen_test::Problem<double> p; p.in_sizes = {N}; p.out_sizes = {N};
  p.forward = [&](auto in, auto out) { c12_flag(in[0], out[0], nx, ny, 0); };
  p.adjoint = [&](auto in, auto adj, auto seed) { c12_flag_adjoint(in[0], adj[0], seed[0], nx, ny, 0); };
  p.tangent = [&](auto in, auto d, auto out, auto dout) { c12_flag_tangent(in[0], d[0], out[0], dout[0], nx, ny, 0); };
  dpgen_test::check_adjoint(p); } }
TEST_CASE("r5_buffers: m2_maxofbuf") { for (int n : {1, 2, 7, 256}) { CAPTURE(n);
  dpgen_test::Problem<double> p; p.in_sizes = {size_t(n)}; p.out_sizes = {1};
  p.forward = [&](auto in, auto out) { m2_maxofbuf(in[0], out[0], n); };
  p.adjoint = [&](auto in, auto adj, auto seed) { m2_maxofbuf_adjoint(in[0], adj[0], seed[0], n); };
  p.tangent = [&](auto in, auto d, auto out, auto dout) { m2_maxofbuf_tangent(in[0], d[0], out[0], dout[0], n); };
  dpgen_test::check_adjoint(p); } }
