// Block decomposition of a 1D, 2D or 3D cell grid over the ranks of an MPI Cartesian
// communicator, each block padded with halo cells: the layout the generated kernels run on
// unchanged (kernels/halo/), plus the copies, gathers and reductions around it.
#pragma once

#include "dpgen/error.hpp"

#include <Eigen/Core>
#include <mpi.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace dpgen::mpi {

/// The grid and how it is cut.
struct DecompositionOptions {
  /// Cells per dimension, x first (1 to 3 entries). Arrays are stored x fastest.
  std::vector<int> global;
  /// Periodic dimensions (one entry per dimension; empty: all periodic). A periodic dimension
  /// wraps its halos around; a non-periodic one leaves the halos at the domain's edges to the
  /// caller (boundary conditions) and the exchange never touches them.
  std::vector<bool> periodic;
  /// Ranks per dimension (one entry per dimension; empty, or a 0 entry: MPI_Dims_create
  /// chooses). Their product must be the communicator's size.
  std::vector<int> processes;
  /// Halo cells on each side of a block in every dimension (>= 1); every block must own at
  /// least that many cells in every dimension.
  int halo = 1;
};

/// The block of one rank: `local(d)` cells starting at global cell `offset(d)` in dimension d.
/// A padded array holds padded(d) = local(d) + 2 halo values per dimension (1 in dimensions the
/// grid does not have), x fastest: cell (i, j, k) of the block is at
///   ((k + halo) padded(1) + (j + halo)) padded(0) + (i + halo).
/// Interior (unpadded) vectors hold the block's own cells in the same order without halos; a
/// global vector holds the whole grid x fastest. Every check that depends on the whole
/// decomposition fails on every rank alike, so no rank is left waiting in a collective; error
/// messages start with where(), "rank R of N (block i,j of PxQ)".
class Decomposition {
public:
  /// Creates the Cartesian communicator (a duplicate of `comm`'s group, ranks not reordered)
  /// and this rank's block. Throws std::invalid_argument for a bad grid, a process grid that
  /// does not match the communicator, or a block smaller than the halo.
  Decomposition(MPI_Comm comm, const DecompositionOptions& options) {
    MPI_Comm_rank(comm, &rank_);
    MPI_Comm_size(comm, &size_);
    dims_ = static_cast<int>(options.global.size());
    halo_ = options.halo;
    const std::string who = detail::message("rank ", rank_, " of ", size_, ": decomposition");
    if (dims_ < 1 || dims_ > 3)
      throw std::invalid_argument(
          detail::message(who, ": the grid needs 1 to 3 dimensions (got ", dims_, ")"));
    if (!options.periodic.empty() && static_cast<int>(options.periodic.size()) != dims_)
      throw std::invalid_argument(detail::message(who, ": ", options.periodic.size(),
                                                  " periodic flags for a ", dims_, "D grid"));
    if (!options.processes.empty() && static_cast<int>(options.processes.size()) != dims_)
      throw std::invalid_argument(detail::message(who, ": ", options.processes.size(),
                                                  " process counts for a ", dims_, "D grid"));
    if (halo_ < 1)
      throw std::invalid_argument(
          detail::message(who, ": the halo width must be >= 1 (got ", halo_, ")"));
    std::array<int, 3> procs{1, 1, 1};
    std::array<int, 3> periods{0, 0, 0};
    for (int d = 0; d < dims_; ++d) {
      global_[d] = options.global[d];
      if (global_[d] < 1)
        throw std::invalid_argument(
            detail::message(who, ": dimension ", axis(d), " has ", global_[d], " cells"));
      periods[d] = options.periodic.empty() || options.periodic[d] ? 1 : 0;
      procs[d] = options.processes.empty() ? 0 : options.processes[d];
      if (procs[d] < 0)
        throw std::invalid_argument(
            detail::message(who, ": ", procs[d], " ranks requested in ", axis(d)));
    }
    long long requested = 1;
    bool all_given = true;
    for (int d = 0; d < dims_; ++d) {
      all_given = all_given && procs[d] > 0;
      requested *= std::max(procs[d], 1);
    }
    if ((all_given && requested != size_) || (!all_given && size_ % requested != 0))
      throw std::invalid_argument(detail::message(who, ": process grid ", grid_string(procs),
                                                  " does not fit the communicator's ", size_,
                                                  " ranks"));
    MPI_Dims_create(size_, dims_, procs.data());
    for (int d = 0; d < dims_; ++d)
      procs_[d] = procs[d];
    // Every block must own at least `halo` cells: its halos are filled from its neighbours'
    // own cells only. The smallest block of dimension d is floor(N / P) wide, the same on
    // every rank, so every rank throws alike.
    for (int d = 0; d < dims_; ++d)
      if (global_[d] / procs_[d] < halo_)
        throw std::invalid_argument(
            detail::message(who, ": ", global_[d], " cells in ", axis(d), " over ", procs_[d],
                            " ranks leaves a block of ", global_[d] / procs_[d],
                            " cells, fewer than the halo "
                            "width ",
                            halo_, " (use fewer ranks in ", axis(d), " or a larger grid)"));
    MPI_Cart_create(comm, dims_, procs.data(), periods.data(), /*reorder=*/0, &cart_);
    MPI_Cart_coords(cart_, rank_, dims_, coords_.data());
    for (int d = 0; d < dims_; ++d) {
      periodic_[d] = periods[d] != 0;
      local_[d] = block_extent(d, coords_[d]);
      offset_[d] = block_offset(d, coords_[d]);
      padded_[d] = local_[d] + 2 * halo_;
      MPI_Cart_shift(cart_, d, 1, &low_[d], &high_[d]);
    }
    where_ = detail::message("rank ", rank_, " of ", size_, " (block ", grid_string(coords_, ","),
                             " of ", grid_string(procs_), ")");
  }

  Decomposition(const Decomposition&) = delete;
  Decomposition& operator=(const Decomposition&) = delete;
  ~Decomposition() {
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (cart_ != MPI_COMM_NULL && !finalized)
      MPI_Comm_free(&cart_);
  }

  /// The Cartesian communicator every collective of the decomposition runs on.
  MPI_Comm comm() const { return cart_; }
  int rank() const { return rank_; }
  int size() const { return size_; }
  /// Number of grid dimensions (1 to 3).
  int dims() const { return dims_; }
  int halo() const { return halo_; }
  /// Cells of the whole grid in dimension d (1 for d >= dims()).
  int global(int d) const { return global_.at(d); }
  /// Cells of this rank's block in dimension d (1 for d >= dims()).
  int local(int d) const { return local_.at(d); }
  /// Global index of the block's first cell in dimension d.
  int offset(int d) const { return offset_.at(d); }
  /// Padded extent local(d) + 2 halo in dimension d (1 for d >= dims()).
  int padded(int d) const { return padded_.at(d); }
  /// Ranks along dimension d, and this rank's position among them.
  int processes(int d) const { return procs_.at(d); }
  int coord(int d) const { return coords_.at(d); }
  bool periodic(int d) const { return periodic_.at(d); }
  /// Neighbour ranks in dimension d (MPI_PROC_NULL at a non-periodic edge).
  int low_neighbour(int d) const { return low_.at(d); }
  int high_neighbour(int d) const { return high_.at(d); }

  Eigen::Index global_size() const { return product(global_); }
  Eigen::Index interior_size() const { return product(local_); }
  Eigen::Index padded_size() const { return product(padded_); }

  /// "rank R of N (block i,j of PxQ)": the prefix of every error message.
  const std::string& where() const { return where_; }

  /// Index in a padded array of the block's cell (i, j, k) (0-based, without halo).
  Eigen::Index padded_index(int i, int j = 0, int k = 0) const {
    const int h = halo_;
    return (static_cast<Eigen::Index>(k + (dims_ > 2 ? h : 0)) * padded_[1] +
            (j + (dims_ > 1 ? h : 0))) *
               padded_[0] +
           (i + h);
  }

  /// Throws (naming this rank) unless `v` has `expected` values.
  void require_size(Eigen::Index actual, Eigen::Index expected, const std::string& what,
                    const char* kind) const {
    if (actual != expected)
      throw std::invalid_argument(detail::message(where_, ": ", what, " has ", actual,
                                                  " values, expected ", expected, " (", kind, " ",
                                                  shape_string(kind), ")"));
  }

  /// The padded array of an interior vector, halos zero.
  Eigen::VectorXd pad(const Eigen::VectorXd& interior) const {
    Eigen::VectorXd padded = Eigen::VectorXd::Zero(padded_size());
    copy_interior(interior, padded, "pad: interior vector");
    return padded;
  }
  /// Writes an interior vector into the interior of an existing padded array (halos kept).
  void copy_interior(const Eigen::VectorXd& interior, Eigen::VectorXd& padded,
                     const std::string& what = "interior vector") const {
    require_size(interior.size(), interior_size(), what, "block");
    require_size(padded.size(), padded_size(), "padded array", "padded block");
    for_each_row([&](Eigen::Index flat, Eigen::Index row) {
      std::copy_n(interior.data() + flat, local_[0], padded.data() + row);
    });
  }
  /// The interior (the block's own cells) of a padded array.
  Eigen::VectorXd interior(const Eigen::VectorXd& padded) const {
    Eigen::VectorXd v(interior_size());
    extract_interior(padded, v);
    return v;
  }
  /// interior = (or += with add) the interior of a padded array, into an existing vector of
  /// interior_size() values (no allocation: for inner loops).
  void extract_interior(const Eigen::VectorXd& padded, Eigen::VectorXd& interior,
                        bool add = false) const {
    require_size(padded.size(), padded_size(), "padded array", "padded block");
    require_size(interior.size(), interior_size(), "interior vector", "block");
    for_each_row([&](Eigen::Index flat, Eigen::Index row) {
      if (add)
        interior.segment(flat, local_[0]) += padded.segment(row, local_[0]);
      else
        interior.segment(flat, local_[0]) = padded.segment(row, local_[0]);
    });
  }

  /// This rank's block of a global vector (no communication).
  Eigen::VectorXd local_part(const Eigen::VectorXd& global) const {
    require_size(global.size(), global_size(), "global vector", "grid");
    Eigen::VectorXd v(interior_size());
    for_each_row([&](Eigen::Index flat, Eigen::Index, int j, int k) {
      const Eigen::Index g =
          (static_cast<Eigen::Index>(offset_[2] + k) * global_[1] + offset_[1] + j) * global_[0] +
          offset_[0];
      std::copy_n(global.data() + g, local_[0], v.data() + flat);
    });
    return v;
  }

  /// The global vector assembled from every rank's interior vector, on every rank (an
  /// all-gather: for output, tests and small grids, not for the inner loop).
  Eigen::VectorXd gather(const Eigen::VectorXd& interior) const {
    require_size(interior.size(), interior_size(), "gather: interior vector", "block");
    std::vector<int> counts(size_), displs(size_);
    const int mine = static_cast<int>(interior_size());
    MPI_Allgather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, cart_);
    for (int r = 1; r < size_; ++r)
      displs[r] = displs[r - 1] + counts[r - 1];
    std::vector<double> all(static_cast<std::size_t>(displs.back() + counts.back()));
    MPI_Allgatherv(interior.data(), mine, MPI_DOUBLE, all.data(), counts.data(), displs.data(),
                   MPI_DOUBLE, cart_);
    Eigen::VectorXd global(global_size());
    for (int r = 0; r < size_; ++r) {
      std::array<int, 3> c{0, 0, 0};
      MPI_Cart_coords(cart_, r, dims_, c.data());
      std::array<int, 3> n{1, 1, 1}, o{0, 0, 0};
      for (int d = 0; d < dims_; ++d)
        n[d] = block_extent(d, c[d]), o[d] = block_offset(d, c[d]);
      const double* src = all.data() + displs[r];
      for (int k = 0; k < n[2]; ++k)
        for (int j = 0; j < n[1]; ++j, src += n[0])
          std::copy_n(src, n[0],
                      global.data() +
                          (static_cast<Eigen::Index>(o[2] + k) * global_[1] + o[1] + j) *
                              global_[0] +
                          o[0]);
    }
    return global;
  }

  /// The sum of one value over the ranks (MPI_Allreduce).
  double sum(double local_value) const {
    double total = 0;
    MPI_Allreduce(&local_value, &total, 1, MPI_DOUBLE, MPI_SUM, cart_);
    return total;
  }
  /// <a, b> of two distributed interior (or any equally distributed) vectors.
  double dot(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const {
    if (a.size() != b.size())
      throw std::invalid_argument(
          detail::message(where_, ": dot of vectors of sizes ", a.size(), " and ", b.size()));
    return sum(a.dot(b));
  }
  /// ||a|| of a distributed vector.
  double norm(const Eigen::VectorXd& a) const { return std::sqrt(sum(a.squaredNorm())); }

  /// Calls fn(flat, row, j, k) for every row (fixed j, k) of the block: `flat` is the row's
  /// first index in an interior vector, `row` in a padded array.
  template <typename Fn> void for_each_row(Fn&& fn) const {
    Eigen::Index flat = 0;
    for (int k = 0; k < local_[2]; ++k)
      for (int j = 0; j < local_[1]; ++j, flat += local_[0]) {
        if constexpr (std::is_invocable_v<Fn, Eigen::Index, Eigen::Index, int, int>)
          fn(flat, padded_index(0, j, k), j, k);
        else
          fn(flat, padded_index(0, j, k));
      }
  }

  /// Cells of the block at position c of dimension d: N = q P + r, the first r blocks get q + 1.
  int block_extent(int d, int c) const {
    const int q = global_[d] / procs_[d], r = global_[d] % procs_[d];
    return q + (c < r ? 1 : 0);
  }
  /// Global index of that block's first cell.
  int block_offset(int d, int c) const {
    const int q = global_[d] / procs_[d], r = global_[d] % procs_[d];
    return c * q + std::min(c, r);
  }

  /// "x", "y" or "z".
  static const char* axis(int d) { return d == 0 ? "x" : d == 1 ? "y" : "z"; }

private:
  Eigen::Index product(const std::array<int, 3>& e) const {
    return static_cast<Eigen::Index>(e[0]) * e[1] * e[2];
  }
  std::string grid_string(const std::array<int, 3>& e, const char* sep = "x") const {
    std::string s;
    for (int d = 0; d < dims_; ++d)
      s += (d ? sep : "") + (e[d] > 0 ? std::to_string(e[d]) : std::string("?"));
    return s;
  }
  std::string shape_string(const char* kind) const {
    const std::string k = kind;
    const std::array<int, 3>& e = k == "grid" ? global_ : k == "block" ? local_ : padded_;
    return grid_string(e);
  }

  int rank_ = 0, size_ = 1, dims_ = 1, halo_ = 1;
  MPI_Comm cart_ = MPI_COMM_NULL;
  std::array<int, 3> global_{1, 1, 1}, procs_{1, 1, 1}, coords_{0, 0, 0};
  std::array<int, 3> local_{1, 1, 1}, offset_{0, 0, 0}, padded_{1, 1, 1};
  std::array<int, 3> low_{MPI_PROC_NULL, MPI_PROC_NULL, MPI_PROC_NULL};
  std::array<int, 3> high_{MPI_PROC_NULL, MPI_PROC_NULL, MPI_PROC_NULL};
  std::array<bool, 3> periodic_{false, false, false};
  std::string where_;
};

} // namespace dpgen::mpi
