// Halo exchange on a block decomposition, and its adjoint: the exchange copies neighbours'
// cells into the halos; its transpose sends the halos' adjoints back and adds them into the
// owners' cells.
#pragma once

#include "dpgen/mpi/decomposition.hpp"

#include <Eigen/Core>
#include <mpi.h>

#include <algorithm>
#include <array>
#include <vector>

namespace dpgen::mpi {

// The maths. The exchange is a linear map E on padded arrays: every halo cell h that has a
// neighbour becomes a copy of the cell c(h) it mirrors on the neighbouring block, every other
// value is kept:
//   (E a)[h] = a[c(h)],   (E a)[c] = a[c]  (own cells, and halos at non-periodic edges).
// Its transpose, applied to adjoints, is therefore
//   a_adj[c(h)] += a_adj[h],  then  a_adj[h] = 0,
// for every such halo cell: the reverse exchange sends the halo adjoints to the ranks that own
// the mirrored cells, which ADD them into those cells, and the halos' adjoints are zeroed (a halo
// value is a copy, not a variable of its own). A kernel's adjoint leaves in the halos the
// contributions of the reads it made there; after exchange_halos_adjoint they sit in the owners'
// cells, where they belong.
//
// E is done one dimension at a time, E = E_z E_y E_x. E_d moves slabs of halo width across the
// faces normal to d; the slabs span the halos of the dimensions done before (so E_y carries the
// x halos with it and the corners come out right) and the own cells of those after. Hence
//   E^T = E_x^T E_y^T E_z^T:
// the reverse exchange runs the dimensions backwards, each step the transpose of its forward
// step. Within one dimension the two directions touch disjoint cells (halos written, own cells
// read, for any block of at least `halo` cells) and commute.

namespace detail {

// A box of a padded array, [lo, hi) per dimension in padded coordinates.
struct Box {
  std::array<int, 3> lo{0, 0, 0}, hi{1, 1, 1};
  Eigen::Index size() const {
    return static_cast<Eigen::Index>(hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]);
  }
};

// Calls fn(run, length) for every x-row of the box: `run` is the row's first index in the
// padded array.
template <typename Fn> void for_each_run(const Decomposition& dec, const Box& b, Fn&& fn) {
  for (int k = b.lo[2]; k < b.hi[2]; ++k)
    for (int j = b.lo[1]; j < b.hi[1]; ++j)
      fn((static_cast<Eigen::Index>(k) * dec.padded(1) + j) * dec.padded(0) + b.lo[0],
         b.hi[0] - b.lo[0]);
}

// The slab exchanged across the faces normal to d, between [lo, hi) in d: halos included in the
// dimensions before d, own cells only in those after.
inline Box slab(const Decomposition& dec, int d, int lo, int hi) {
  Box b;
  for (int e = 0; e < dec.dims(); ++e) {
    if (e < d)
      b.lo[e] = 0, b.hi[e] = dec.padded(e);
    else
      b.lo[e] = dec.halo(), b.hi[e] = dec.halo() + dec.local(e);
  }
  b.lo[d] = lo, b.hi[d] = hi;
  return b;
}

inline void pack(const Decomposition& dec, const double* a, const Box& b,
                 std::vector<double>& buffer) {
  buffer.resize(static_cast<std::size_t>(b.size()));
  double* out = buffer.data();
  for_each_run(dec, b, [&](Eigen::Index run, int n) {
    std::copy_n(a + run, n, out);
    out += n;
  });
}

// a[box] = buffer (add = false) or a[box] += buffer (add = true).
inline void unpack(const Decomposition& dec, double* a, const Box& b,
                   const std::vector<double>& buffer, bool add) {
  const double* in = buffer.data();
  for_each_run(dec, b, [&](Eigen::Index run, int n) {
    if (add)
      for (int i = 0; i < n; ++i)
        a[run + i] += in[i];
    else
      std::copy_n(in, n, a + run);
    in += n;
  });
}

inline void zero(const Decomposition& dec, double* a, const Box& b) {
  for_each_run(dec, b, [&](Eigen::Index run, int n) { std::fill_n(a + run, n, 0.0); });
}

// One face pair of one dimension: `send` (a box of `a`) goes to rank `to`; what comes from rank
// `from` is assigned to (or added into) the box `receive`. MPI_PROC_NULL on either side skips
// that side (a non-periodic edge).
inline void transfer(const Decomposition& dec, double* a, const Box& send, int to,
                     const Box& receive, int from, int tag, bool add, std::vector<double>& out,
                     std::vector<double>& in) {
  if (to != MPI_PROC_NULL)
    pack(dec, a, send, out);
  else
    out.clear();
  in.resize(from != MPI_PROC_NULL ? static_cast<std::size_t>(receive.size()) : 0);
  MPI_Sendrecv(out.data(), static_cast<int>(out.size()), MPI_DOUBLE, to, tag, in.data(),
               static_cast<int>(in.size()), MPI_DOUBLE, from, tag, dec.comm(), MPI_STATUS_IGNORE);
  if (from != MPI_PROC_NULL)
    unpack(dec, a, receive, in, add);
}

inline void require_padded(const Decomposition& dec, const Eigen::VectorXd& a, const char* what) {
  dec.require_size(a.size(), dec.padded_size(), what, "padded block");
}

} // namespace detail

/// Fills the halos of a padded array from the neighbouring blocks (every rank of the
/// decomposition must call it). Halos at non-periodic edges are left as they are.
inline void exchange_halos(const Decomposition& dec, Eigen::VectorXd& a) {
  detail::require_padded(dec, a, "halo exchange: field");
  std::vector<double> out, in;
  const int h = dec.halo();
  for (int d = 0; d < dec.dims(); ++d) {
    const int n = dec.local(d), low = dec.low_neighbour(d), high = dec.high_neighbour(d);
    // my first own cells -> the low neighbour's high halo; mine from the high neighbour
    detail::transfer(dec, a.data(), detail::slab(dec, d, h, 2 * h), low,
                     detail::slab(dec, d, h + n, 2 * h + n), high, 2 * d, false, out, in);
    // my last own cells -> the high neighbour's low halo; mine from the low neighbour
    detail::transfer(dec, a.data(), detail::slab(dec, d, n, n + h), high,
                     detail::slab(dec, d, 0, h), low, 2 * d + 1, false, out, in);
  }
}

/// The transpose of exchange_halos on adjoints: every halo adjoint that the forward exchange
/// filled is sent back and ADDED into the owner's cell it mirrors, then zeroed. Call it on an
/// adjoint array after the kernel adjoints have accumulated into it, before reading its interior.
inline void exchange_halos_adjoint(const Decomposition& dec, Eigen::VectorXd& a_adj) {
  detail::require_padded(dec, a_adj, "reverse halo exchange: adjoint");
  std::vector<double> out, in;
  const int h = dec.halo();
  for (int d = dec.dims() - 1; d >= 0; --d) {
    const int n = dec.local(d), low = dec.low_neighbour(d), high = dec.high_neighbour(d);
    // transpose of "my last own cells -> the high neighbour's low halo": my low halo's adjoint
    // goes back to the low neighbour; the high neighbour's comes back into my last own cells.
    const detail::Box low_halo = detail::slab(dec, d, 0, h);
    detail::transfer(dec, a_adj.data(), low_halo, low, detail::slab(dec, d, n, n + h), high,
                     2 * d + 1, true, out, in);
    if (low != MPI_PROC_NULL)
      detail::zero(dec, a_adj.data(), low_halo);
    // transpose of "my first own cells -> the low neighbour's high halo"
    const detail::Box high_halo = detail::slab(dec, d, h + n, 2 * h + n);
    detail::transfer(dec, a_adj.data(), high_halo, high, detail::slab(dec, d, h, 2 * h), low, 2 * d,
                     true, out, in);
    if (high != MPI_PROC_NULL)
      detail::zero(dec, a_adj.data(), high_halo);
  }
}

} // namespace dpgen::mpi
