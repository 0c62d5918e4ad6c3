// Lowering, guards: values computed where the conditions they were made
// under may fail (lower_guard.hpp).
#include "lower_impl.hpp"

namespace dpgen::lowering {

// (lower_impl.hpp)
bool may_fault(const ExprP& e) {
  bool found = false;
  std::set<const LocalVar*> seen;
  walk(
      e,
      [&](const ExprP& x) {
        found = found || x->op == Op::Read ||
                ((x->op == Op::Div || x->op == Op::Rem) && !is_real(x->type) &&
                 (x->ops[1]->op != Op::IntConst || x->ops[1]->ival == 0)) ||
                ((x->op == Op::Shl || x->op == Op::Shr) &&
                 (x->ops[1]->op != Op::IntConst || x->ops[1]->ival < 0 || x->ops[1]->ival > 31)) ||
                (x->op == Op::Shl && (x->ops[0]->op != Op::IntConst || x->ops[0]->ival < 0)) ||
                (x->op == Op::Cast && !is_real(x->type) && is_real(x->ops[0]->type));
        return !found;
      },
      [](const ExprP&) { return false; }, seen);
  return found;
}

// (lower_impl.hpp)
ExprP when(const ExprP& cond, const ExprP& value) {
  if (!cond)
    return value;
  if (value->type == Type::Bool)
    return binary(Op::And, cond, value);
  return select(cond, value, value->type == Type::Int ? int_const(0) : zero(value->type));
}

// (lower_guard.hpp) Each local made under more conditions than `depth` (not a
// kernel-level one: those are guarded where made; nor a view's row symbol,
// whose definition is a placeholder) gets a copy that is safe to evaluate
// anywhere, `d_1 = i > 0 ? a[i - 1] : 0.0` where it reads or divides
// integers, one per local and depth, so values the arm shares stay shared.
ExprP Guards::guarded(const ExprP& e, size_t depth) {
  if (e->op != Op::Local)
    return map_operands(e, [&](const ExprP& o) { return guarded(o, depth); });
  const LocalVar& l = *e->local;
  if (l.kernel_level || l.opaque || l.made_under.size() <= depth)
    return e;
  auto it = guarded_.find({l.id, depth});
  if (it != guarded_.end())
    return it->second;
  ExprP def = guarded(l.def, depth);
  if (may_fault(def)) // (the conditions may read the arm's values too: `if (d > 0)`)
    def = when(guarded(path_condition(l.made_under, depth), depth), def);
  ExprP copy = L.stmts_.make_local(l.name, nullptr, def);
  auto g = std::const_pointer_cast<LocalVar>(copy->local);
  g->type_name = l.type_name;
  g->kernel_level = false;
  g->made_under.assign(l.made_under.begin(), l.made_under.begin() + std::ptrdiff_t(depth));
  return guarded_[{l.id, depth}] = copy;
}

// `i > 0 ? sq(a[i - 1]) : a[i]`: the helper's parameter,
// `x = a[i - 1]`, is computed before the select (emitted code evaluates both
// arms), so it becomes `i > 0 ? a[i - 1] : 0.0`. Operands whose locals cannot
// fault keep them as they are.
ExprP Guards::guarded_operand(const ExprP& v, size_t depth, int first_local) {
  const bool faults = any_node(v, [&](const ExprP& x) {
    return x->op == Op::Local && x->local->id >= first_local && may_fault(x->local->def);
  });
  return faults ? guarded(v, depth) : v;
}

// An operand C++ evaluates only under a condition (a `?:` arm, the right
// side of `&&` / `||`), lowered as if it always ran (its value is selected
// after): on Lowerer::cond_operands_ while it is, so that a call in it that
// assigns or stores is refused (Stores::check_caller_write, add_store), and
// under its condition, so that the locals it makes are guarded by it.
ExprP Guards::conditional(const clang::Expr* operand, std::optional<PathCond> holds,
                          const std::function<ExprP()>& lower) {
  L.cond_operands_.emplace_back(L.frames_.size(), operand->getBeginLoc());
  const size_t depth = L.path_.size();
  struct Mark {
    Lowerer& L;
    size_t depth;
    ~Mark() { // (also when an error abandons the operand)
      L.cond_operands_.pop_back();
      L.path_.resize(depth);
    }
  } mark{L, depth};
  if (holds)
    L.path_.push_back(*holds);
  const int first_local = L.next_local_id_;
  ExprP v = lower();
  L.path_.resize(depth);
  return guarded_operand(v, depth, first_local);
}

} // namespace dpgen::lowering
