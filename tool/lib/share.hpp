// The pass `share` (after hoist, before emit): a value that the interior
// terms of a gather loop compute at several shifts of the innermost counter
// (the upwind adjoint's `u[i] / dx` at i = c_i - 1, c_i and c_i + 1) is
// computed once per iteration of a strip of cells into a buffer, which the
// terms read. The planned terms are rewritten in place (CellLoop::shared);
// emit prints the strips.
#pragma once

#include "loop_plan.hpp"

namespace dpgen {

/// Cells of one strip of the innermost interior loop (emit: a buffer of a
/// shared value holds this many elements and the span of its shifts).
constexpr int kShareStripCells = 256;

/// The pass, for an adjoint's gather loops (each stage's, for a staged
/// adjoint). Why: each recomputation of a division or a math function costs
/// what the forward paid once per iteration (SSE2 divides two doubles at a
/// time, and more slowly than it multiplies), so the upwind adjoint with a
/// CMake Release build's flags was bound by its three divisions per cell.
///
/// What is shared: a subexpression that a term of the interior evaluates
/// unconditionally (not in an arm of a conditional or the right operand of
/// && or ||; in a term under run-time guards, only in the first guard and in
/// the locals the guards use, which emit defines before the guards), that is
/// a real division (not by a power of two: GCC writes that as a product) or a
/// call of a costly math function (sqrt, cbrt, exp, expm1, log, log1p, sin,
/// cos, tanh, atan2, hypot, erf), depends on the iteration only through the
/// layout's counters (not in a group that sums over counters inside the
/// cell), and is met at two or more shifts of the innermost counter, with the
/// same shifts of the other counters it mentions: a buffer for each run of
/// shifts at most 16 apart that holds two or more; at most 16 buffers per
/// loop, in order of first use. Values that differ only by a
/// shift of the innermost counter in their reads' indices are one value
/// (`u[i - 1] / dx` at iteration c + 1 is `u[i] / dx` at c: one buffer, one
/// division per cell for a flux form's `cm`, `c0`, `cp`). A value must be
/// safe to evaluate at the iterations between those (hoist.hpp:
/// safe_anywhere; no conditional inside; every array read at an index affine
/// in the innermost counter, not through an accessor class, so an index
/// between two that the terms read is in bounds too). The buffer holds the
/// very same expression tree. No product in it (through its locals: a * b,
/// pow, x / 2.0, x / -4.0, x / h for a constant h, x + x, which GCC writes as
/// products) may be, through negations, an operand of a sum or difference in
/// it (`exp(-q * q)` is shared, `sqrt(u * u + v * v)` is not), and none may be
/// computed in any term of the loop outside the unconditional occurrences of
/// shareable values (through a local, or as the same subexpression; compared
/// with indices left out, so it errs towards not sharing): GCC contracts a
/// product into a multiply-add only where every use of it is a sum, so a
/// product that something else in the value uses is contracted neither in
/// place nor in the buffer, and no copy of it is left with a sum as its only
/// use. Every result stays bit-identical (under the compiler's IEEE rules:
/// with -ffast-math it may evaluate a math function in a vectorized fill loop
/// otherwise than one by one).
/// `dpgen --no-share` leaves the pass out, to compare.
void share_shifted_values(LoopPlan& plan);

} // namespace dpgen
