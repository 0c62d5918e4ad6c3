// Walking the IR: one traversal for the questions the phases ask of an
// expression (which locals it needs, whether it reads an array, which select
// conditions it holds), instead of a hand-written recursion each.
#pragma once

#include "ir.hpp"

#include <set>
#include <stdexcept>

namespace dpgen {

/// Calls visit(x) for `e` and every expression below it, pre-order, operands
/// left to right; visit returns false to skip what is below x. Below a Local
/// is its definition: walked when enter(x) (x the Local) returns true, and
/// then only the first time that local is met (`seen`, shared by calls that
/// should not walk a definition twice). A null `e` is an internal error (no
/// ExprP is null; an exact zero is zero(), ir.hpp).
template <typename Visit, typename Enter>
void walk(const ExprP& e, Visit&& visit, Enter&& enter, std::set<const LocalVar*>& seen) {
  if (!e)
    throw std::logic_error("internal error: walk: a null expression");
  if (!visit(e))
    return;
  if (e->op == Op::Local) {
    if (enter(e) && seen.insert(e->local.get()).second)
      walk(e->local->def, visit, enter, seen);
    return;
  }
  for (const auto& o : e->ops)
    walk(o, visit, enter, seen);
}

/// Whether pred holds for `e` or anything below it, definitions of locals
/// included (each walked once; `seen` may carry over between calls).
template <typename Pred>
bool any_node(const ExprP& e, Pred&& pred, std::set<const LocalVar*>& seen) {
  bool found = false;
  walk(
      e,
      [&](const ExprP& x) {
        found = found || pred(x);
        return !found;
      },
      [](const ExprP&) { return true; }, seen);
  return found;
}
template <typename Pred> bool any_node(const ExprP& e, Pred&& pred) {
  std::set<const LocalVar*> seen;
  return any_node(e, pred, seen);
}

} // namespace dpgen
