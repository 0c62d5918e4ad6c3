// Index analysis: integer expressions as polynomials in the parameters and
// loop variables, conditional indices as pieces, and iteration domains as
// disjoint unions of boxes whose bounds are max/min sets of such polynomials.
//
// Nothing here needs to order symbolic bounds: a bound set {0, n-1} is emitted
// as std::max(0, n - 1) and decided at run time. Only bounds that differ by a
// constant are compared here (to drop dominated bounds and empty boxes).
#pragma once

#include "ir.hpp"
#include "poly.hpp"

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace dpgen {

/// An order of index coefficients by likely size, for mixed-radix tests: by
/// degree, then the magnitude of the highest-degree terms (nx before 2 * nx),
/// then the rest. Only a heuristic: a wrong order makes a test fail, never
/// pass wrongly.
bool smaller_coefficient(const Poly& a, const Poly& b);

/// One counter of a layout `sum_k c_k * x_k` (0 <= x_k < e_k) in mixed-radix
/// order: `dim` indexes the caller's list, `coefficient` is c_k as given,
/// `step` its magnitude (a coefficient whose terms are all negative, as in a
/// mirrored `(ny - 1 - j) * nx`, steps by its negation) and `reach` the largest
/// offset the counters before it reach, the sum of step * (e - 1).
struct RadixStep {
  size_t dim;
  Poly coefficient;
  Poly step;
  Poly reach;
};

/// The mixed-radix one-to-one test, written once: with the counters ordered
/// by coefficient (smaller_coefficient), a layout gives distinct counters
/// distinct offsets when the first step is not zero and every later step
/// exceeds the reach of the ones before it (reach < step). Returns the
/// counters in that order. `dims`: (coefficient, extent) per counter. The
/// lowering proves the conditions for the write-once rule (or checks them on
/// entry); the adjoint prints them as the run-time test of its parallel loops.
std::vector<RadixStep> mixed_radix(std::vector<std::pair<Poly, Poly>> dims);

/// The integer expression as a polynomial, seeing through integer Locals;
/// nullopt when it is not a polynomial (a division, a conditional, a cast).
std::optional<Poly> to_poly(const ExprP& e);

/// Half-open interval max(lo...) <= v < min(hi...); an empty set is unbounded.
struct Interval {
  std::vector<Poly> lo, hi;
};

/// A box: one interval per constrained loop counter.
struct Box {
  std::map<std::string, Interval> dims; // counter name (Loop::var) -> interval
};

/// A disjoint union of boxes (empty vector = empty set).
using Domain = std::vector<Box>;

Domain universe();
Domain intersect(const Domain& a, const Domain& b);
Domain subtract(const Domain& a, const Domain& b);
Domain unite(const Domain& a, const Domain& b); // a ∪ (b \ a), kept disjoint
/// Shifts every box by +delta[v] in each counter v (keyed like Box::dims).
Domain shift(const Domain& d, const std::map<std::string, Poly>& delta);
/// Drops bounds dominated by a constant difference and provably empty boxes.
Box simplify(Box b);

/// The domain of an index condition (comparisons of one loop variable, with
/// coefficient +-1, against parameters, combined by && || !); nullopt for any
/// other condition, which then stays a run-time guard.
std::optional<Domain> condition_domain(const ExprP& cond);
/// The domain of `p op 0` (op a comparison) where p moves with one loop counter by +-1;
/// nullopt for any other p.
std::optional<Domain> zero_compare_domain(const Poly& p, Op op);

/// True when box `b` certainly lies inside `d` / certainly misses `d`,
/// deciding only comparisons that differ by a constant.
bool box_inside(const Box& b, const Domain& d);
bool box_disjoint(const Box& b, const Domain& d);

/// One piece of a piecewise-affine index: `value` where `where` holds.
struct IndexPiece {
  Poly value;
  Domain where;
};

/// The pieces of an integer index expression (conditional expressions on
/// index conditions split it); nullopt when some piece is not a polynomial or
/// a condition is not an index condition (a data-dependent index).
std::optional<std::vector<IndexPiece>> index_pieces(const ExprP& index);

} // namespace dpgen
