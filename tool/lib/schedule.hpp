// Schedule (phase 4): decide, for every read of a differentiable input, where
// its adjoint contribution is summed.
//
// Worked example (the upwind step, seed eq. 17). The forward loop reads d at
// three places per iteration i:  d[i+1], d[i], d[i-1]. Scatter form pushes
// each partial into the cell that was read:
//     for i:  d_adj[i+1] += p1(i)*g[i];  d_adj[i] += p0(i)*g[i];  d_adj[i-1] += ...
// which races as soon as the loop is parallel. Gather form turns it around:
// cell c of d was read as d[i+1] by iteration i = c-1, as d[i] by i = c and
// as d[i-1] by i = c+1, so
//     for c:  d_adj[c] += p1(c-1)*g[c-1] + p0(c)*g[c] + pm(c+1)*g[c+1]
// where each term exists only if its iteration exists (c-1 in the loop's
// domain, the wrap piece not taken, ...). Every cell is written by exactly one
// iteration of the c loop: no atomics, and the loop vectorizes.
//
// Mechanically: an index is piecewise affine in the loop counters
// (index_pieces); its linear part is the array's *layout* (`j*nx + i`), the
// rest decomposes into a per-counter *shift* (`+nx` = one row, j+1) and a
// base. Reads with the same layout and base form a gather group; each
// (store, shift, piece) is a block whose iteration is cell - shift and whose
// iteration domain is the store's path domain intersected with the piece.
// An index that is not piecewise affine (data dependent) cannot be inverted:
// its reads get a scatter unit, run serially.
#pragma once

#include "affine.hpp"
#include "derive.hpp"
#include "ir.hpp"
#include "prove.hpp"

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace dpgen {

/// One store's contribution to a cell: d store.value / d reads, times the
/// output seed.
struct Term {
  const Store* store = nullptr;
  std::set<const Expr*> reads;
  ExprP partial; // never zero(): the schedule drops a read whose partial vanishes
};

/// Terms evaluated at one iteration: iteration = cell - shift.
struct Block {
  std::map<std::string, Poly> shift; // layout counter -> shift
  Domain domain;                     // iteration domain (all counters)
  std::vector<PathCond> guards;      // run-time conditions of the store's path
  std::vector<Term> terms;
  bool bulk = false;   // part of the branch-free interior loop
  std::string comment; // which read this is, for the generated code
};

struct GatherGroup {
  std::string array;
  const Nest* nest = nullptr;
  std::vector<std::pair<std::string, Poly>> layout; // counter -> coefficient, loop order
  Poly base;
  std::vector<std::string> reduced; // counters summed over inside a cell
  std::vector<Block> blocks;
};

struct ScatterRead {
  const Expr* read;
  ExprP partial;               // never zero(), as Term::partial
  std::vector<PathCond> conds; // the read happens only where these hold
};

struct ScatterUnit {
  std::string array;
  const Nest* nest = nullptr;
  const Store* store = nullptr;
  std::vector<ScatterRead> reads;
};

struct Remark {
  SourcePos pos;
  std::string text;
};

struct AdjointPlan;

/// A kernel whose later loop nests read what earlier ones wrote (work arrays)
/// is adjoint nest by nest: a stage is the kernel restricted to one nest, with
/// the work arrays that nest reads as inputs and the others as outputs, and
/// its own plan.
struct Stage {
  std::shared_ptr<const Kernel> kernel;
  std::shared_ptr<const AdjointPlan> plan;
};

struct AdjointPlan {
  const Kernel* kernel = nullptr;
  std::vector<GatherGroup> gathers;
  std::vector<ScatterUnit> scatters;
  std::vector<Remark> remarks;
  std::vector<Stage> stages; // a kernel with work arrays: one per loop nest
};

/// Phase 4. `partials` is derive(k) (derive.hpp): the schedule looks up the
/// partial of each read and adds those of the reads its blocks merge. The
/// stages of a kernel with work arrays are derived and scheduled here, each
/// with a table of its own.
AdjointPlan schedule(const Kernel& k, Partials& partials);

} // namespace dpgen
