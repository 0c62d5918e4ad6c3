// Geometric multigrid on 2D cell-centred grids: a V-cycle (damped Jacobi smoothing, bilinear
// prolongation, restriction = its transpose / 4, direct coarse solve) used as the preconditioner
// of conjugate_gradient, forward and backward. Matrix-free: the user's operator kernel is applied
// on every level, with its coefficient averaged 2x2 from the level below. The transfers are dpgen
// kernels (kernels/multigrid_transfer.cpp): link dpgen::kernels to use this header.
#pragma once

#include "dpgen/cg.hpp"
#include "dpgen/error.hpp"
#include "dpgen/parallel.hpp"
#include "kernels.hpp"
#include "multigrid_transfer_adjoint.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace dpgen {

/// The condition on one side of the grid, for the prolongation's ghost cells (the operator
/// kernel applies the same condition on its own). Periodic must be set on both sides of an axis.
enum class Boundary {
  periodic,  ///< wraps around to the other side
  dirichlet, ///< zero value on the boundary face (ghost = -cell)
  neumann,   ///< zero normal derivative (ghost = cell); with no Dirichlet side, A 1 = 0
};

/// The enumerator's name, for messages.
inline const char* to_string(Boundary boundary) {
  switch (boundary) {
  case Boundary::periodic:
    return "periodic";
  case Boundary::dirichlet:
    return "dirichlet";
  case Boundary::neumann:
    return "neumann";
  }
  return "unknown";
}

/// The boundary condition of each side of the grid (west: i = 0, south: j = 0).
struct Boundaries {
  Boundary west = Boundary::periodic;
  Boundary east = Boundary::periodic;
  Boundary south = Boundary::periodic;
  Boundary north = Boundary::periodic;
  /// The same condition on every side.
  static Boundaries all(Boundary b) { return {b, b, b, b}; }
};

/// The operator on one level: y = A_l x on an nx-by-ny row-major grid (cell (i, j) at j*nx + i)
/// of cells of size h, with the level's cell-centred coefficient k. Must assign every cell of y,
/// as a dpgen kernel such as `void neg_div_k_grad(const double* p, const double* k, double* out,
/// int nx, int ny, double h)` does (a function pointer to it converts). Must be symmetric, with a
/// positive diagonal, and a stencil of radius 1 (5 or 9 points): the diagonal is found by probing
/// with colours that rely on it.
using LevelOperator =
    std::function<void(const double* x, const double* k, double* y, int nx, int ny, double h)>;

namespace detail {

// The cells of each probing colour along an axis of n cells: i mod 3, so two neighbours never
// share a colour; on a periodic axis with n mod 3 = 1 the last cell (a neighbour of cell 0, also
// colour 0) takes colour 1 instead, which neither of its neighbours n-2 (colour 2) and 0 has.
// (With n mod 3 = 2 the wrapped pair n-1, 0 has colours 1, 0 already.)
inline std::vector<std::vector<int>> probe_classes(int n, bool periodic) {
  std::vector<std::vector<int>> classes(std::min(n, 3));
  for (int i = 0; i < n; ++i) {
    const bool moved = periodic && n > 3 && n % 3 == 1 && i == n - 1;
    classes[moved ? 1 : i % 3].push_back(i);
  }
  return classes;
}

} // namespace detail

/// diag(A) of a level operator on an nx-by-ny grid, matrix-free by probing: for a stencil of
/// radius 1 (5 or 9 points), A applied to the indicator of one colour class (cells whose colours
/// along x and along y agree, no two of them neighbours) returns A_cc at every cell c of the
/// class. At most 9 operator applications. Also the diagonal a Jacobi-preconditioned CG needs.
namespace detail {

// operator_diagonal into `diagonal`, with `probe` and `column` as work space (nx * ny values
// each, all three distinct; a Multigrid passes its level's scratch vectors, so that its setup
// allocates nothing per level).
inline void probe_diagonal(const LevelOperator& op, const double* k, int nx, int ny, double h,
                           const Boundaries& boundaries, double* probe, double* column,
                           double* diagonal) {
  const Eigen::Index n = static_cast<Eigen::Index>(nx) * ny;
  const auto columns = probe_classes(nx, boundaries.west == Boundary::periodic);
  const auto rows = probe_classes(ny, boundaries.south == Boundary::periodic);
  parallel_chunks(n, [&](Eigen::Index lo, Eigen::Index hi) {
    std::fill(probe + lo, probe + hi, 0.0);
    return 0.0;
  });
  // f(c) for every cell c of a colour class, on every thread for a large grid (by rows)
  const auto for_class = [&](const std::vector<int>& row_class,
                             const std::vector<int>& column_class, auto&& f) {
    const Eigen::Index cells = Eigen::Index(row_class.size()) * Eigen::Index(column_class.size());
    const int row_count = static_cast<int>(row_class.size());
    const int threads = cells * 9 >= kParallelValues ? max_threads() : 1;
#ifdef _OPENMP
#pragma omp parallel for num_threads(threads) schedule(static) if (threads > 1)
#endif
    for (int r = 0; r < row_count; ++r)
      for (int i : column_class)
        f(static_cast<Eigen::Index>(row_class[r]) * nx + i);
    (void)threads;
  };
  for (const auto& row_class : rows)
    for (const auto& column_class : columns) {
      for_class(row_class, column_class, [&](Eigen::Index c) { probe[c] = 1.0; });
      op(probe, k, column, nx, ny, h);
      for_class(row_class, column_class, [&](Eigen::Index c) {
        diagonal[c] = column[c];
        probe[c] = 0.0;
      });
    }
}

} // namespace detail

inline Eigen::VectorXd operator_diagonal(const LevelOperator& op, const Eigen::VectorXd& k, int nx,
                                         int ny, double h, const Boundaries& boundaries) {
  const Eigen::Index n = static_cast<Eigen::Index>(nx) * ny;
  detail::require_size(k.size(), n, "operator_diagonal", "coefficient k");
  Eigen::VectorXd probe(n), column(n), diagonal(n);
  detail::probe_diagonal(op, k.data(), nx, ny, h, boundaries, probe.data(), column.data(),
                         diagonal.data());
  return diagonal;
}

/// Settings of the multigrid hierarchy and its V-cycle.
struct MultigridOptions {
  /// Number of levels including the finest. 0: halve both sides while they are even and the
  /// grid has more than coarse_cells cells.
  int levels = 0;
  /// Automatic coarsening stops at or below this many cells.
  int coarse_cells = 64;
  /// The coarsest grid is solved directly (dense Cholesky); a coarsest grid with more cells than
  /// this is an error (sizes such as 100 = 25 * 4 cannot be halved far enough).
  int max_coarse_cells = 1024;
  /// Damped Jacobi sweeps before and after the coarse-grid correction (the same number on both
  /// sides, so the V-cycle is a symmetric operator).
  int smoothing_sweeps = 2;
  /// Jacobi damping w in x += w D^-1 (b - A x); 4/5 damps the high frequencies of a 5-point
  /// Laplacian best. Must lie in (0, 1].
  double jacobi_weight = 0.8;
  /// Run the operator on horizontal strips of the grid on every thread (dpgen/parallel.hpp:
  /// each strip with one row of its neighbours on either side, whose output is discarded). Right
  /// for any operator whose row j depends only on rows j - 1 .. j + 1 and on whether j is the
  /// first or last row; checked level by level against one whole-grid application (bit for
  /// bit, on a pseudo-random x) when a level is first applied on several threads after a
  /// coefficient is set: a level where they differ runs the operator whole.
  bool parallel_rows = true;
  /// On a level of 512K cells or more (whose vectors do not stay in the caches from one pass to
  /// the next) whose operator gives its bits by row strips (the check of parallel_rows), fuse
  /// each side's sweeps (and, before the coarse-grid correction, the residual) over row strips:
  /// a strip takes its rows with a halo of one row per stencil application, runs every sweep in
  /// the core's cache and writes only its result, so the level is streamed once per side
  /// instead of once per sweep. The halo rows are computed in both strips that need them; every
  /// value is the same expression as unfused, so the V-cycle gives the same bits either way.
  bool fuse_sweeps = true;
  /// Prefix of every error message.
  std::string name = "multigrid";
};

/// A multigrid hierarchy for one operator and one coefficient field, and its V-cycle
/// z = B r. B is symmetric and positive definite whenever A is (positive semi-definite with the
/// constants as null space for periodic / all-Neumann grids, where CG projects them out with
/// CgOptions::remove_null_space_mean), so it preconditions CG:
///
///   dpgen::Multigrid mg(nx, ny, h, dpgen::Boundaries::all(dpgen::Boundary::periodic),
///                       neg_div_k_grad_periodic2d, k);
///   dpgen::CgOptions cg;
///   cg.preconditioner = mg.preconditioner();
///   cg.remove_null_space_mean = mg.constant_null_space();
///   dpgen::solve_forward(mg.fine_operator(), b, cg);   // and solve_backward with the same cg
///
/// The preconditioner and operator returned refer to this object, which must outlive them; a
/// V-cycle uses the object's scratch vectors, so one Multigrid serves one solve at a time.
class Multigrid {
public:
  /// Builds the hierarchy for an nx-by-ny grid of cells of size h and the coefficient k
  /// (nx*ny cell values). Throws std::invalid_argument for bad input, sizes that cannot be
  /// coarsened to a small enough grid, and operators that are not symmetric or have a
  /// non-positive diagonal.
  Multigrid(int nx, int ny, double h, Boundaries boundaries, LevelOperator op,
            const Eigen::VectorXd& k, MultigridOptions options = {})
      : boundaries_(boundaries), op_(std::move(op)), options_(std::move(options)) {
    check_input(nx, ny, h);
    build_levels(nx, ny, h);
    set_coefficient(k);
  }

  /// Redoes the setup for a new coefficient on the same grid (coarse coefficients, diagonals,
  /// coarse factorization).
  void set_coefficient(const Eigen::VectorXd& k) {
    Level& fine = levels_.front();
    detail::require_size(k.size(), fine.cells(), options_.name, "coefficient k");
    detail::require_finite(k, options_.name, "coefficient k");
    const double* kin = k.data();
    double* kf = fine.k.data(); // sized by build_levels; copied on every thread
    parallel_chunks(fine.cells(), [&](Eigen::Index lo, Eigen::Index hi) {
      std::copy(kin + lo, kin + hi, kf + lo);
      return 0.0;
    });
    for (std::size_t l = 1; l < levels_.size(); ++l)
      average_2x2(levels_[l - 1], levels_[l]);
    for (Level& level : levels_) // checked when first needed (on more than one thread)
      level.strips = options_.parallel_rows ? Strips::unchecked : Strips::no;
    for (std::size_t l = 0; l + 1 < levels_.size(); ++l)
      set_smoother(static_cast<int>(l));
    factor_coarsest();
  }

  /// True when level l may apply the operator by row strips in parallel: the check found that
  /// they give the whole grid's bits (see MultigridOptions::parallel_rows; false for levels
  /// too small to be split). A level below 64K values runs whole all the same.
  bool parallel_rows(int l) const { return strips_right(levels_.at(l)); }

  /// True when the V-cycle fuses level l's sweeps over row strips (MultigridOptions::fuse_sweeps:
  /// a level of 512K cells or more, with its strips found right; checked on first use).
  bool fuses_sweeps(int l) const { return l + 1 < levels() && use_fused(levels_.at(l)); }

  /// z = B r: one V-cycle for A z = r from z = 0.
  void precondition(const Eigen::VectorXd& r, Eigen::VectorXd& z) {
    detail::require_size(r.size(), levels_.front().cells(), options_.name, "residual");
    z.resize(r.size());
    v_cycle(0, r, z, /*zero_guess=*/true);
  }

  /// x <- x + B (b - A x): one V-cycle from the guess x (multigrid as a stationary solver).
  void cycle(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
    detail::require_size(b.size(), levels_.front().cells(), options_.name, "right-hand side");
    detail::require_size(x.size(), levels_.front().cells(), options_.name, "x");
    v_cycle(0, b, x, /*zero_guess=*/false);
  }

  /// y = A x on the finest grid, with the fine coefficient.
  void apply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
    detail::require_size(x.size(), levels_.front().cells(), options_.name, "x");
    y.resize(x.size());
    apply_level(levels_.front(), x, y);
  }

  /// The V-cycle as CgOptions::preconditioner (refers to this object).
  VectorOperator preconditioner() {
    return [this](const Eigen::VectorXd& r, Eigen::VectorXd& z) { precondition(r, z); };
  }

  /// The fine-grid operator as a VectorOperator for CG (refers to this object).
  VectorOperator fine_operator() const {
    return [this](const Eigen::VectorXd& x, Eigen::VectorXd& y) { apply(x, y); };
  }

  /// Number of levels, the finest included.
  int levels() const { return static_cast<int>(levels_.size()); }
  /// Cells along x and y on level l (0 = finest).
  int level_nx(int l) const { return levels_.at(l).nx; }
  int level_ny(int l) const { return levels_.at(l).ny; }
  /// True when the operator annihilates the constants (periodic or all-Neumann, no reaction
  /// term), as measured on the coarsest level: set CgOptions::remove_null_space_mean then.
  bool constant_null_space() const { return null_space_; }

private:
  enum class Strips { unchecked, yes, no };
  struct Level {
    int nx = 0, ny = 0;
    double h = 0.0;
    Eigen::VectorXd k;        // coefficient, averaged 2x2 from the finer level
    Eigen::VectorXd smoother; // w / diag(A): one Jacobi sweep is x += smoother .* (b - A x)
    Eigen::VectorXd b, x;     // right-hand side and correction (coarse levels)
    Eigen::VectorXd scratch;  // A x, residuals, prolonged corrections
    Eigen::VectorXd next;     // the other iterate of the smoothing sweeps (they alternate)
    Eigen::VectorXd transfer; // 2nx-by-ny: between the x and y passes of P and R = P^T / 4
    mutable Strips strips = Strips::unchecked; // does the operator give its bits by row strips
    Eigen::Index cells() const { return static_cast<Eigen::Index>(nx) * ny; }
  };

  // Ghost weights of the prolongation kernels: ghost = self * (edge cell) + wrap * (other end).
  struct Ghost {
    double self, wrap;
  };
  static Ghost ghost(Boundary b) {
    switch (b) {
    case Boundary::periodic:
      return {0.0, 1.0};
    case Boundary::neumann:
      return {1.0, 0.0};
    case Boundary::dirichlet:
      return {-1.0, 0.0};
    }
    return {0.0, 0.0};
  }

  void check_input(int nx, int ny, double h) const {
    const std::string& where = options_.name;
    if (nx < 1 || ny < 1)
      throw std::invalid_argument(detail::message(where, ": grid of ", nx, "x", ny, " cells"));
    if (!(h > 0.0) || !std::isfinite(h))
      throw std::invalid_argument(detail::message(where, ": cell size h = ", h, " is not > 0"));
    if (!op_)
      throw std::invalid_argument(detail::message(where, ": no level operator given"));
    if ((boundaries_.west == Boundary::periodic) != (boundaries_.east == Boundary::periodic) ||
        (boundaries_.south == Boundary::periodic) != (boundaries_.north == Boundary::periodic))
      throw std::invalid_argument(detail::message(
          where, ": periodic must be set on both sides of an axis (west ",
          to_string(boundaries_.west), ", east ", to_string(boundaries_.east), ", south ",
          to_string(boundaries_.south), ", north ", to_string(boundaries_.north), ")"));
    if (options_.levels < 0 || options_.coarse_cells < 1 || options_.max_coarse_cells < 1)
      throw std::invalid_argument(detail::message(
          where, ": levels must be >= 0 and coarse_cells, max_coarse_cells >= 1 (got ",
          options_.levels, ", ", options_.coarse_cells, ", ", options_.max_coarse_cells, ")"));
    if (options_.smoothing_sweeps < 1)
      throw std::invalid_argument(detail::message(where, ": smoothing_sweeps must be >= 1 (got ",
                                                  options_.smoothing_sweeps, ")"));
    if (!(options_.jacobi_weight > 0.0 && options_.jacobi_weight <= 1.0))
      throw std::invalid_argument(detail::message(where, ": jacobi_weight must lie in (0, 1] (got ",
                                                  options_.jacobi_weight, ")"));
  }

  // Halves both sides level by level: while the grid is larger than coarse_cells (or, with
  // options.levels set, until that many levels exist), as long as both sides are even.
  void build_levels(int nx, int ny, double h) {
    const std::string& where = options_.name;
    const int wanted = options_.levels;
    levels_.clear();
    Level fine;
    fine.nx = nx, fine.ny = ny, fine.h = h;
    levels_.push_back(fine);
    for (;;) {
      const Level& last = levels_.back();
      const bool more = wanted > 0 ? levels() < wanted : last.cells() > options_.coarse_cells;
      if (!more)
        break;
      if (last.nx % 2 != 0 || last.ny % 2 != 0) {
        if (wanted > 0)
          throw std::invalid_argument(detail::message(where, ": cannot build ", wanted,
                                                      " levels from ", nx, "x", ny, ": level ",
                                                      levels() - 1, " has ", last.nx, "x", last.ny,
                                                      " cells and an odd side cannot be halved"));
        break;
      }
      Level coarse;
      coarse.nx = last.nx / 2, coarse.ny = last.ny / 2, coarse.h = 2.0 * last.h;
      levels_.push_back(coarse);
    }
    const Level& coarsest = levels_.back();
    if (coarsest.cells() > options_.max_coarse_cells)
      throw std::invalid_argument(detail::message(
          where, ": the ", nx, "x", ny, " grid coarsens to ", coarsest.nx, "x", coarsest.ny,
          " cells (", levels(),
          " levels), more than max_coarse_cells = ", options_.max_coarse_cells,
          " for the direct coarse solve; use sides m * 2^L with small m (e.g. powers of two)"));
    for (std::size_t l = 0; l < levels_.size(); ++l) {
      Level& level = levels_[l];
      level.k.resize(level.cells());
      level.scratch.resize(level.cells());
      if (l + 1 < levels_.size())
        level.next.resize(level.cells());
      if (l > 0) {
        level.b.resize(level.cells());
        level.x.resize(level.cells());
        level.transfer.resize(2 * level.cells());
      }
    }
  }

  // y = A_l x: by row strips on every thread where they were found right, else in one call.
  void apply_level(const Level& level, const double* x, double* y) const {
    if (!use_strips(level) || !apply_by_strips(level, x, y, /*force=*/false))
      op_(x, level.k.data(), y, level.nx, level.ny, level.h);
  }

  // On several threads, where the level's strips were found right (checked on first use).
  bool use_strips(const Level& level) const {
    return level.strips != Strips::no && detail::max_threads() > 1 && strips_right(level);
  }

  // Whether the operator gives the whole grid's bits by row strips on this level, checked once
  // per coefficient (false for a level too small to be split).
  bool strips_right(const Level& level) const {
    if (level.strips == Strips::unchecked) {
      Eigen::VectorXd x(level.cells()), whole(level.cells()), strips(level.cells());
      level.strips =
          strips_match(level, x.data(), whole.data(), strips.data()) ? Strips::yes : Strips::no;
    }
    return level.strips == Strips::yes;
  }
  void apply_level(const Level& level, const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
    apply_level(level, x.data(), y.data());
  }

  bool apply_by_strips(const Level& level, const double* x, double* y, bool force) const {
    return apply_by_strips_then(
        level, x,
        [y](Eigen::Index first, Eigen::Index count, const double* ax) {
          std::memcpy(y + first, ax, sizeof(double) * count);
        },
        force);
  }

  // The operator on row strips (dpgen/parallel.hpp), each strip's A x handed to store(first,
  // count, ax) while it is in the core's cache.
  template <typename Store>
  bool apply_by_strips_then(const Level& level, const double* x, Store&& store, bool force) const {
    const RowStripShape shape{level.ny, level.nx, level.nx, 1,
                              boundaries_.south == Boundary::periodic};
    return for_row_strips<2>(
        shape, {x, level.k.data()},
        [&](const std::array<const double*, 2>& in, double* out, int rows) {
          op_(in[0], in[1], out, level.nx, rows, level.h);
        },
        store, force);
  }

  // store(first, count, ax) over every cell, ax = (A_l x)[first, first + count): by row strips
  // where apply_level would use them (each strip's A x from the cache), else after one
  // application into level.scratch, in chunks on every thread. store may write level.scratch
  // at the cells it is given (the residual does), nothing else it reads.
  template <typename Store> void apply_level_then(Level& level, const double* x, Store&& store) {
    if (use_strips(level) && apply_by_strips_then(level, x, store, /*force=*/false))
      return;
    op_(x, level.k.data(), level.scratch.data(), level.nx, level.ny, level.h);
    const double* ax = level.scratch.data();
    parallel_chunks(level.cells(), [&](Eigen::Index lo, Eigen::Index hi) {
      store(lo, hi - lo, ax + lo);
      return 0.0;
    });
  }

  // One whole-grid application against one by strips, on a pseudo-random x (x, whole and
  // strips: work space of level.cells() values each).
  bool strips_match(const Level& level, double* xs, double* whole, double* ss) const {
    const Eigen::Index n = level.cells();
    parallel_chunks(n, [&](Eigen::Index lo, Eigen::Index hi) {
      for (Eigen::Index c = lo; c < hi; ++c) {
        // a fixed pseudo-random x: splitmix64, its state after c + 1 steps from the seed
        std::uint64_t z = 0x9e3779b97f4a7c15ULL * static_cast<std::uint64_t>(c + 2);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        xs[c] = static_cast<double>((z ^ (z >> 31)) >> 11) * 0x1.0p-53 - 0.5;
        ss[c] = std::numeric_limits<double>::quiet_NaN(); // a row never written shows
      }
      return 0.0;
    });
    op_(xs, level.k.data(), whole, level.nx, level.ny, level.h);
    return apply_by_strips(level, xs, ss, /*force=*/true) &&
           std::memcmp(whole, ss, sizeof(double) * n) == 0;
  }

  // The coarse coefficient: mg_average_2x2 by row strips (coarse row jc reads fine rows 2 jc and
  // 2 jc + 1: one input row of 4 nx_coarse values).
  void average_2x2(const Level& fine, Level& coarse) const {
    const int nxc = coarse.nx;
    const auto average = [&](const std::array<const double*, 1>& in, double* out, int rows) {
      mg_average_2x2(in[0], out, nxc, rows);
    };
    if (!run_by_row_strips<1>({coarse.ny, 4 * Eigen::Index(nxc), nxc, 1, false}, {fine.k.data()},
                              coarse.k.data(), average))
      average({fine.k.data()}, coarse.k.data(), coarse.ny);
  }

  // smoother = w / diag(A), diag(A) > 0 checked; probed with the level's own application.
  void set_smoother(int l) {
    Level& level = levels_[l];
    const LevelOperator apply = [&](const double* x, const double*, double* y, int, int, double) {
      apply_level(level, x, y);
    };
    level.smoother.resize(level.cells());
    double* smoother = level.smoother.data();
    // the row strips' check (on several threads, or for the fused sweeps) with the level's
    // vectors, free during setup
    if (level.strips == Strips::unchecked && (detail::max_threads() > 1 || fusable(level)))
      level.strips = strips_match(level, level.next.data(), level.scratch.data(), smoother)
                         ? Strips::yes
                         : Strips::no;
    // the diagonal into level.smoother (probes in next, A probe in scratch)
    detail::probe_diagonal(apply, level.k.data(), level.nx, level.ny, level.h, boundaries_,
                           level.next.data(), level.scratch.data(), smoother);
    const auto bad = [](double d) { return !(d > 0.0) || !std::isfinite(d); };
    const double bad_cells = parallel_chunks(level.cells(), [&](Eigen::Index lo, Eigen::Index hi) {
      double count = 0.0;
      for (Eigen::Index c = lo; c < hi; ++c)
        count += bad(smoother[c]) ? 1.0 : 0.0;
      return count;
    });
    if (bad_cells > 0.0) // the first such cell, for the message
      for (int j = 0; j < level.ny; ++j)
        for (int i = 0; i < level.nx; ++i) {
          const double d = smoother[j * level.nx + i];
          if (bad(d))
            throw std::invalid_argument(detail::message(
                options_.name, ": the operator's diagonal is ", d, " at cell (", i, ", ", j,
                ") of level ", l, " (", level.nx, "x", level.ny,
                "); Jacobi smoothing needs a positive diagonal (negate a Laplacian; k must be > "
                "0)"));
        }
    const double weight = options_.jacobi_weight; // smoother = w / diag(A)
    parallel_chunks(level.cells(), [&](Eigen::Index lo, Eigen::Index hi) {
      for (Eigen::Index c = lo; c < hi; ++c)
        smoother[c] = weight * (1.0 / smoother[c]);
      return 0.0;
    });
  }

  // The coarsest operator as a dense matrix (one probe per cell), checked for symmetry, then
  // factored. With the constants as null space (A 1 = 0) the factored matrix is A + s 1 1^T,
  // s > 0: it is SPD, and for mean-free b its solution is the mean-free A^+ b.
  void factor_coarsest() {
    Level& level = levels_.back();
    const Eigen::Index n = level.cells();
    Eigen::MatrixXd a(n, n);
    Eigen::VectorXd unit = Eigen::VectorXd::Zero(n);
    for (Eigen::Index c = 0; c < n; ++c) {
      unit[c] = 1.0;
      apply_level(level, unit, level.scratch);
      a.col(c) = level.scratch;
      unit[c] = 0.0;
    }
    const std::string& where = options_.name;
    if (!a.allFinite())
      throw std::invalid_argument(
          detail::message(where, ": the operator returned NaN or Inf on the coarsest level (",
                          level.nx, "x", level.ny, ")"));
    const double scale = a.cwiseAbs().maxCoeff();
    const double asymmetry = (a - a.transpose()).cwiseAbs().maxCoeff();
    if (asymmetry > 1e-10 * scale)
      throw std::invalid_argument(detail::message(
          where, ": the operator is not symmetric on the coarsest level (", level.nx, "x", level.ny,
          "): max |A_ij - A_ji| = ", asymmetry, " against max |A_ij| = ", scale,
          "; CG and this preconditioner need a symmetric operator"));
    null_space_ = (a.rowwise().sum()).cwiseAbs().maxCoeff() <= 1e-10 * scale;
    if (null_space_)
      a.array() += a.diagonal().mean() / static_cast<double>(n); // A + s 1 1^T
    coarse_solver_.compute(a);
    if (coarse_solver_.info() != Eigen::Success)
      throw std::invalid_argument(detail::message(
          where, ": the operator is not positive definite on the coarsest level (", level.nx, "x",
          level.ny, null_space_ ? ", after removing the constants" : "",
          "); a Laplacian must be negated"));
  }

  // One damped Jacobi sweep out of place: to = from + w D^-1 (b - A from), each strip's update
  // made from its A x while that is in the cache. to must not be from: a strip reads its
  // neighbours' rows of from while they are being updated.
  void smooth(Level& level, const Eigen::VectorXd& b, const Eigen::VectorXd& from,
              Eigen::VectorXd& to) {
    assert(&from != &to);
    const double* w = level.smoother.data();
    const double* rhs = b.data();
    const double* xs = from.data();
    double* out = to.data();
    apply_level_then(level, xs, [=](Eigen::Index first, Eigen::Index count, const double* ax) {
      for (Eigen::Index c = 0; c < count; ++c)
        out[first + c] = xs[first + c] + w[first + c] * (rhs[first + c] - ax[c]);
    });
  }

  // The fused sweeps (MultigridOptions::fuse_sweeps) on a level large enough, with strips at
  // least as high as their halo (the applications a run makes: at most m + 1), and its strips
  // found right (checked in the setup, or on first use).
  bool use_fused(const Level& level) const { return fusable(level) && strips_right(level); }
  bool fusable(const Level& level) const {
    // Below 512K cells a level's vectors stay in a 32 MiB L3 from sweep to sweep: fusing would
    // only add the halo's work and copies (measured: 20% slower at 256x256, 10% faster from
    // 1024x1024 on two threads).
    constexpr Eigen::Index kFusedCells = Eigen::Index(1) << 19;
    if (!options_.fuse_sweeps || !options_.parallel_rows || level.cells() < kFusedCells)
      return false;
    const int halo = options_.smoothing_sweeps + 1, height = fused_height(level);
    return height >= halo && height + 2 * halo <= level.ny;
  }

  // Rows per fused strip: about kFusedValues values (the strip's iterates, its A x and the
  // streamed rows of b, w and k stay in L2), two or more strips per thread where the grid has
  // the rows, at least 8.
  static int fused_height(const Level& level) {
    constexpr Eigen::Index kFusedValues = 65536;
    const int threads = detail::max_threads();
    return static_cast<int>(std::max<Eigen::Index>(
        8, std::min<Eigen::Index>(kFusedValues / level.nx, level.ny / (2 * threads))));
  }

  // What a fused run computes on every row strip: from x_0 (`guess`, or x_0 = 0 when null, whose
  // first sweep is x_1 = w D^-1 b), `sweeps` damped Jacobi sweeps into `x`, then (where
  // `residual` is not null) b - A x into it. x must not be guess: the strips read their
  // neighbours' rows of the guess while those are written.
  struct FusedRun {
    const double* guess;
    int sweeps;
    double* x;
    double* residual;
  };

  // One strip's iterates and A x, per thread (kept: no allocation once the sizes were seen).
  struct FusedBuffers {
    std::vector<double> x, y, ax, k;
  };
  static FusedBuffers& fused_buffers() {
    thread_local FusedBuffers buffers;
    return buffers;
  }

  // The fused run on rows [a, b) of the level. The strip holds rows [a - halo, b + halo) (cut at
  // a closed grid's first and last row; wrapped on a periodic one), halo = the stencil
  // applications the run makes; each application is valid one row further in on each side (the
  // operator treats the strip's first and last row as boundary rows), except at a closed grid's
  // own first and last row, so the last one is valid on [a, b) (or wider, near such a row).
  void fused_strip(const Level& level, const double* rhs, const FusedRun& run, int a, int b,
                   FusedBuffers& buffers) const {
    const Eigen::Index nx = level.nx;
    const int rows = level.ny;
    const bool periodic = boundaries_.south == Boundary::periodic;
    const int applications = run.sweeps - (run.guess ? 0 : 1) + (run.residual ? 1 : 0);
    int lo = a - applications, hi = b + applications; // rows of the strip; r is grid row g(r)
    if (!periodic)
      lo = std::max(lo, 0), hi = std::min(hi, rows);
    assert(hi - lo <= rows);
    const bool in_place = lo >= 0 && hi <= rows; // else rows of the other end wrap in
    const auto g = [rows](int r) {
      return Eigen::Index(r < 0 ? r + rows : r >= rows ? r - rows : r);
    };
    const std::size_t values = static_cast<std::size_t>((hi - lo) * nx);
    buffers.x.resize(values), buffers.y.resize(values), buffers.ax.resize(values);
    double* spare[2] = {buffers.x.data(), buffers.y.data()}; // the iterates, alternating
    int next = 0;
    double* ax = buffers.ax.data();
    const double* w = level.smoother.data();
    const double* k = nullptr; // the strip's coefficient rows, row r at k + (r - lo) * nx
    if (in_place) {
      k = level.k.data() + Eigen::Index(lo) * nx;
    } else {
      buffers.k.resize(values);
      for (int r = lo; r < hi; ++r)
        std::memcpy(buffers.k.data() + (r - lo) * nx, level.k.data() + g(r) * nx,
                    sizeof(double) * nx);
      k = buffers.k.data();
    }
    const double* x = nullptr; // the iterate, row r at x + (r - lo) * nx
    if (run.guess && in_place) {
      x = run.guess + Eigen::Index(lo) * nx;
    } else { // x_0 copied, or x_1 = w D^-1 b from x_0 = 0
      double* x0 = spare[next];
      next ^= 1;
      for (int r = lo; r < hi; ++r) {
        double* row_out = x0 + (r - lo) * nx;
        const Eigen::Index row = g(r) * nx;
        if (run.guess)
          std::memcpy(row_out, run.guess + row, sizeof(double) * nx);
        else
          for (Eigen::Index i = 0; i < nx; ++i)
            row_out[i] = w[row + i] * rhs[row + i];
      }
      x = x0;
    }
    int v0 = lo, v1 = hi; // the rows where x holds the iterate
    // A x on the rows where it is valid, which become [v0, v1)
    const auto apply = [&] {
      const Eigen::Index first = (v0 - lo) * nx;
      op_(x + first, k + first, ax + first, level.nx, v1 - v0, level.h);
      v0 += periodic || v0 > 0 ? 1 : 0;
      v1 -= periodic || v1 < rows ? 1 : 0;
    };
    bool stored = false; // x's rows [a, b) are in run.x
    for (int s = run.guess ? 0 : 1; s < run.sweeps; ++s) {
      apply();
      // the last sweep before no residual is valid on [a, b) and goes to run.x directly
      stored = s + 1 == run.sweeps && !run.residual;
      double* y = spare[next];
      next ^= 1;
      for (int r = v0; r < v1; ++r) {
        const Eigen::Index local = (r - lo) * nx, row = g(r) * nx;
        double* out = stored ? run.x + row : y + local;
        for (Eigen::Index i = 0; i < nx; ++i)
          out[i] = x[local + i] + w[row + i] * (rhs[row + i] - ax[local + i]);
      }
      x = y;
    }
    if (!stored)
      std::memcpy(run.x + Eigen::Index(a) * nx, x + (a - lo) * nx, sizeof(double) * (b - a) * nx);
    if (run.residual) {
      apply();
      for (int r = a; r < b; ++r) {
        const Eigen::Index local = (r - lo) * nx, row = Eigen::Index(r) * nx;
        for (Eigen::Index i = 0; i < nx; ++i)
          run.residual[row + i] = rhs[row + i] - ax[local + i];
      }
    }
    assert(v0 <= a && v1 >= b); // (wider where a closed grid's own first or last row is near)
  }

  // The fused run on every row strip of the level (fused_height), on every thread.
  void fused_sweeps(const Level& level, const Eigen::VectorXd& b, const FusedRun& run) const {
    const int rows = level.ny, threads = detail::max_threads();
    const int strips = std::max(1, rows / fused_height(level));
    const double* rhs = b.data();
#ifdef _OPENMP
#pragma omp parallel num_threads(threads) if (threads > 1)
#endif
    {
      FusedBuffers& buffers = fused_buffers();
#ifdef _OPENMP
#pragma omp for schedule(static)
#endif
      for (int s = 0; s < strips; ++s)
        fused_strip(level, rhs, run, static_cast<int>(Eigen::Index(rows) * s / strips),
                    static_cast<int>(Eigen::Index(rows) * (s + 1) / strips), buffers);
    }
  }

  // R r = P^T r / 4: the generated adjoints of the two prolongation passes, in reverse order
  // (P = P_y P_x, so P^T = P_x^T P_y^T). Adjoints accumulate, hence the zero fills.
  void restrict_residual(const Eigen::VectorXd& r, Level& coarse) const {
    const Ghost s = ghost(boundaries_.south), n = ghost(boundaries_.north);
    const Ghost w = ghost(boundaries_.west), e = ghost(boundaries_.east);
    // The adjoints of these linear kernels never read their primal input; they get the
    // buffer they accumulate into as a stand-in of the right size.
    fill_zero(coarse.transfer);
    mg_prolong_y_adjoint(coarse.transfer.data(), coarse.transfer.data(), r.data(), coarse.nx,
                         coarse.ny, s.self, s.wrap, n.self, n.wrap);
    fill_zero(coarse.b);
    mg_prolong_x_adjoint(coarse.b.data(), coarse.b.data(), coarse.transfer.data(), coarse.nx,
                         coarse.ny, w.self, w.wrap, e.self, e.wrap);
    double* cb = coarse.b.data(); // a coarse level: a quarter of the cells
    parallel_chunks(coarse.cells(), [&](Eigen::Index lo, Eigen::Index hi) {
      for (Eigen::Index c = lo; c < hi; ++c)
        cb[c] *= 0.25;
      return 0.0;
    });
  }

  static void fill_zero(Eigen::VectorXd& v) {
    double* p = v.data();
    parallel_chunks(v.size(), [&](Eigen::Index lo, Eigen::Index hi) {
      std::fill(p + lo, p + hi, 0.0);
      return 0.0;
    });
  }

  // to = from + P x_coarse (bilinear, ghosts from the boundary conditions; to may be from). The
  // two kernels run by row strips (dpgen/parallel.hpp): mg_prolong_x acts on each row alone,
  // mg_prolong_y writes fine rows 2 jc, 2 jc + 1 from coarse rows jc - 1 .. jc + 1, as that
  // needs; each strip of P x_coarse is added from the cache.
  void add_prolonged(Level& coarse, Level& fine, const Eigen::VectorXd& from,
                     Eigen::VectorXd& to) const {
    const Ghost s = ghost(boundaries_.south), n = ghost(boundaries_.north);
    const Ghost w = ghost(boundaries_.west), e = ghost(boundaries_.east);
    const int nxc = coarse.nx, nyc = coarse.ny;
    const auto prolong_x = [&](const std::array<const double*, 1>& in, double* out, int rows) {
      mg_prolong_x(in[0], out, nxc, rows, w.self, w.wrap, e.self, e.wrap);
    };
    if (!run_by_row_strips<1>({nyc, nxc, 2 * nxc, 1, false}, {coarse.x.data()},
                              coarse.transfer.data(), prolong_x))
      prolong_x({coarse.x.data()}, coarse.transfer.data(), nyc);
    const auto prolong_y = [&](const std::array<const double*, 1>& in, double* out, int rows) {
      mg_prolong_y(in[0], out, nxc, rows, s.self, s.wrap, n.self, n.wrap);
    };
    const double* xs = from.data();
    double* out = to.data();
    const auto add = [=](Eigen::Index first, Eigen::Index count, const double* p) {
      for (Eigen::Index c = 0; c < count; ++c)
        out[first + c] = xs[first + c] + p[c];
    };
    if (for_row_strips<1>({nyc, 2 * nxc, 2 * nxc, 2, boundaries_.south == Boundary::periodic},
                          {coarse.transfer.data()}, prolong_y, add))
      return;
    prolong_y({coarse.transfer.data()}, fine.scratch.data(), nyc);
    const double* p = fine.scratch.data();
    parallel_chunks(fine.cells(), [&](Eigen::Index lo, Eigen::Index hi) {
      add(lo, hi - lo, p + lo);
      return 0.0;
    });
  }

  // The V-cycle on level l for A_l x = b:
  //   x <- S^m x                      m damped Jacobi sweeps (from x = 0: x = w D^-1 b first)
  //   x <- x + P B_{l+1} R (b - A x)  coarse-grid correction, B_{l+1} the next level's V-cycle
  //   x <- S^m x                      the same sweeps again
  // and a direct solve on the coarsest level. With S self-adjoint (Jacobi), R = P^T / 4 and
  // B_{l+1} symmetric, the map b -> x from x = 0 is symmetric: a valid CG preconditioner.
  //
  // The sweeps alternate between x and level.next (each is out of place, so that a strip's
  // update can be made from its A x in the cache), arranged so that the last one writes x.
  void v_cycle(int l, const Eigen::VectorXd& b, Eigen::VectorXd& x, bool zero_guess) {
    Level& level = levels_[l];
    if (l == levels() - 1) {
      if (zero_guess) {
        x = coarse_solver_.solve(b);
      } else {
        apply_level(level, x, level.scratch);
        x += coarse_solver_.solve(b - level.scratch);
      }
      return;
    }
    const int m = options_.smoothing_sweeps;
    if (use_fused(level)) { // the same steps, each side's sweeps in one pass over the grid
      Level& coarse = levels_[l + 1];
      fused_sweeps(level, b,
                   {zero_guess ? nullptr : x.data(), m, level.next.data(), level.scratch.data()});
      restrict_residual(level.scratch, coarse);
      v_cycle(l + 1, coarse.b, coarse.x, /*zero_guess=*/true);
      add_prolonged(coarse, level, level.next, level.next);
      fused_sweeps(level, b, {level.next.data(), m, x.data(), nullptr});
      return;
    }
    Eigen::VectorXd* from = &x;
    Eigen::VectorXd* to = &level.next;
    const auto sweep = [&] {
      smooth(level, b, *from, *to);
      std::swap(from, to);
    };
    for (int s = 0; s < m; ++s) {
      if (s == 0 && zero_guess) {
        const double* w = level.smoother.data();
        const double* rhs = b.data();
        double* xs = from->data();
        parallel_chunks(x.size(), [&](Eigen::Index lo, Eigen::Index hi) {
          for (Eigen::Index c = lo; c < hi; ++c)
            xs[c] = w[c] * rhs[c];
          return 0.0;
        });
      } else {
        sweep();
      }
    }
    Level& coarse = levels_[l + 1];
    {
      const double* rhs = b.data();
      double* r = level.scratch.data();
      apply_level_then(level, from->data(),
                       [=](Eigen::Index first, Eigen::Index count, const double* ax) {
                         for (Eigen::Index c = first; c < first + count; ++c)
                           r[c] = rhs[c] - ax[c - first]; // r = b - A x
                       });
    }
    restrict_residual(level.scratch, coarse);
    v_cycle(l + 1, coarse.b, coarse.x, /*zero_guess=*/true);
    // the corrected iterate where the m sweeps after it end in x
    Eigen::VectorXd* corrected = m % 2 == 0 ? &x : &level.next;
    add_prolonged(coarse, level, *from, *corrected);
    from = corrected;
    to = corrected == &x ? &level.next : &x;
    for (int s = 0; s < m; ++s)
      sweep();
  }

  Boundaries boundaries_;
  LevelOperator op_;
  MultigridOptions options_;
  std::vector<Level> levels_;
  Eigen::LLT<Eigen::MatrixXd> coarse_solver_;
  bool null_space_ = false;
};

} // namespace dpgen
