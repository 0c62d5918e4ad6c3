// Prove: facts about the sizes a kernel runs with, and a small prover over
// them. The write-once rule for outputs reduces to inequalities between
// polynomials in the parameters ("the row stride exceeds the last column
// index": nx - (nx - 2) >= 1); many hold only for the sizes the kernel can
// run with at all (a loop `for (i = 1; i < nx - 1; ++i)` that runs has
// nx >= 3) or after a leading guard (`if (n < 3) return;`). What cannot be
// proved here becomes a run-time check in the generated adjoint.
#pragma once

#include "affine.hpp"
#include "ir.hpp"

#include <vector>

namespace dpgen {

/// `f >= 0` for each f: facts that hold wherever a store executes.
using Facts = std::vector<Poly>;

/// Facts a path condition gives about the parameters: comparisons of integer
/// polynomials that mention no loop counter, joined by && (or negated ||).
/// Conditions it cannot read give no fact (never a wrong one).
void add_facts(const PathCond& pc, Facts& out);

/// True when the condition is a conjunction of comparisons of parameters
/// that `facts` prove (it holds wherever the facts do).
bool implied(const PathCond& pc, const Facts& facts);

/// The loop runs at least once: hi - lo - 1 >= 0.
void add_nonempty(const Loop& l, Facts& out);

/// Inside the loop: lo <= counter <= hi - 1 (facts that mention the counter).
void add_counter_range(const Loop& l, Facts& out);
/// add_facts, comparisons with loop counters included (`if (i > 0)`).
void add_facts_with_counters(const PathCond& pc, Facts& out);

/// True when `goal >= 0` follows from `facts` for all integers (sound, not
/// complete): Fourier-Motzkin elimination shows that `goal <= -1` together
/// with the facts has no rational solution. Products of two to four symbols
/// are treated as unknowns of their own, bounded below by the products of
/// the symbols' lower bounds.
bool prove_nonneg(const Poly& goal, const Facts& facts);

/// A store's index written with bit operations on a power-of-two layout,
/// `(j << lg) | i` or `(j << 3) | i`, as the sum it equals, `j * n + i`: a
/// shift by a non-constant `lg` is a product with the kernel-level local
/// defined as `1 << lg` (`const int n = 1 << lg;`), and `a | b` is `a + b`
/// where `a` is a multiple of a power of two M (a constant 2^c, or that
/// local) and 0 <= b <= M - 1 follows from the loops' ranges and the path:
/// the two sides share no bit. Anything that does not fit stays as written
/// (not affine: the store is refused as before). `loops`: the loops around
/// the store, innermost last.
ExprP bits_as_sum(const ExprP& index, const std::vector<Loop>& loops,
                  const std::vector<PathCond>& path, const std::vector<LocalP>& locals);

/// `v % m` for an integer v the loops and path keep in [k m, (k + 2) m), k
/// = 0, 1 or 2 (a periodic wrap written with a remainder, `(x + 1 + nx) % nx`
/// for x in [0, nx)): with w = v - k m, the choice `w < m ? w : w - m` it
/// equals, which index analysis reads as two affine pieces. nullopt where v
/// or m is not a polynomial, v has no loop counter (a remainder of constants
/// folds as written), or the range is not proved (the remainder then stays
/// as written).
std::optional<ExprP> remainder_as_choice(const ExprP& v, const ExprP& m,
                                         const std::vector<Loop>& loops,
                                         const std::vector<PathCond>& path);

/// Some symbol of `d` is a layout symbol (ir.hpp: row_symbol, plane_symbol).
bool mentions_layout(const Poly& d);
/// `d`, the difference of two indices with no counter, is a nonzero constant
/// times the highest layout symbol in it plus terms of lower layout ranks
/// only: the indices lie in different planes (rows), never the same element.
bool layout_apart(const Poly& d);

/// The iteration domain of a store: its loop box intersected with the index
/// conditions on its path; other conditions are returned as guards. Empty:
/// the store never runs.
Domain store_domain(const Nest& nest, const Store& s, std::vector<PathCond>& guards);

} // namespace dpgen
