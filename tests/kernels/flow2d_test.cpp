// flow2d (kernels/): the flow solver's kernels on a MAC grid, each axis closed or periodic. The
// semi-Lagrangian ones read at data-dependent indices (scatter adjoints, piecewise smooth:
// clamping, wrapping and floor); velocities of up to ~1.5 cells per step so the traces cross
// cells and reach the walls or wrap around.
#include "support/adjoint_check.hpp"

#include "flow2d_adjoint.hpp"
#include "kernels.hpp"

namespace {
const std::vector<std::pair<int, int>> kGrids = {{2, 2}, {3, 5}, {6, 4}};
constexpr double kDtH = 1.5;
// (px, py): closed, periodic in x, periodic in y, periodic in both.
const std::vector<std::pair<int, int>> kAxes = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
} // namespace

TEST_CASE("flow_advect_marker adjoint") {
  for (auto [px, py] : kAxes)
  for (auto [nx, ny] : kGrids) {
    CAPTURE(px);
    CAPTURE(py);
    CAPTURE(nx);
    CAPTURE(ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t(nx * ny), size_t((nx + 1) * ny), size_t(nx * (ny + 1)), size_t(nx * ny)};
    p.out_sizes = {size_t(nx * ny)};
    p.forward = [&](auto in, auto out) {
      flow_advect_marker(in[0], in[1], in[2], in[3], out[0], nx, ny, kDtH, px, py);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      flow_advect_marker_adjoint(in[0], adj[0], in[1], adj[1], in[2], adj[2], in[3], adj[3],
                                 seed[0], nx, ny, kDtH, px, py);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      flow_advect_marker_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], in[2], in_n[2], adj[2], in_n[2], in[3], in_n[3], adj[3], in_n[3], seed[0], out_n[0], nx, ny, kDtH, px, py);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("flow_advect_u and flow_advect_v adjoints") {
  for (int zt : {0, 1}) // tangential velocity beyond closed walls: clamped, zero ghosts
  for (auto [px, py] : kAxes)
  for (auto [nx, ny] : kGrids) {
    CAPTURE(zt);
    CAPTURE(px);
    CAPTURE(py);
    CAPTURE(nx);
    CAPTURE(ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {size_t((nx + 1) * ny), size_t(nx * (ny + 1))};
    p.out_sizes = {size_t((nx + 1) * ny)};
    p.forward = [&](auto in, auto out) { flow_advect_u(in[0], in[1], out[0], nx, ny, kDtH, px, py, zt); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      flow_advect_u_adjoint(in[0], adj[0], in[1], adj[1], seed[0], nx, ny, kDtH, px, py, zt);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      flow_advect_u_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], nx, ny, kDtH, px, py, zt);
    };
    dpgen_test::check_adjoint(p);
    p.out_sizes = {size_t(nx * (ny + 1))};
    p.forward = [&](auto in, auto out) { flow_advect_v(in[0], in[1], out[0], nx, ny, kDtH, px, py, zt); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      flow_advect_v_adjoint(in[0], adj[0], in[1], adj[1], seed[0], nx, ny, kDtH, px, py, zt);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      flow_advect_v_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], nx, ny, kDtH, px, py, zt);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("flow_buoyancy, flow_force_u, flow_divergence, flow_subtract_gradient_u/v adjoints (linear)") {
  for (auto [px, py] : kAxes)
  for (auto [nx, ny] : kGrids) {
    CAPTURE(px);
    CAPTURE(py);
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t cells = size_t(nx * ny), uf = size_t((nx + 1) * ny), vf = size_t(nx * (ny + 1));
    dpgen_test::Problem<double> p;
    p.linear = true;
    p.in_sizes = {vf, cells, cells};
    p.out_sizes = {vf};
    p.forward = [&](auto in, auto out) {
      flow_buoyancy(in[0], in[1], in[2], out[0], nx, ny, 0.7, 0.3, py);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      flow_buoyancy_adjoint(in[0], adj[0], in[1], adj[1], in[2], adj[2], seed[0], nx, ny, 0.7,
                            0.3, py);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      flow_buoyancy_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], in[2], in_n[2], adj[2], in_n[2], seed[0], out_n[0], nx, ny, 0.7, 0.3, py);
    };
    dpgen_test::check_adjoint(p);
    p.in_sizes = {uf, cells};
    p.out_sizes = {uf};
    p.forward = [&](auto in, auto out) { flow_force_u(in[0], in[1], out[0], nx, ny, 0.3, px); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      flow_force_u_adjoint(in[0], adj[0], in[1], adj[1], seed[0], nx, ny, 0.3, px);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      flow_force_u_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], nx, ny, 0.3, px);
    };
    dpgen_test::check_adjoint(p);
    p.in_sizes = {uf, vf};
    p.out_sizes = {cells};
    p.forward = [&](auto in, auto out) { flow_divergence(in[0], in[1], out[0], nx, ny, 0.5, px, py); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      flow_divergence_adjoint(in[0], adj[0], in[1], adj[1], seed[0], nx, ny, 0.5, px, py);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      flow_divergence_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], nx, ny, 0.5, px, py);
    };
    dpgen_test::check_adjoint(p);
    p.in_sizes = {uf, cells};
    p.out_sizes = {uf};
    p.forward = [&](auto in, auto out) {
      flow_subtract_gradient_u(in[0], in[1], out[0], nx, ny, 0.5, px);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      flow_subtract_gradient_u_adjoint(in[0], adj[0], in[1], adj[1], seed[0], nx, ny, 0.5, px);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      flow_subtract_gradient_u_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], nx, ny, 0.5, px);
    };
    dpgen_test::check_adjoint(p);
    p.in_sizes = {vf, cells};
    p.out_sizes = {vf};
    p.forward = [&](auto in, auto out) {
      flow_subtract_gradient_v(in[0], in[1], out[0], nx, ny, 0.5, py);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      flow_subtract_gradient_v_adjoint(in[0], adj[0], in[1], adj[1], seed[0], nx, ny, 0.5, py);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      flow_subtract_gradient_v_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], nx, ny, 0.5, py);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("flow_pressure_operator adjoint; -div grad is the operator") {
  for (auto [px, py] : kAxes)
  for (auto [nx, ny] : kGrids) {
    CAPTURE(px);
    CAPTURE(py);
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t cells = size_t(nx * ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {cells, cells};
    p.in_ranges = {{-1.0, 1.0}, {0.5, 2.0}};
    p.out_sizes = {cells};
    p.forward = [&](auto in, auto out) {
      flow_pressure_operator(in[0], in[1], out[0], nx, ny, 0.5, double(px), double(py));
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      flow_pressure_operator_adjoint(in[0], adj[0], in[1], adj[1], seed[0], nx, ny, 0.5, double(px), double(py));
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      flow_pressure_operator_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], seed[0], out_n[0], nx, ny, 0.5, double(px), double(py));
    };
    dpgen_test::check_adjoint(p);
    // With k = 1: A p = -div(grad p), grad p from the projection kernels on zero velocities.
    std::vector<double> pr(cells), k(cells, 1.0), ap(cells), gu((nx + 1) * ny), gv(nx * (ny + 1));
    std::vector<double> zu((nx + 1) * ny, 0.0), zv(nx * (ny + 1), 0.0), div(cells);
    for (size_t c = 0; c < cells; ++c)
      pr[c] = std::sin(1.0 + 2.3 * double(c));
    flow_pressure_operator(pr.data(), k.data(), ap.data(), nx, ny, 0.5, double(px), double(py));
    flow_subtract_gradient_u(zu.data(), pr.data(), gu.data(), nx, ny, 0.5, px); // -grad_x p
    flow_subtract_gradient_v(zv.data(), pr.data(), gv.data(), nx, ny, 0.5, py); // -grad_y p
    flow_divergence(gu.data(), gv.data(), div.data(), nx, ny, 0.5, px, py);         // -div grad p
    for (size_t c = 0; c < cells; ++c)
      CHECK(ap[c] == doctest::Approx(div[c]).epsilon(1e-12));
  }
}

TEST_CASE("flow_maccormack_marker adjoint") {
  for (auto [px, py] : kAxes)
  for (auto [nx, ny] : kGrids) {
    CAPTURE(px);
    CAPTURE(py);
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t cells = size_t(nx * ny);
    dpgen_test::Problem<double> p;
    p.in_sizes = {cells, cells, cells, size_t((nx + 1) * ny), size_t(nx * (ny + 1)), cells};
    p.out_sizes = {cells};
    p.forward = [&](auto in, auto out) {
      flow_maccormack_marker(in[0], in[1], in[2], in[3], in[4], in[5], out[0], nx, ny, kDtH, px, py);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      flow_maccormack_marker_adjoint(in[0], adj[0], in[1], adj[1], in[2], adj[2], in[3], adj[3],
                                     in[4], adj[4], in[5], adj[5], seed[0], nx, ny, kDtH, px, py);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      flow_maccormack_marker_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], in[1], in_n[1], adj[1], in_n[1], in[2], in_n[2], adj[2], in_n[2], in[3], in_n[3], adj[3], in_n[3], in[4], in_n[4], adj[4], in_n[4], in[5], in_n[5], adj[5], in_n[5], seed[0], out_n[0], nx, ny, kDtH, px, py);
    };
    dpgen_test::check_adjoint(p);
  }
}
