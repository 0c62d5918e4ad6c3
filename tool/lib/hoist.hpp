// The pass `hoist` (after plan, before emit): loop-invariant subexpressions
// of the expressions a generated function prints inside its loops, moved
// into `const` locals the printer defines once before them. The planned
// terms are rewritten in place; emit prints them as they are.
#pragma once

#include "emit_util.hpp"
#include "ir.hpp"
#include "loop_plan.hpp"

#include <map>
#include <set>
#include <string>
#include <vector>

namespace dpgen {

/// Replaces, in the expressions a generated function prints inside its
/// loops, each loop-invariant subexpression (over parameters, constants and
/// kernel-level locals only: `1.0 / dx`, `nu / (dx * dx)`) by a local that
/// the function defines before the loops (`hoisted`, in order of first use:
/// the expressions are visited in the order they are printed). The local
/// holds the very same expression tree, printed the same way and declared
/// `auto`, so it has the type the expression had in place and every result
/// stays bit-identical. Why: a derivative often copies a division of the
/// forward into a conditional (`u[i] / dx <= 0.0 ? 1.0 / dx : 0.0`), and GCC
/// will not evaluate a division that may trap where the source does not, so
/// it does not vectorize such a loop; hoisted, the conditional selects
/// between two values.
///
/// Not hoisted (the operands may be): a subtree that could behave otherwise
/// when evaluated where the source would not evaluate it (integer division or
/// remainder, shifts, a conversion to an integer), a lone negation (its
/// operand is hoisted instead, so `-x` keeps its place in a product), and a
/// product that a sum uses directly (`a * b + c`): the compiler may contract
/// that pair into one fused multiply-add where it sees both, so the product
/// stays next to its sum. A loop-level local whose whole definition is
/// invariant moves as it is (same name, same type), under the same rules.
///
/// The rewrite of one function's expressions (the pass below runs one per
/// generated function).
class Hoister {
public:
  /// `taken`: names of generated locals the hoisted ones must not take
  /// besides the kernel's (the tangent's `<local>_dot`); may be null.
  explicit Hoister(const Kernel& k, const std::set<std::string>* taken = nullptr)
      : k_(k), taken_(taken) {}
  /// `e` with its hoistable subexpressions replaced. `summed`: the value is
  /// added to something where it is used (`x += e`), so a product at its top
  /// stays (see above).
  ExprP operator()(const ExprP& e, bool summed = false);
  /// The path condition with its condition rewritten.
  PathCond operator()(const PathCond& pc);
  /// Each of `conds` rewritten in place, in order.
  void all(std::vector<PathCond>& conds) {
    for (auto& pc : conds)
      pc = (*this)(pc);
  }
  /// The definitions, in order of first use.
  std::vector<LocalP> hoisted() const { return hoisted_; }

private:
  ExprP rewrite(const ExprP& e, bool summed);
  bool hoistable(const ExprP& e, bool summed) const;
  ExprP hoist(const ExprP& e);
  bool movable(const ExprP& local) const;
  bool locals_move(const ExprP& e) const;
  ExprP move(const ExprP& local);
  ExprP with_moved_locals(const ExprP& e);
  std::string name_for(const ExprP& e);

  const Kernel& k_;
  const std::set<std::string>* taken_;
  std::vector<LocalP> hoisted_;            // in order of definition
  std::map<std::string, LocalP> by_text_;  // printed expression -> its local
  std::set<std::string> names_;            // names given out
  /// Loop-level locals seen, with what they became (the key kept alive, so
  /// its address is not reused while it is a key).
  std::map<const LocalVar*, std::pair<LocalP, ExprP>> locals_;
  /// Locals moved before the loops, by name: their definition as printed, and
  /// the reference to the moved one.
  std::map<std::string, std::pair<std::string, ExprP>> moved_;
  /// Names of loop-level locals kept in the loops: a local of the same name
  /// specialized to another box (a split forward's interior) does not move,
  /// or its definition before the loops would be shadowed by the kept one.
  std::set<std::string> kept_;
};

/// Nothing in `e` can behave otherwise when evaluated where the source would
/// not evaluate it: no integer division or remainder (by zero), no shift (by
/// too much), no conversion of a real to an integer (out of range). Real
/// arithmetic and the math functions give a value for every argument.
bool safe_anywhere(const ExprP& e);

/// A real product as the compiler may see it: `a * b`, or `pow(a, 2.0)`, which
/// GCC writes as `a * a` even without -ffast-math. A sum next to it may take it
/// into one fused multiply-add where both are in place (-ffp-contract=fast, the
/// default with FMA), so a pass that moves it away from the sum changes the
/// result's rounding.
bool may_be_product(const ExprP& e);

/// The pass: for an adjoint, its gather and scatter loops (LoopPlan::hoisted),
/// each stage's (a staged adjoint) and the kernel's forward loops
/// (LoopPlan::forward); the expressions are visited in the order emit prints
/// them, so the hoisted locals are numbered in order of first use.
void hoist_invariants(LoopPlan& plan);

/// The same for a forward form (the parallel forward, a staged adjoint's
/// recompute, the tangent with its stores' tangents). `taken`: names of
/// generated locals the hoisted ones must not take besides the kernel's (the
/// tangent's `<local>_dot`); may be null.
void hoist_invariants(ForwardPlan& plan, const std::set<std::string>* taken = nullptr);

/// The hoisted definitions, under a comment saying what they are; nothing if
/// there are none.
void emit_hoisted(Code& code, const std::vector<LocalP>& hoisted);

/// Opens `if (<conds>)` for a guarded statement of a generated loop (`conds`
/// as planned, hoisted), the locals they use defined first (into `done`, as
/// define_locals does), each after the conditions before it where a local
/// needs them (nested ifs). Returns the number of blocks opened (0, nothing
/// written, when `conds` is empty); `inside`: the locals defined inside them.
int open_guard(Code& code, const std::vector<PathCond>& conds, std::set<int>& done,
               std::set<std::string>& vars, std::set<int>& inside);

} // namespace dpgen
