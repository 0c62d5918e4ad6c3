// vector_buffers (tests/styles/): local std::vector work arrays made with their length (and a
// value), read as line buffers: a flux form with hand-set wall faces, a per-row temporary made
// inside the row loop, single-precision vectors, and faces no loop writes read as the value
// the vector was made with (zero, or an input's).
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "vector_buffers_adjoint.hpp"
#include "vector_buffers_tangent.hpp"

#include <vector>

DPGEN_KERNEL void vector_flux_form(DPGEN_IN const double* q, DPGEN_IN const double* c,
                                   DPGEN_OUT double* q_next, int n, double dt_dx);
DPGEN_KERNEL void vector_row_filter(DPGEN_IN const double* u, DPGEN_OUT double* v, int nx, int ny);
DPGEN_KERNEL void vector_float_grad(DPGEN_IN const float* p, DPGEN_OUT float* e, int n, float h);
DPGEN_KERNEL void vector_size_faces(DPGEN_IN const double* u, DPGEN_OUT double* out, int n);
DPGEN_KERNEL void vector_gather(DPGEN_IN const std::vector<double>& a,
                                const std::vector<double>& pos, DPGEN_OUT std::vector<double>& out,
                                int n);
DPGEN_KERNEL void vector_walls_at_zero(DPGEN_IN const double* u, DPGEN_IN const double* k,
                                       DPGEN_OUT double* u_next, int n, double dt);
DPGEN_KERNEL void vector_inflow_value(DPGEN_IN const double* u, DPGEN_IN const double* g,
                                      DPGEN_OUT double* r, int n, int m);
DPGEN_KERNEL void vector_row_walls(DPGEN_IN const double* u, DPGEN_OUT double* out, int nx,
                                   int ny);
DPGEN_KERNEL void vector_reads_in_declarations(DPGEN_IN const double* u, DPGEN_OUT double* r,
                                               int n);

TEST_CASE("styles: vector_buffers, flux form with wall faces") {
  for (int n : {1, 2, 3, 10, 257}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n), size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { vector_flux_form(in[0], in[1], out[0], n, 0.4); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      vector_flux_form_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n, 0.4);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      vector_flux_form_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], n, 0.4);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: vector_buffers, a per-row temporary") {
  for (auto [nx, ny] : {std::pair{1, 1}, {2, 3}, {3, 2}, {17, 5}, {130, 4}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t cells = size_t(nx) * size_t(ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {cells};
    p.out_sizes = {cells};
    p.forward = [&](auto in, auto out) { vector_row_filter(in[0], out[0], nx, ny); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      vector_row_filter_adjoint(in[0], adj[0], seed[0], nx, ny);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      vector_row_filter_tangent(in[0], dir[0], out[0], outd[0], nx, ny);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: vector_buffers, single precision") {
  for (int n : {1, 2, 3, 9, 100}) {
    CAPTURE(n);
    dpgen_test::Problem<float> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { vector_float_grad(in[0], out[0], n, 0.5f); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      vector_float_grad_adjoint(in[0], adj[0], seed[0], n, 0.5f);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      vector_float_grad_tangent(in[0], dir[0], out[0], outd[0], n, 0.5f);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: vector_buffers, a data-dependent gather from a std::vector parameter") {
  for (int n : {0, 1, 5, 40}) {
    CAPTURE(n);
    const size_t m = size_t(n) + 2;
    std::vector<double> pos(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) // departure points in [0, n + 1), in no order
      pos[size_t(i)] = std::fmod(0.37 + 2.71 * i, double(n) + 0.999);
    const auto vec = [](const double* x, size_t k) { return std::vector<double>(x, x + k); };
    dpgen_test::Problem<double> p;
    p.in_sizes = {m};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) {
      std::vector<double> o(static_cast<size_t>(n));
      vector_gather(vec(in[0], m), pos, o, n);
      std::copy(o.begin(), o.end(), out[0]);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      std::vector<double> a_adj = vec(adj[0], m); // (adds to what the adjoint holds)
      vector_gather_adjoint(vec(in[0], m), a_adj, pos, vec(seed[0], size_t(n)), n);
      std::copy(a_adj.begin(), a_adj.end(), adj[0]);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: vector_buffers, faces counted by size()") {
  for (int n : {0, 1, 2, 9, 100}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { vector_size_faces(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      vector_size_faces_adjoint(in[0], adj[0], seed[0], n);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      vector_size_faces_tangent(in[0], dir[0], out[0], outd[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: vector_buffers, wall faces left at the vector's zero") {
  for (int n : {0, 1, 2, 3, 10, 257}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n), size_t(n)};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { vector_walls_at_zero(in[0], in[1], out[0], n, 0.3); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      vector_walls_at_zero_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n, 0.3);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      vector_walls_at_zero_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], n, 0.3);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: vector_buffers, faces left at an input's value, a gap between two fills") {
  for (auto [n, m] : {std::pair{1, 0}, {2, 1}, {3, 1}, {5, 2}, {5, 4}, {9, 9}, {12, 0}, {40, 17}}) {
    CAPTURE(n);
    CAPTURE(m);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n), 1};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { vector_inflow_value(in[0], in[1], out[0], n, m); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      vector_inflow_value_adjoint(in[0], adj[0], in[1], adj[1], seed[0], n, m);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      vector_inflow_value_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], n, m);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: vector_buffers, per-row faces made in the row loop, walls left out") {
  for (auto [nx, ny] : {std::pair{1, 1}, {2, 3}, {3, 2}, {17, 5}, {130, 4}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t cells = size_t(nx) * size_t(ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {cells};
    p.out_sizes = {cells};
    p.forward = [&](auto in, auto out) { vector_row_walls(in[0], out[0], nx, ny); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      vector_row_walls_adjoint(in[0], adj[0], seed[0], nx, ny);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      vector_row_walls_tangent(in[0], dir[0], out[0], outd[0], nx, ny);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("styles: vector_buffers, elements read into locals, a vector made with another's") {
  for (int n : {0, 1, 2, 3, 10, 65}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(n) + 1};
    p.out_sizes = {size_t(n)};
    p.forward = [&](auto in, auto out) { vector_reads_in_declarations(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      vector_reads_in_declarations_adjoint(in[0], adj[0], seed[0], n);
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      vector_reads_in_declarations_tangent(in[0], dir[0], out[0], outd[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}
