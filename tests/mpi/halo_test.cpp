// Tests of dpgen/mpi: the block decomposition, the halo exchange and its adjoint, and generated
// halo kernels run on every block against the single-process (periodic-wrap) kernels: values,
// the dot-product test across ranks, and gradients through an unrolled, checkpointed time loop.
// Run under mpirun with 1, 2 and 4 ranks (ctest: mpi.halo.np*).
#include "dpgen/checkpoint.hpp"
#include "dpgen/mpi/checkpoint.hpp"
#include "dpgen/mpi/decomposition.hpp"
#include "dpgen/mpi/halo.hpp"

#include "halo_kernels.hpp"
#include "kernels.hpp"
#include "mac_divergence_halo_adjoint.hpp"
#include "neg_div_k_grad_halo2d_adjoint.hpp"
#include "neg_div_k_grad_periodic2d_adjoint.hpp"
#include "neg_laplacian_halo3d_adjoint.hpp"
#include "operators.hpp"
#include "upwind_step_adjoint.hpp"
#include "upwind_step_halo_adjoint.hpp"

#include "mpi_test_support.hpp"

#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace {

using dpgen::mpi::Decomposition;
using dpgen::mpi::DecompositionOptions;
using dpgen_mpi_test::contains;
using dpgen_mpi_test::error_of;
using dpgen_mpi_test::max_over_ranks;
using dpgen_mpi_test::random_vector;
using Eigen::VectorXd;

// Grids of 1, 2 and 3 dimensions, periodic or not, sizes that do not divide evenly, halo
// widths 1 to 3: every block has at least `halo` cells with 1, 2 and 4 ranks.
std::vector<DecompositionOptions> layouts() {
  return {
      {{13}, {true}, {}, 1},
      {{13}, {false}, {}, 2},
      {{16}, {true}, {}, 3},
      {{10, 7}, {true, true}, {}, 1},
      {{10, 7}, {true, false}, {}, 1},
      {{9, 8}, {false, true}, {}, 2},
      {{6, 5, 4}, {true, true, true}, {}, 1},
      {{6, 5, 4}, {false, true, false}, {}, 1},
      {{10, 7}, {true, true}, {1, 0}, 1}, // all ranks along y
  };
}

std::string describe(const DecompositionOptions& o) {
  std::string s;
  for (std::size_t d = 0; d < o.global.size(); ++d)
    s += (d ? "x" : "") + std::to_string(o.global[d]) + (o.periodic[d] ? "p" : "");
  return s + " halo " + std::to_string(o.halo);
}

// Calls fn(index, g) for every value of a padded array, g its global cell position (outside
// [0, N) in the halos beyond the grid's edge; 0 in dimensions the grid does not have).
template <typename Fn> void for_each_padded(const Decomposition& dec, Fn&& fn) {
  const int h = dec.halo();
  Eigen::Index index = 0;
  for (int pk = 0; pk < dec.padded(2); ++pk)
    for (int pj = 0; pj < dec.padded(1); ++pj)
      for (int pi = 0; pi < dec.padded(0); ++pi, ++index) {
        const std::array<int, 3> p{pi, pj, pk};
        std::array<int, 3> g{0, 0, 0};
        for (int d = 0; d < dec.dims(); ++d)
          g[d] = dec.offset(d) + p[d] - h;
        fn(index, g);
      }
}

// The wrapped global cell id + 1 of position g, or 0 when g lies beyond a non-periodic edge.
double cell_id(const Decomposition& dec, std::array<int, 3> g) {
  for (int d = 0; d < dec.dims(); ++d) {
    const int n = dec.global(d);
    if (g[d] < 0 || g[d] >= n) {
      if (!dec.periodic(d))
        return 0;
      g[d] = ((g[d] % n) + n) % n;
    }
  }
  return 1.0 + (static_cast<double>(g[2]) * dec.global(1) + g[1]) * dec.global(0) + g[0];
}

// max |a - ref| / max |ref| over every rank's block.
double relative_error(const VectorXd& a, const VectorXd& ref) {
  const double diff = max_over_ranks((a - ref).cwiseAbs().maxCoeff());
  const double scale = max_over_ranks(ref.cwiseAbs().maxCoeff());
  return diff / scale;
}

} // namespace

TEST_CASE("the blocks tile the grid and gather() reassembles it") {
  for (const auto& o : layouts()) {
    CAPTURE(describe(o));
    Decomposition dec(MPI_COMM_WORLD, o);
    const VectorXd global = random_vector(dec.global_size(), 3);
    const VectorXd local = dec.local_part(global);
    CHECK(dec.sum(static_cast<double>(dec.interior_size())) == dec.global_size());
    CHECK(dec.gather(local) == global);
    CHECK(dec.interior(dec.pad(local)) == local);
  }
}

TEST_CASE("the exchange fills every halo cell with the cell it mirrors, corners included") {
  const double sentinel = -7.0; // halos beyond a non-periodic edge must keep it
  for (const auto& o : layouts()) {
    CAPTURE(describe(o));
    Decomposition dec(MPI_COMM_WORLD, o);
    VectorXd a = VectorXd::Constant(dec.padded_size(), sentinel);
    VectorXd expected(dec.padded_size());
    std::vector<bool> own(dec.padded_size(), false);
    for_each_padded(dec, [&](Eigen::Index i, std::array<int, 3> g) {
      const double id = cell_id(dec, g);
      expected[i] = id == 0 ? sentinel : id;
      bool inside = true;
      for (int d = 0; d < dec.dims(); ++d)
        inside = inside && g[d] >= dec.offset(d) && g[d] < dec.offset(d) + dec.local(d);
      if (inside)
        a[i] = id; // only the block's own cells are set before the exchange
    });
    dpgen::mpi::exchange_halos(dec, a);
    const double wrong = max_over_ranks((a - expected).cwiseAbs().maxCoeff());
    CHECK(wrong == 0.0);
  }
}

TEST_CASE("the reverse exchange is the transpose of the exchange: <E a, b> = <a, E^T b>") {
  unsigned seed = 11;
  for (const auto& o : layouts()) {
    CAPTURE(describe(o));
    Decomposition dec(MPI_COMM_WORLD, o);
    // random values everywhere, halos included, different on every rank
    const VectorXd a = random_vector(dec.padded_size(), seed + 100 * dec.rank());
    const VectorXd b = random_vector(dec.padded_size(), seed + 100 * dec.rank() + 1);
    ++seed;
    VectorXd ea = a, etb = b;
    dpgen::mpi::exchange_halos(dec, ea);
    dpgen::mpi::exchange_halos_adjoint(dec, etb);
    const double lhs = dec.sum(ea.dot(b)), rhs = dec.sum(a.dot(etb));
    CAPTURE(lhs);
    CAPTURE(rhs);
    CHECK(std::abs(lhs - rhs) <= 1e-13 * std::abs(lhs));
  }
}

TEST_CASE("upwind steps: loss and gradients through T steps equal the single-process run "
          "(full tape and Revolve across ranks)") {
  const int n = 37, steps = 25; // 37 cells: blocks of 37, 19/18, 10/9 cells
  const double dx = 1.0 / n, dt = 0.4 * dx;
  // velocities of both signs, so both upwind branches and both halo sides are exercised
  const VectorXd u = random_vector(n, 1, -0.8, 0.8), d0 = random_vector(n, 2, 0.0, 1.0);
  const VectorXd target_mid = random_vector(n, 3), target_end = random_vector(n, 4);
  // L = |d(T/2) - target_mid|^2 + |d(T) - target_end|^2: loss terms at two times
  auto loss_term = [&](int t, const VectorXd& d, VectorXd& d_adj, const VectorXd& mid,
                       const VectorXd& end) {
    if (t != steps && t != steps / 2)
      return 0.0;
    const VectorXd r = d - (t == steps ? end : mid);
    d_adj += 2.0 * r;
    return r.squaredNorm();
  };

  // The single-process reference: the periodic-wrap kernel on the whole grid, on every rank.
  VectorXd u_adj_ref = VectorXd::Zero(n);
  auto ref = dpgen::unrolled_gradient(
      d0, steps,
      [&](int, const VectorXd& d, VectorXd& next) {
        upwind_step(d.data(), u.data(), next.data(), n, dt, dx);
      },
      [&](int, const VectorXd& d, const VectorXd& next_adj, VectorXd& d_adj) {
        upwind_step_adjoint(d.data(), d_adj.data(), u.data(), u_adj_ref.data(), next_adj.data(), n,
                            dt, dx);
      },
      [&](int t, const VectorXd& d, VectorXd& d_adj) {
        return loss_term(t, d, d_adj, target_mid, target_end);
      });

  Decomposition dec(MPI_COMM_WORLD, {{n}, {true}, {}, 1});
  const int nl = dec.local(0);
  const VectorXd mid = dec.local_part(target_mid), end = dec.local_part(target_end);
  VectorXd u_padded = dec.pad(dec.local_part(u));
  dpgen::mpi::exchange_halos(dec, u_padded);

  struct Result {
    double loss;
    VectorXd d0_grad, u_grad;
  };
  auto distributed = [&](const dpgen::CheckpointOptions& cp) {
    VectorXd u_adj = VectorXd::Zero(dec.padded_size());
    VectorXd dp = VectorXd::Zero(dec.padded_size()), out(dec.padded_size());
    VectorXd d_adj_p(dec.padded_size());
    auto g = dpgen::mpi::unrolled_gradient(
        dec, dec.local_part(d0), steps,
        [&](int, const VectorXd& d, VectorXd& next) { // next = K(E(P d))
          dec.copy_interior(d, dp);
          dpgen::mpi::exchange_halos(dec, dp);
          out.setZero();
          upwind_step_halo(dp.data(), u_padded.data(), out.data(), nl, dt, dx);
          next = dec.interior(out);
        },
        [&](int, const VectorXd& d, const VectorXd& next_adj, VectorXd& d_adj) {
          // d_adj += P^T E^T K^T next_adj; u's adjoint stays padded until the end
          dec.copy_interior(d, dp);
          dpgen::mpi::exchange_halos(dec, dp);
          const VectorXd seed = dec.pad(next_adj);
          d_adj_p.setZero();
          upwind_step_halo_adjoint(dp.data(), d_adj_p.data(), u_padded.data(), u_adj.data(),
                                   seed.data(), nl, dt, dx);
          dpgen::mpi::exchange_halos_adjoint(dec, d_adj_p);
          d_adj += dec.interior(d_adj_p);
        },
        [&](int t, const VectorXd& d, VectorXd& d_adj) { return loss_term(t, d, d_adj, mid, end); },
        cp);
    dpgen::mpi::exchange_halos_adjoint(dec, u_adj); // u was exchanged once, before the loop
    return Result{g.loss, g.state_adjoint, dec.interior(u_adj)}; // loss: summed over ranks
  };

  const Result full = distributed({});
  const Result revolve = distributed({dpgen::CheckpointStrategy::revolve, 4});
  CHECK(std::abs(full.loss - ref.loss) <= 1e-12 * ref.loss);
  CHECK(relative_error(full.d0_grad, dec.local_part(ref.state_adjoint)) <= 1e-12);
  CHECK(relative_error(full.u_grad, dec.local_part(u_adj_ref)) <= 1e-12);
  // every rank keeps its own snapshots; recomputation gives the same bits
  CHECK(revolve.loss == full.loss);
  CHECK(revolve.d0_grad == full.d0_grad);
  CHECK(revolve.u_grad == full.u_grad);
}

TEST_CASE("2D variable-coefficient operator: values and adjoints equal the periodic kernel's") {
  const int nx = 10, ny = 7;
  const double h = 1.0 / nx;
  const int n = nx * ny;
  const VectorXd p = random_vector(n, 5), k = random_vector(n, 6, 0.5, 2.0);
  const VectorXd w = random_vector(n, 7); // the output's adjoint seed
  VectorXd out_ref(n), p_adj_ref = VectorXd::Zero(n), k_adj_ref = VectorXd::Zero(n);
  neg_div_k_grad_periodic2d(p.data(), k.data(), out_ref.data(), nx, ny, h);
  neg_div_k_grad_periodic2d_adjoint(p.data(), p_adj_ref.data(), k.data(), k_adj_ref.data(),
                                    w.data(), nx, ny, h);

  for (const std::vector<int>& procs : {std::vector<int>{}, std::vector<int>{1, 0}}) {
    Decomposition dec(MPI_COMM_WORLD, {{nx, ny}, {true, true}, procs, 1});
    CAPTURE(dec.where());
    VectorXd pp = dec.pad(dec.local_part(p)), kp = dec.pad(dec.local_part(k));
    dpgen::mpi::exchange_halos(dec, pp);
    dpgen::mpi::exchange_halos(dec, kp);
    VectorXd out = VectorXd::Zero(dec.padded_size());
    neg_div_k_grad_halo2d(pp.data(), kp.data(), out.data(), dec.local(0), dec.local(1), h);
    CHECK(relative_error(dec.interior(out), dec.local_part(out_ref)) <= 1e-14);

    const VectorXd seed = dec.pad(dec.local_part(w));
    VectorXd p_adj = VectorXd::Zero(dec.padded_size()), k_adj = p_adj;
    neg_div_k_grad_halo2d_adjoint(pp.data(), p_adj.data(), kp.data(), k_adj.data(), seed.data(),
                                  dec.local(0), dec.local(1), h);
    dpgen::mpi::exchange_halos_adjoint(dec, p_adj);
    dpgen::mpi::exchange_halos_adjoint(dec, k_adj);
    CHECK(relative_error(dec.interior(p_adj), dec.local_part(p_adj_ref)) <= 1e-12);
    CHECK(relative_error(dec.interior(k_adj), dec.local_part(k_adj_ref)) <= 1e-12);
  }
}

TEST_CASE("MAC divergence on blocks: dot-product test of exchange + kernel across ranks") {
  // F(u, v) = K(E P u, E P v) as a map of the distributed interior vectors; F^T by the
  // generated adjoint and the reverse exchange: <F(u, v), w> = <(u, v), F^T w>.
  Decomposition dec(MPI_COMM_WORLD, {{12, 9}, {true, true}, {}, 1});
  const double h = 0.1;
  const Eigen::Index m = dec.interior_size();
  const VectorXd u = random_vector(m, 20 + dec.rank()), v = random_vector(m, 40 + dec.rank());
  const VectorXd w = random_vector(m, 60 + dec.rank());
  VectorXd up = dec.pad(u), vp = dec.pad(v), div = VectorXd::Zero(dec.padded_size());
  dpgen::mpi::exchange_halos(dec, up);
  dpgen::mpi::exchange_halos(dec, vp);
  mac_divergence_halo(up.data(), vp.data(), div.data(), dec.local(0), dec.local(1), h);
  const VectorXd seed = dec.pad(w);
  VectorXd u_adj = VectorXd::Zero(dec.padded_size()), v_adj = u_adj;
  mac_divergence_halo_adjoint(up.data(), u_adj.data(), vp.data(), v_adj.data(), seed.data(),
                              dec.local(0), dec.local(1), h);
  dpgen::mpi::exchange_halos_adjoint(dec, u_adj);
  dpgen::mpi::exchange_halos_adjoint(dec, v_adj);
  const double lhs = dec.dot(dec.interior(div), w);
  const double rhs = dec.dot(u, dec.interior(u_adj)) + dec.dot(v, dec.interior(v_adj));
  CHECK(std::abs(lhs - rhs) <= 1e-12 * std::abs(lhs));
}

TEST_CASE("3D Laplacian on blocks: values equal the periodic sum; dot-product test") {
  const int nx = 6, ny = 5, nz = 4;
  const double h = 0.5;
  Decomposition dec(MPI_COMM_WORLD, {{nx, ny, nz}, {true, true, true}, {}, 1});
  CAPTURE(dec.where());
  const VectorXd p = random_vector(dec.global_size(), 8);
  // the reference, summed in the kernel's order with wrapped indices
  VectorXd ref(dec.global_size());
  auto at = [&](int i, int j, int k) {
    i = (i + nx) % nx, j = (j + ny) % ny, k = (k + nz) % nz;
    return p[(static_cast<Eigen::Index>(k) * ny + j) * nx + i];
  };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const double sum = at(i + 1, j, k) + at(i - 1, j, k) + at(i, j + 1, k) + at(i, j - 1, k) +
                           at(i, j, k + 1) + at(i, j, k - 1);
        ref[(static_cast<Eigen::Index>(k) * ny + j) * nx + i] = (6.0 * at(i, j, k) - sum) / (h * h);
      }
  VectorXd pp = dec.pad(dec.local_part(p)), out = VectorXd::Zero(dec.padded_size());
  dpgen::mpi::exchange_halos(dec, pp);
  neg_laplacian_halo3d(pp.data(), out.data(), dec.padded(0), dec.padded(1), dec.padded(2), h);
  CHECK(relative_error(dec.interior(out), dec.local_part(ref)) <= 1e-14);

  const VectorXd w = random_vector(dec.interior_size(), 80 + dec.rank());
  const VectorXd seed = dec.pad(w);
  VectorXd p_adj = VectorXd::Zero(dec.padded_size());
  neg_laplacian_halo3d_adjoint(pp.data(), p_adj.data(), seed.data(), dec.padded(0), dec.padded(1),
                               dec.padded(2), h);
  dpgen::mpi::exchange_halos_adjoint(dec, p_adj);
  const double lhs = dec.dot(dec.interior(out), w);
  const double rhs = dec.dot(dec.local_part(p), dec.interior(p_adj));
  CHECK(std::abs(lhs - rhs) <= 1e-12 * std::abs(lhs));
}

TEST_CASE("bad decompositions and sizes are errors naming the rank and what is wrong") {
  const int size = dpgen_mpi_test::world_size();
  // a process grid that does not match the communicator
  std::string e = error_of([&] { Decomposition d(MPI_COMM_WORLD, {{8, 8}, {}, {3, 1}, 1}); });
  CAPTURE(e);
  CHECK(contains(e, "rank "));
  CHECK(contains(e, "process grid 3x1 does not fit the communicator's " + std::to_string(size)));
  // blocks smaller than the halo
  e = error_of([&] { Decomposition d(MPI_COMM_WORLD, {{size}, {}, {}, 2}); });
  CHECK(contains(e, "fewer than the halo width 2"));
  e = error_of([&] { Decomposition d(MPI_COMM_WORLD, {{4, 4, 4, 4}, {}, {}, 1}); });
  CHECK(contains(e, "1 to 3 dimensions"));
  e = error_of([&] { Decomposition d(MPI_COMM_WORLD, {{8, 0}, {}, {}, 1}); });
  CHECK(contains(e, "dimension y has 0 cells"));
  // a field of the wrong size handed to the exchange (the same mistake on every rank)
  Decomposition dec(MPI_COMM_WORLD, {{16}, {true}, {}, 1});
  VectorXd interior_only = VectorXd::Zero(dec.interior_size());
  e = error_of([&] { dpgen::mpi::exchange_halos(dec, interior_only); });
  CAPTURE(e);
  CHECK(contains(e, dec.where() + ": halo exchange: field has " +
                        std::to_string(dec.interior_size()) + " values, expected " +
                        std::to_string(dec.padded_size())));
  e = error_of([&] { dpgen::mpi::exchange_halos_adjoint(dec, interior_only); });
  CHECK(contains(e, "reverse halo exchange: adjoint has"));
  e = error_of([&] { dec.local_part(VectorXd::Zero(15)); });
  CHECK(contains(e, "global vector has 15 values, expected 16 (grid 16)"));
}

TEST_CASE("ranks that disagree on the time loop get an error instead of a deadlock") {
  Decomposition dec(MPI_COMM_WORLD, {{16}, {true}, {}, 1});
  const VectorXd s0 = VectorXd::Ones(dec.interior_size());
  auto step = [&](int, const VectorXd& s, VectorXd& next) { next = s; };
  auto step_adjoint = [&](int, const VectorXd&, const VectorXd& a, VectorXd& s_adj) { s_adj += a; };
  auto loss = [&](int, const VectorXd& s, VectorXd& s_adj) {
    s_adj += s;
    return 0.5 * s.squaredNorm();
  };
  const bool last = dec.rank() == dec.size() - 1;
  const dpgen::CheckpointOptions revolve{dpgen::CheckpointStrategy::revolve, last ? 3 : 4};
  const std::string e = error_of(
      [&] { dpgen::mpi::unrolled_gradient(dec, s0, 10, step, step_adjoint, loss, revolve); });
  if (dec.size() == 1) {
    CHECK(e.empty());
  } else {
    CAPTURE(e);
    CHECK(contains(e, dec.where() +
                          ": checkpoint: the ranks disagree on the time loop: rank 0 "
                          "has 10 steps, Revolve with 4 snapshots, rank " +
                          std::to_string(dec.size() - 1) +
                          " has 10 steps, Revolve with 3 "
                          "snapshots"));
  }
  // agreeing ranks: the loss is summed over them (11 loss terms of |1|^2 / 2 per cell)
  const auto g = dpgen::mpi::unrolled_gradient(dec, s0, 10, step, step_adjoint, loss);
  CHECK(g.loss == 11 * 0.5 * 16);
}
