// Plan (phase 5): the loops of an adjoint, decided before anything is
// printed. For each gather group, or groups fused into one loop, the cell
// box (per layout counter, the bounds of every block's domain shifted to cell
// space), the branch-free interior (inside every bulk block, narrowed so the
// index conditions of its terms are decided there), the edge boxes that may
// reach into the interior (checked at run time), and the parallel test (the
// mixed-radix one-to-one test of affine.hpp). Groups of different inputs fuse
// when they share the nest and cell index and their cell boxes are the same,
// or apart by a constant at each end with the loop around them keeping its
// interior (FusionKey). emit.cpp prints the
// plan: it decides no box, bound, fusion or test, and rewrites no
// expression. Each term's expressions are specialized here to the box the
// plan puts it in (loop_plan.cpp's Specializer); the pass `hoist` (hoist.hpp)
// then moves their loop-invariant subexpressions before the loops, and the
// pass `share` (share.hpp) has the interior compute values its terms read at
// several shifts once per cell of a strip.
#pragma once

#include "affine.hpp"
#include "schedule.hpp"

#include <map>
#include <set>
#include <string>
#include <vector>

namespace dpgen {

/// One end of a cell range: for a lower end the minimum over `parts` of the
/// maximum of each part (an upper end: the maximum of minima). Parts hold no
/// duplicate bound and no two parts are equal, so two ends are equal exactly
/// when they print the same.
struct CellBound {
  std::vector<std::vector<Poly>> parts;
  bool operator==(const CellBound& o) const { return parts == o.parts; }
};

struct CellRange {
  CellBound lo, hi;
  bool operator==(const CellRange& o) const { return lo == o.lo && hi == o.hi; }
};

/// What decides whether gather groups of different inputs run in one loop
/// (plan_adjoint_loops): the loop nest (its index in the kernel) and the
/// memory index of a cell, the same; and the cell boxes, the same, or apart
/// by a constant at each end (`near_boxes`) where the loop around them keeps
/// an interior no edge term reaches into and every group has terms there.
struct FusionKey {
  size_t nest = 0;
  Poly cell;
  std::map<std::string, CellRange> bounds; // layout counter -> cell range
  bool operator==(const FusionKey& o) const {
    return nest == o.nest && cell == o.cell && bounds == o.bounds;
  }
};

/// An edge (non-bulk) block's box in cell space that may overlap the
/// interior: unless it is empty or apart from the interior at run time, every
/// cell is treated as an edge.
struct EdgeReach {
  Box box;                         // all counters of the block
  std::set<std::string> cell_dims; // those of the layout
};

/// A block's term as it is printed in one box of its iterations: its partial,
/// the index of the seed it multiplies and the store's run-time conditions
/// (each as it must hold), with the conditional expressions the box decides
/// folded (an interior loop reads a[i + 1], not a[(i == n - 1) ? 0 : i + 1]).
/// (After the pass `hoist`, the expressions use the plan's hoisted locals;
/// after the pass `share`, an interior term may read a shared value's buffer,
/// `shared0[i - shared0_lo]`, which emit defines in the interior's function.)
struct BoxTerm {
  Box box;
  ExprP partial;
  ExprP seed_index;
  std::vector<ExprP> guards;
  /// The partial, as derived, is the same in every iteration (parameters and
  /// kernel-level locals only): an interior cell factors it out of its sum.
  /// (Decided before hoisting, which makes moved locals kernel-level.)
  bool same_everywhere = false;
  /// An interior term whose partial is factored out of the cell's sum (the
  /// pass `hoist`): its index in CellLoop::factored of its group; else -1.
  int factor = -1;
  /// The partial is -P for the factored P: the seed is subtracted from P's sum.
  bool factor_negated = false;
};

/// A value the interior terms of a cell loop compute at several shifts of
/// the innermost counter (the pass `share`): an interior strip of cells
/// computes it once per iteration into the buffer `name`, whose element 0 is
/// the iteration `lo_name`; the terms read `name[i - lo_name]`.
struct SharedValue {
  std::string name, lo_name;
  ExprP value; // as a term computes it, its locals and counters included
  /// The iterations a cell c reads it at: c + lo ..= c + hi of the innermost
  /// counter, and per other layout counter that it mentions, c + that shift.
  long long lo = 0, hi = 0;
  std::map<std::string, long long> outer;
};

/// One cell loop over one or more gather groups (fused when more than one)
/// that share a layout, over the box around their cell boxes.
struct CellLoop {
  std::vector<const GatherGroup*> groups;
  std::map<std::string, CellRange> bounds; // the cell box, per layout counter
  bool any_bulk = false;                   // some block runs in the interior
  Box interior;                            // cell space
  std::vector<EdgeReach> reaches;
  /// Per group and block (bulk blocks only): the boxes of its iteration
  /// domain that an interior cell's iteration lies in.
  std::vector<std::vector<std::vector<Box>>> interior_boxes;
  /// Per group and block: its first term in each box of its domain (an edge
  /// cell checks which box its iteration lies in) and, for bulk blocks, in
  /// each of its interior boxes.
  std::vector<std::vector<std::vector<BoxTerm>>> edge_terms, interior_terms;
  /// Per group and block: its terms for the cells of an edge row whose
  /// innermost counter lies in the interior's range of it (emit's
  /// `interior_row`): each edge term with what that range decides folded. A box
  /// the range keeps the iteration's innermost counter inside is printed
  /// without that check, one it keeps it outside of is left out, and the term
  /// is specialized to its box narrowed by the range (a wrap in the innermost
  /// counter folds). The same terms in the same order as an edge cell, so the
  /// same sum. Empty for a one-counter layout, without bulk blocks, or where
  /// no term would change: edge rows then run the edge function throughout.
  std::vector<std::vector<std::vector<BoxTerm>>> row_terms;
  /// Per group: the partials that are the same in every iteration, factored
  /// out of an interior cell's sum (the pass `hoist`), in order of first use:
  ///   acc += P * g1; acc += P * g2   ->   s0 += g1; s0 += g2; ... acc += P * s0
  /// (a partial -P subtracts its seed from P's sum: s0 -= g3)
  /// (one multiplication instead of one per term, and a shorter dependence
  /// chain on acc; the sum is the same up to rounding). Only where no bulk
  /// block of the group has a run-time guard (BoxTerm::factor).
  std::vector<std::vector<ExprP>> factored;
  /// The parallel test: a one-dimensional unit-stride layout needs only
  /// enough cells; any other also the mixed-radix conditions, counters in
  /// `radix` order (dim indexes the layout).
  bool unit_1d = false;
  std::vector<RadixStep> radix;
  /// The values an interior strip shares between its cells (the pass
  /// `share`); none: the interior runs cell by cell.
  std::vector<SharedValue> shared;
};

/// Gather groups run in one step: `loops[0]` is the loop over all of them;
/// for fused groups of which some input may be inactive (a null adjoint; a
/// view is always active), `loops[1..]` are the loops of each group alone,
/// run when one is.
struct GatherStep {
  std::vector<CellLoop> loops;
  bool fused() const { return loops.front().groups.size() > 1; }
};

/// A scatter read as printed: its conditions, its partial (never zero) and
/// the index of the element its adjoint adds to.
struct ScatterTerm {
  const ScatterRead* read = nullptr;
  std::vector<PathCond> conds;
  ExprP partial;
  ExprP index;
};

/// A scatter unit's loop as printed: the index of the seed it reads, the
/// store's path and its reads.
struct ScatterLoop {
  const ScatterUnit* unit = nullptr;
  ExprP seed_index;
  std::vector<PathCond> path;
  std::vector<ScatterTerm> reads;
};

/// The loops of one differentiable input, in order: gathers, then scatters.
struct InputLoops {
  std::string array;
  std::vector<GatherStep> gathers;
  std::vector<ScatterLoop> scatters;
};

/// One store of a forward nest as printed: its index, value and path, and in
/// a tangent its tangent (null in other forms; possibly zero()).
struct ForwardStore {
  const Store* store = nullptr;
  ExprP index, value, dot;
  std::vector<PathCond> path;
  ExprP chain; // Store::chain
};

/// Fewer iterations than this run serially in a forward form: a parallel
/// region costs microseconds.
constexpr int kMinParallelIterations = 8192;

/// One nest of a forward form (the tangent; the parallel forward of the torch
/// ops): the kernel's own loops, no index inverted. `parallel`: its outermost
/// loop may run on every thread (with at least kMinParallelIterations
/// iterations in the nest's box): every store sets its element (`=`), and the
/// output rules make each element written by one iteration, whose reads see
/// only what earlier nests wrote. A nest that adds (`+=`, a min/max scan)
/// runs serially.
struct ForwardNest {
  const Nest* nest = nullptr;
  bool parallel = false;
  std::vector<ForwardStore> stores; // the nest's, in order
  /// The loops split where the index conditions of the stores are decided
  /// (peel_forward): per loop, outermost first, the bounds that narrow it to
  /// its interior (the counter at least the maximum of `lo`, below the
  /// minimum of `hi`, and within the loop's own bounds; none: the whole
  /// loop). An iteration whose counters all lie in their interiors runs
  /// `interior_stores`, the stores with those conditions folded: `d[i + 1]`,
  /// not `d[i == n - 1 ? 0 : i + 1]`; a guard that holds there is dropped, a
  /// store whose guard fails there is left out. The innermost loop runs as
  /// edge / interior / edge, an outer one tests its counter. The same
  /// iterations in the same order, so the same results; the interior loop is
  /// branch-free where the source's was not, and the compiler may vectorize
  /// it. Not split (no interior store) when no condition is decided near
  /// the loops' ends, or the innermost loop counts down.
  std::vector<Interval> interior;
  std::vector<ForwardStore> interior_stores;
  bool peeled() const { return !interior_stores.empty(); }
};

/// The loops of a forward form of one kernel, and the loop-invariant
/// subexpressions its printer defines before them (the pass `hoist`).
struct ForwardPlan {
  const Kernel* kernel = nullptr;
  std::vector<ForwardNest> nests;
  std::vector<LocalP> hoisted;
  bool invariants_hoisted = false; // the pass `hoist` ran (once only)
};

/// Phase 5 for the forward forms: the loops of `k` (which must outlive the
/// result).
ForwardPlan plan_forward(const Kernel& k);

/// Splits the loops of each nest of `plan` where the index conditions of its
/// stores are decided away from their ends (ForwardNest::interior). After the tangents are set
/// (ForwardStore::dot: it folds them too), before the pass `hoist`.
void peel_forward(ForwardPlan& plan);

/// The plan emit prints for one kernel (or one stage of a kernel with work
/// arrays).
struct LoopPlan {
  const AdjointPlan* adjoint = nullptr;
  std::vector<InputLoops> inputs;
  std::vector<LoopPlan> stages; // a kernel with work arrays: one per stage
  /// The loop-invariant subexpressions the adjoint defines before its loops
  /// (the pass `hoist`), in order of first use.
  std::vector<LocalP> hoisted;
  bool invariants_hoisted = false; // the pass `hoist` ran (once only)
  /// The kernel's forward loops (the parallel forward of the adjoint files;
  /// a staged adjoint's recompute): top level only.
  ForwardPlan forward;
};

/// Phase 5: the loops of `plan` (which must outlive the result).
LoopPlan plan_loops(const AdjointPlan& plan);

} // namespace dpgen
