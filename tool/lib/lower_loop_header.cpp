// Lowering, loop headers: the counter, range and step of a `for` statement,
// triangular and strided bounds, and the index algebra over the enclosing
// loops (lower_loop.hpp).
#include "lower_impl.hpp"
#include "lower_while.hpp"
#include "print.hpp"

namespace dpgen::lowering {

namespace {

// C compares in the operands' common type. Where that is unsigned, a value below zero (a
// signed start or bound converted, `for (int i = start; i < v.size(); ++i)` with start < 0,
// `size_t i = n; while (i-- > lo)` with `int lo = -1`; or unsigned arithmetic that wrapped,
// `lo - 1` with lo = 0) compares as a huge number, and the user's loop runs other iterations
// than dpgen's, which counts with the values as numbers: the lowest value the condition
// tests must provably be >= 0 (for_header), else this is the error. (A bound below zero that
// a count up never reaches makes the user's loop run until it leaves its arrays: no gradient
// to differ from.)
std::string unsigned_compare(const std::string& var, const std::string& type, const ExprP& lowest) {
  return fmt::format("the condition of loop '{}' compares in the unsigned type '{}', where a "
                     "value below zero is a huge number, and dpgen cannot prove that the values "
                     "it compares stay >= 0 (the lowest is '{}'); compare signed values "
                     "(`std::ptrdiff_t(n)`), or start and bound the loop at or above zero",
                     var, type, print(lowest));
}

// `i = i + s`, `i = s + i`, `i = i - s` (s a constant from 1 to 1024): +s or -s; 0 otherwise.
int assigned_step(const BinaryOperator* a, const VarDecl* var, ASTContext& ctx) {
  const VarDecl* v = nullptr;
  bool adds = true;
  const clang::Expr* k = self_step(a, v, adds);
  clang::Expr::EvalResult r;
  if (!k || v != var || !k->EvaluateAsInt(r, ctx) || r.Val.getInt().getSExtValue() < 1 ||
      r.Val.getInt().getSExtValue() > 1024)
    return 0;
  const int step = static_cast<int>(r.Val.getInt().getSExtValue());
  return adds ? step : -step;
}

// b + k, for the lowest value a count down's body sees (count_down's offset).
ExprP offset_by(ExprP b, int k) {
  return k == 0 ? b : binary(k > 0 ? Op::Add : Op::Sub, std::move(b), int_const(k > 0 ? k : -k));
}

// `k-- >= 0` on an unsigned counter (always true: the user's loop never ends): the message,
// or empty.
std::string never_ending(const CountDown& down, ASTContext& ctx, const std::string& type,
                         const std::string& var) {
  clang::Expr::EvalResult r;
  if (down.offset != -1 || !down.bound || !down.bound->EvaluateAsInt(r, ctx) ||
      !r.Val.getInt().isZero())
    return "";
  return fmt::format("'{}-- >= 0' is always true in the unsigned type '{}': the loop never ends; "
                     "count down with '{}-- > 0', which runs the body down to {} = 0",
                     var, type, var, var);
}

// Where a loop's condition compares, in which type, and where its bound is (`i--` alone: the
// condition's place and the counter's type).
struct Compared {
  SourceLocation at, bound_at;
  QualType type;
};
Compared compared(const BinaryOperator* c, const ForStmt* f, const clang::Expr* cond,
                  const VarDecl* var, const clang::Expr* counted_bound) {
  const SourceLocation cond_loc = cond ? cond->getBeginLoc() : f->getBeginLoc();
  if (!c)
    return {cond_loc, cond_loc, var->getType()};
  return {c->getOperatorLoc(), (counted_bound ? counted_bound : c->getRHS())->getBeginLoc(),
          c->getLHS()->getType()};
}

// A loop whose step and condition go opposite ways.
std::string direction_mismatch(const VarDecl* var, int step) {
  return var->getType()->isUnsignedIntegerType() && step < 0
             ? "loop direction does not match its condition: an unsigned counter counting down "
               "to 0 under `i < n` ends by wrapping around, which dpgen does not follow; count "
               "down with `for (size_t i = n; i-- > 0;)`"
             : "loop direction does not match its condition";
}

// The operands of comma expression `e` (`++i, --j`), or `e` itself.
std::vector<const clang::Expr*> comma_parts(const clang::Expr* e) {
  e = e->IgnoreParens();
  if (const auto* b = dyn_cast<BinaryOperator>(e); b && b->getOpcode() == BO_Comma) {
    auto out = comma_parts(b->getLHS());
    for (const clang::Expr* r : comma_parts(b->getRHS()))
      out.push_back(r);
    return out;
  }
  return {e};
}

} // namespace

// The integer local with a value that increment part `e` steps (`++p`, `p
// += 2`), if that is what it is.
const VarDecl* LoopHeaders::stepped_local(const clang::Expr* e) const {
  const clang::Expr* operand = nullptr;
  if (const auto* u = dyn_cast<UnaryOperator>(e->IgnoreParens()); u && u->isIncrementDecrementOp())
    operand = u->getSubExpr();
  else if (const auto* c = dyn_cast<CompoundAssignOperator>(e->IgnoreParens()))
    operand = c->getLHS();
  const auto* r = operand ? dyn_cast<DeclRefExpr>(operand->IgnoreParenImpCasts()) : nullptr;
  const auto* v = r ? dyn_cast<VarDecl>(r->getDecl()) : nullptr;
  auto it = v ? L.env_.find(v) : L.env_.end();
  if (it == L.env_.end() || it->second.kind != Binding::Value || !it->second.value ||
      !v->getType()->isIntegerType() || v->getType()->isBooleanType())
    return nullptr;
  return v;
}

namespace {

// Loop bound `e` with each integer local of a loop body (`const int m = nx;` in an outer
// loop's body, a helper's `int n` parameter bound to `nx` where the helper is called in a
// loop) replaced by its definition, where that mentions no counter and reads no array: the
// same value (to_poly already sees through such a local), but one that generated code can
// evaluate before the nest (a parallel loop's size test, the tangent's and the parallel
// forward's headers), where the local is not defined.
ExprP invariant_bound(const ExprP& e) {
  if (e->op == Op::Local && !e->local->kernel_level && !e->local->opaque && e->type == Type::Int) {
    ExprP def = invariant_bound(e->local->def);
    // (kernel-level locals are defined before every nest: not entered)
    bool varies = false;
    std::set<const LocalVar*> seen;
    walk(
        def,
        [&](const ExprP& x) {
          varies = varies || x->op == Op::LoopVar || x->op == Op::Read ||
                   (x->op == Op::Local && !x->local->kernel_level);
          return !varies;
        },
        [](const ExprP&) { return false; }, seen);
    return varies ? e : def;
  }
  return map_operands(e, invariant_bound);
}

} // namespace

// Whether `s` names variable `v`.
bool LoopHeaders::mentions(const Stmt* s, const VarDecl* v) {
  return ReductionForms::mentions(s, v);
}

// The header of `for` statement `f`: its counter, its range [lo, hi) with
// the step, and what makes the box rectangular (lower_loop.hpp).
ForHeader LoopHeaders::for_header(const ForStmt* f) {
  // A loop in a void helper (a library parallel-for: `ParallelFor(box, f)`
  // runs f(i, j, k) in a nest) is a loop of the kernel; a helper that
  // returns a value computes it without loops.
  if (!L.frames_.empty() && !L.frames_.back().is_void)
    L.fail(f->getBeginLoc(),
           fmt::format("a loop in helper '{}', which returns a value: helpers "
                       "that compute a value do it without loops; write the "
                       "loop in the kernel",
                       L.frames_.back().fn->getNameAsString()),
           "dpgen-loop");
  // init: `int i = lo` or, C89 style, `i = lo` for a counter declared
  // earlier; with companion counters, `int i = 0, j = n - 1` or `i = 0, j =
  // n - 1` (the condition tests one of them, the increment steps each).
  std::vector<std::pair<const VarDecl*, const clang::Expr*>> inits;
  if (const auto* ds = dyn_cast_or_null<DeclStmt>(f->getInit())) {
    for (const Decl* d : ds->decls()) {
      const auto* v = dyn_cast<VarDecl>(d);
      if (!v || !v->getInit())
        L.fail(f->getBeginLoc(),
               fmt::format("loop counter '{}' needs an initial value (declare other variables "
                           "before the loop)",
                           v ? v->getNameAsString() : "?"),
               "dpgen-loop");
      inits.push_back({v, v->getInit()});
    }
  } else if (const auto* e = dyn_cast_or_null<clang::Expr>(f->getInit())) {
    for (const clang::Expr* part : comma_parts(e)) {
      const auto* a = dyn_cast<BinaryOperator>(part);
      if (!a || a->getOpcode() != BO_Assign)
        L.fail(part->getBeginLoc(),
               "a kernel loop must set its counter: 'for (int i = lo; i < hi; ++i)' "
               "or, with 'int i;' declared earlier, 'for (i = lo; i < hi; ++i)'",
               "dpgen-loop");
      const auto* r = dyn_cast<DeclRefExpr>(a->getLHS()->IgnoreParenImpCasts());
      const auto* v = r ? dyn_cast<VarDecl>(r->getDecl()) : nullptr;
      auto it = v ? L.env_.find(v) : L.env_.end();
      if (v && L.poisoned_.count(v))
        throw Rejected{}; // its declaration's error is reported already
      if (!v || it == L.env_.end() || it->second.kind != Binding::Value)
        L.fail(a->getLHS()->getBeginLoc(),
               "the loop counter must be a local variable of the "
               "kernel: 'for (i = lo; i < hi; ++i)'",
               "dpgen-loop");
      inits.push_back({v, a->getRHS()});
    }
  } else {
    L.fail(f->getBeginLoc(),
           "a kernel loop must set its counter: 'for (int i = lo; i < hi; ++i)' "
           "or, with 'int i;' declared earlier, 'for (i = lo; i < hi; ++i)'",
           "dpgen-loop");
  }
  // The counter is the one the condition tests; the others are companions,
  // each the same affine function of the iteration in the body.
  const VarDecl* var = inits[0].first;
  const clang::Expr* init = inits[0].second;
  if (inits.size() > 1) {
    std::vector<size_t> tested;
    for (size_t k = 0; k < inits.size(); ++k)
      if (f->getCond() && mentions(f->getCond(), inits[k].first))
        tested.push_back(k);
    std::string names;
    for (const auto& [v, e] : inits)
      names += (names.empty() ? "'" : ", '") + v->getNameAsString() + "'";
    if (tested.size() != 1)
      L.fail(f->getCond() ? f->getCond()->getBeginLoc() : f->getBeginLoc(),
             fmt::format("a loop with counters {} tests exactly one of them in its condition "
                         "('i < n'); the others follow it",
                         names),
             "dpgen-loop");
    var = inits[tested[0]].first;
    init = inits[tested[0]].second;
    for (const auto& [v, e] : inits)
      for (const auto& [w, other] : inits)
        if (mentions(e, w))
          L.fail(e->getBeginLoc(),
                 fmt::format("the initial value of loop counter '{}' reads counter '{}' of the "
                             "same loop; give each counter a value of its own",
                             v->getNameAsString(), w->getNameAsString()),
                 "dpgen-loop");
  }
  QualType vt = var->getType().getCanonicalType();
  if (!vt->isIntegerType() || vt->isBooleanType())
    L.fail(var->getLocation(),
           fmt::format("loop counter '{}' must have an integer type", var->getNameAsString()),
           "dpgen-loop");
  L.in_loop_bounds_ = true; // (reset below, also when lowering them fails)
  struct Reset {
    bool& flag;
    ~Reset() { flag = false; }
  } reset{L.in_loop_bounds_};
  ExprP init_value = L.exprs_.expr(init);
  // cond: `i < hi`, `i <= hi`, `i >= lo`, `i > lo`; also `i + 1 < n` or
  // `n > i`: any comparison whose sides differ by +-i plus a bound.
  // (a bound such as std::min(n, i + w + 1) binds temporaries to const
  // references: the condition comes wrapped in ExprWithCleanups)
  const clang::Expr* cond_expr = f->getCond();
  if (const auto* cleanups = dyn_cast_or_null<ExprWithCleanups>(cond_expr))
    cond_expr = cleanups->getSubExpr();
  const auto* c = dyn_cast_or_null<BinaryOperator>(cond_expr);
  BinaryOperatorKind cond_op = c ? c->getOpcode() : BO_Comma;
  // `for (unsigned i = n; i-- > lo;)`, the way to count an unsigned counter
  // down: the body sees i = n - 1, ..., lo (also `i-- >= lo`, `i--`, `--i >= lo`:
  // count_down, whose lowest value the body sees is the bound).
  const CountDown down = count_down(cond_expr);
  const bool post_decrement = down.var == var && (!f->getInc() || inits.size() > 1);
  if (!post_decrement && unsigned_pre_decrement(cond_expr) == var)
    L.fail(cond_expr->getBeginLoc(), pre_decrement_message(var), "dpgen-loop");
  if (post_decrement)
    c = down.test, cond_op = BO_GT;
  ExprP bound = post_decrement
                    ? offset_by(down.bound ? L.exprs_.expr(down.bound) : int_const(0), down.offset)
                : c && (c->isRelationalOp() || cond_op == BO_NE) ? loop_bound(c, var, cond_op)
                                                                 : nullptr;
  const Compared cmp = compared(c, f, cond_expr, var, post_decrement ? down.bound : nullptr);
  L.in_loop_bounds_ = false;
  if (const std::string m =
          post_decrement && cmp.type->isUnsignedIntegerType()
              ? never_ending(down, L.ctx_, L.spelled(cmp.type), var->getNameAsString())
              : "";
      !m.empty())
    L.fail(cmp.at, m, "dpgen-loop");
  if (!bound)
    L.fail(f->getCond() ? f->getCond()->getBeginLoc() : f->getBeginLoc(),
           fmt::format("loop condition must compare the counter '{}' with a bound: "
                       "'{} < hi'",
                       var->getNameAsString(), var->getNameAsString()),
           "dpgen-loop");
  // C tests the condition before every iteration: a bound the body assigns (`m = 5;` in the
  // loop over i < m) changes the count as the loop runs, which a fixed range would not.
  std::set<const VarDecl*> assigned;
  L.for_loops_.assigned_vars(f->getBody(), assigned);
  for (const VarDecl* w : assigned)
    if (w != var && mentions(f->getCond(), w) && !L.bufs_.declares(w)) // (`flux.size()`)
      L.fail(f->getCond()->getBeginLoc(),
             fmt::format("the condition of loop '{}' reads '{}', which the loop's body assigns: "
                         "dpgen needs a loop's bounds fixed before it runs; give the new value "
                         "a variable of its own, or set '{}' before the loop",
                         var->getNameAsString(), w->getNameAsString(), w->getNameAsString()),
             "dpgen-loop");
  init_value = invariant_bound(init_value);
  bound = invariant_bound(bound);
  // inc: ++i, i++, i += 1 (or the decrements for a loop that counts down);
  // with companions, one of these for each counter (`++i, --j`)
  std::vector<ForHeader::Companion> companions;
  const clang::Expr* inc = f->getInc();
  if (inits.size() > 1 || (inc && comma_parts(inc).size() > 1)) {
    inc = nullptr;
    // each part of the increment steps one counter, each counter once; a
    // local set before the loop may step beside them (`int p = j * nx + 1;
    // for (i = 1; i < nx - 1; ++i, ++p)`), a companion from its value there
    std::map<const VarDecl*, const clang::Expr*> own;
    std::vector<const VarDecl*> before;
    if (f->getInc())
      for (const clang::Expr* part : comma_parts(f->getInc())) {
        const VarDecl* stepped = nullptr;
        int n = 0;
        for (const auto& [v, e] : inits)
          if (mentions(part, v))
            stepped = v, ++n;
        if (const VarDecl* w = n == 0 ? stepped_local(part) : nullptr) {
          stepped = w, n = 1;
          before.push_back(w);
        }
        if (n != 1 || own.count(stepped) || (post_decrement && stepped == var))
          L.fail(part->getBeginLoc(),
                 "the increment of a loop with several counters steps each of them once: "
                 "'++i, --j'",
                 "dpgen-loop");
        own[stepped] = part;
      }
    inc = own.count(var) ? own[var] : nullptr;
    for (const auto& [v, e] : inits) {
      if (v == var)
        continue;
      const clang::Expr* its = own.count(v) ? own[v] : nullptr;
      int k = its ? loop_step(its, v) : 0;
      QualType t = v->getType().getCanonicalType();
      if (k == 0 || !t->isIntegerType() || t->isBooleanType())
        L.fail(its ? its->getBeginLoc() : f->getBeginLoc(),
               fmt::format("loop counter '{}' must have an integer type and step by a constant "
                           "once per iteration in the loop's increment ('++{}', '--{}', "
                           "'{} += 2')",
                           v->getNameAsString(), v->getNameAsString(), v->getNameAsString(),
                           v->getNameAsString()),
               "dpgen-loop");
      L.in_loop_bounds_ = true;
      ExprP value = L.exprs_.expr(e);
      L.in_loop_bounds_ = false;
      // (an unsigned one must stay >= 0 in the body, `j = off - 2` too: checked
      // where the loop's range is known, ForLoops::for_loop)
      companions.push_back({v, value, k, t->isUnsignedIntegerType(), its});
    }
    for (const VarDecl* w : before) {
      const int k = loop_step(own[w], w);
      if (k == 0)
        L.fail(own[w]->getBeginLoc(),
               fmt::format("'{}' steps beside the loop's counter: by a constant once per "
                           "iteration ('++{}', '{} += 2')",
                           w->getNameAsString(), w->getNameAsString(), w->getNameAsString()),
               "dpgen-loop");
      companions.push_back(
          {w, *L.env_.at(w).value, k, w->getType()->isUnsignedIntegerType(), own[w]});
    }
  }
  int step = post_decrement ? -1 : loop_step(inc, var);
  if (step == 0)
    L.fail(f->getInc() ? f->getInc()->getBeginLoc() : f->getBeginLoc(),
           "loop increment must be ++i, i++, i += s or i = i + s for a constant s > 0 (or --i, "
           "i -= s for a loop counting down)",
           "dpgen-loop");
  // `i != n` stepping by one is `i < n` (counting down, `i > n`); from a start past the bound
  // the user's loop would run until the counter wraps.
  if (cond_op == BO_NE && (step == 1 || step == -1))
    cond_op = step > 0 ? BO_LT : BO_GT;
  ExprP lo, hi;
  ExprP one = int_const(1);
  switch (cond_op) {
  case BO_LT:
    lo = init_value, hi = bound;
    break;
  case BO_LE:
    lo = init_value, hi = binary(Op::Add, bound, one);
    break;
  case BO_GT:
    if (post_decrement)
      lo = bound, hi = init_value;
    else
      lo = binary(Op::Add, bound, one), hi = binary(Op::Add, init_value, one);
    break;
  case BO_GE:
    lo = bound, hi = binary(Op::Add, init_value, one);
    break;
  default:
    L.fail(cmp.at, "loop condition must be <, <=, > or >= ('!=' where the counter steps by one)",
           "dpgen-loop");
  }
  const ExprP hi_before_hull = hi; // (a count down's start + 1)
  if ((step > 0) != (cond_op == BO_LT || cond_op == BO_LE))
    L.fail(f->getInc()->getBeginLoc(), direction_mismatch(var, step), "dpgen-loop");
  // Counting an unsigned counter down is safe when the counter stays above
  // zero: `i > b` (b >= 0), or `i >= b` with b >= 1; `i >= 0` wraps.
  // (a strided count down `i -= s` stays at or above zero where lo - s does)
  bool stays_positive =
      step < -1 ? L.provably_nonneg(binary(Op::Sub, lo, int_const(-step)))
                : cond_op == BO_GT ||
                      (cond_op == BO_GE && L.provably_nonneg(binary(Op::Sub, bound, int_const(1))));
  if (vt->isUnsignedIntegerType() && step < -1 && !stays_positive)
    L.fail(f->getInc()->getBeginLoc(),
           fmt::format("unsigned counter '{}' counts down by {}: it wraps around at 0 unless the "
                       "loop stops at or above {} ('{} >= {}'); use a signed counter",
                       var->getNameAsString(), -step, -step, var->getNameAsString(), -step),
           "dpgen-loop");
  if (vt->isUnsignedIntegerType() && step < 0 && !post_decrement && !stays_positive)
    L.fail(f->getInc()->getBeginLoc(),
           fmt::format("unsigned counter '{}' counts down: its bound check wraps around at 0; "
                       "count up, use a signed counter, or write 'for ({} = n; {}-- > 0;)'",
                       var->getNameAsString(), var->getNameAsString(), var->getNameAsString()),
           "dpgen-loop");
  // (a count down stepped before its test, `--i >= lo`, last compares lo - 1: the bound - 1)
  if (const ExprP lowest = step > 0 ? init_value
                           : cond_op == BO_GE || (post_decrement && !down.post)
                               ? binary(Op::Sub, bound, one)
                               : bound;
      cmp.type->isUnsignedIntegerType() && !L.provably_nonneg(lowest))
    L.fail(cmp.at, unsigned_compare(var->getNameAsString(), L.spelled(cmp.type), lowest),
           "dpgen-loop");
  // A strided loop whose start moves with outer counters (red-black:
  // `for (i = 1 + (j + 1) % 2; i < nx - 1; i += 2)`, or `i = j; ...; i += 2`;
  // counting down, `for (i = n - 1 - j % 2; i >= 0; i -= 2)`) runs as a
  // unit-step loop from the extreme start over the outer ranges, its body
  // under `i >= start && (i - start) % step == 0` (counting down, `i <=
  // start && (start - i) % step == 0`): the same iterations, in the same
  // order, with a box the rules and the gather can range over.
  ExprP parity_start; // the moving start, and the original step
  int parity_step = 0;
  ExprP& start = step > 0 ? lo : hi; // (hi is the start + 1 counting down)
  const ExprP start_value = step > 0 ? lo : init_value;
  if ((step > 1 || step < -1) &&
      any_node(start, [](const ExprP& x) { return x->op == Op::LoopVar; }))
    if (auto bound_start = extreme(start_value, step < 0)) {
      parity_start = start_value;
      parity_step = step;
      start = step > 0 ? *bound_start : binary(Op::Add, *bound_start, one);
      step = step > 0 ? 1 : -1;
    }
  // Triangular nests (`for (j = 0; j <= i; ++j)`, `for (j = i + 1; j < n;
  // ++j)`, `j < std::min(n, i + 3)`): a bound affine in outer counters, with
  // constant coefficients, becomes its extreme over the outer loops' ranges
  // and the bound itself a condition on the body's path (`j < i + 1`), so
  // the box stays rectangular and the iterations are the same. In a min
  // (upper) or max (lower) bound each such term is treated so; the others
  // stay in the bound.
  std::vector<std::pair<ExprP, bool>> triangle; // (original bound, is the upper one)
  for (ExprP* b : {&lo, &hi}) {
    const bool upper = b == &hi;
    if (!any_node(*b, [](const ExprP& x) { return x->op == Op::LoopVar; }))
      continue;
    if (step != 1 && step != -1 && upper == (step < 0))
      continue; // (a strided loop's start fixes its parity: not moved)
    std::vector<ExprP> terms;
    std::function<void(const ExprP&)> flatten = [&](const ExprP& x) {
      const char* fn = upper ? "min" : "max";
      if (x->op == Op::Call && x->name == fn) {
        for (const auto& a : x->ops)
          flatten(a);
      } else if ((x->op == Op::Add || x->op == Op::Sub) && x->ops[1]->op == Op::IntConst &&
                 x->ops[0]->op == Op::Call && x->ops[0]->name == fn) {
        // `j <= std::min(n - 1, i + 1)`: min(a, b) + 1 is min(a + 1, b + 1)
        for (const auto& a : x->ops[0]->ops)
          flatten(binary(x->op, a, x->ops[1]));
      } else {
        terms.push_back(x);
      }
    };
    flatten(*b);
    std::vector<ExprP> hulled;
    std::vector<std::pair<ExprP, bool>> sides;
    bool ok = true;
    for (const auto& t : terms) {
      auto p = to_poly(t);
      if (!p || !p->mentions_any_counter()) {
        hulled.push_back(t);
        continue;
      }
      auto h = hull(t, *p, upper);
      if (!h) {
        ok = false;
        break;
      }
      hulled.push_back(*h);
      sides.push_back({t, upper});
    }
    if (!ok || sides.empty())
      continue; // reported below
    triangle.insert(triangle.end(), sides.begin(), sides.end());
    *b = hulled.size() == 1 ? hulled[0] : call(upper ? "min" : "max", hulled, Type::Int);
  }
  // A bound that is not a polynomial but depends on the sizes only
  // (`i < n / 2`, `i < (n + 1) / 2`) is fixed for the whole kernel: a
  // symbol, like `int half = n / 2;` set before the loops.
  for (ExprP* b : {&lo, &hi})
    if (!to_poly(*b) && !any_node(*b, [](const ExprP& x) {
          return x->op == Op::LoopVar || x->op == Op::Read || is_real(x->type);
        })) {
      auto l = std::make_shared<LocalVar>();
      l->name = var->getNameAsString() + (b == &lo ? "_lo" : "_hi");
      for (int n = 1; L.is_reserved(l->name) || L.local_names_.count(l->name); ++n)
        l->name = fmt::format("{}_{}_{}", L.unprefixed(var->getNameAsString()),
                              b == &lo ? "lo" : "hi", n);
      L.local_names_.insert(l->name);
      l->type_name = "std::ptrdiff_t";
      l->def = *b;
      l->id = L.next_local_id_++;
      l->kernel_level = true;
      L.k_.kernel_locals.push_back(l);
      *b = local_ref(l);
    }
  for (const auto& [what, e, loc] :
       {std::tuple{"lower", lo, init->getBeginLoc()}, std::tuple{"upper", hi, cmp.bound_at}}) {
    auto p = to_poly(e);
    if (!p)
      L.fail(loc,
             fmt::format("{} bound of loop '{}' must be a polynomial in the integer "
                         "parameters",
                         what, var->getNameAsString()),
             "dpgen-loop");
    for (const auto& [m, coef] : p->terms())
      for (const auto& s : m)
        if (s.is_counter())
          L.fail(loc,
                 fmt::format("{} bound of loop '{}' depends on loop '{}' in a way dpgen "
                             "cannot make rectangular: a bound may move with outer "
                             "counters by constant multiples (j <= i, j < i + 3, "
                             "std::min(n, i + w + 1), a strided start 1 + (j + 1) % 2)",
                             what, var->getNameAsString(), s.name),
                 "dpgen-loop");
  }
  if (!companions.empty() && parity_start)
    L.fail(f->getBeginLoc(),
           fmt::format("a strided loop whose start moves with the outer counters has one "
                       "counter; compute '{}' from '{}' in the body",
                       companions[0].var->getNameAsString(), var->getNameAsString()),
           "dpgen-loop");
  // The first value: the start side as it stands, unless a triangle moved it.
  const bool start_moved = std::any_of(triangle.begin(), triangle.end(),
                                       [&](const auto& t) { return t.second == (step < 0); });
  ExprP first = step > 0 ? (start_moved ? init_value : lo)
                         : binary(Op::Sub, start_moved ? hi_before_hull : hi, one);
  return {var, lo, hi, step, triangle, parity_start, parity_step, companions, first, assigned};
}

// The bound of a loop condition as `counter op bound` (op returned in `op`):
// `i < n`, `i + 1 < n` (i < n - 1), `n > i` (i < n). Null when the sides do
// not differ by exactly +-counter plus something free of the counter.
ExprP LoopHeaders::loop_bound(const BinaryOperator* c, const VarDecl* var, BinaryOperatorKind& op) {
  const auto* lhs = dyn_cast<DeclRefExpr>(c->getLHS()->IgnoreParenImpCasts());
  if (lhs && lhs->getDecl() == var)
    return L.exprs_.expr(c->getRHS());
  // The counter is bound to a placeholder counter while the sides are
  // lowered, named apart from every counter already named.
  std::string placeholder = "dpgen_counter";
  for (int n = 1; L.loop_names_.count(placeholder); ++n)
    placeholder = fmt::format("dpgen_counter_{}", n);
  auto saved =
      L.env_.find(var) != L.env_.end() ? std::optional<Binding>(L.env_[var]) : std::nullopt;
  Binding b;
  b.kind = Binding::LoopVar;
  b.value = loop_var(placeholder);
  L.env_[var] = b;
  ExprP l = L.exprs_.expr(c->getLHS()), r = L.exprs_.expr(c->getRHS());
  if (saved)
    L.env_[var] = *saved;
  else
    L.env_.erase(var);
  auto pl = to_poly(l), pr = to_poly(r);
  if (!pl || !pr)
    return nullptr;
  Poly d = *pl - *pr; // condition: d op 0
  Poly k = d.coefficient(Sym::counter(placeholder));
  Poly rest = d.without(Sym::counter(placeholder));
  if (!k.is_constant() || (k.constant_term() != 1 && k.constant_term() != -1) ||
      rest.mentions_any_counter())
    return nullptr;
  op = c->getOpcode();
  if (k.constant_term() == -1) { // -i + rest op 0  <=>  i (flipped op) rest
    op = BinaryOperator::reverseComparisonOp(op);
    return poly_expr(rest);
  }
  return poly_expr(-rest); // i + rest op 0  <=>  i op -rest
}

// An integer expression for a polynomial over parameters and kernel-level
// locals (symbols resolve to what they name).
ExprP LoopHeaders::poly_expr(const Poly& p) {
  ExprP sum;
  for (const auto& [m, coef] : p.terms()) {
    ExprP term = int_const(coef);
    for (const auto& sym : m)
      term = binary(Op::Mul, term, symbol_expr(sym));
    sum = sum ? binary(Op::Add, sum, term) : term;
  }
  return sum ? sum : int_const(0);
}

ExprP LoopHeaders::symbol_expr(const Sym& sym) {
  if (sym.is_counter())
    throw std::logic_error("lower: a loop counter in a size: " + sym.name);
  if (const Param* p = L.k_.find_param(sym.name))
    return param(p->name, p->elem);
  for (const auto& l : L.k_.kernel_locals)
    if (l->name == sym.name)
      return local_ref(l);
  if (L.objects_.object_values().count(sym.name)) // bx.smallEnd(0), u.extent(1) (lower_view.cpp)
    return param(sym.name, Type::Int);
  throw std::logic_error("lower: unknown symbol " + sym.name);
}

// Every local variable assigned (=, op=, ++, --) somewhere in `s`.
// The extreme (the largest if `upper`, else the smallest) of loop bound `e`
// (`p` as a polynomial) over the enclosing loops' ranges: each outer counter
// replaced by its first or last value, by the sign of its coefficient. Null
// where a coefficient is not a constant.
std::optional<ExprP> LoopHeaders::hull(const ExprP& e, const Poly& p, bool upper) const {
  std::map<std::string, ExprP> at;
  for (const auto& l : L.loops_) {
    Poly c = p.coefficient(Sym::counter(l->var));
    if (c == Poly())
      continue;
    if (!c.is_constant() || !to_poly(l->lo) || !to_poly(l->hi) ||
        to_poly(l->lo)->mentions_any_counter() || to_poly(l->hi)->mentions_any_counter())
      return std::nullopt;
    bool last = (c.constant_term() > 0) == upper;
    at[l->var] = last ? binary(Op::Sub, l->hi, int_const(1)) : l->lo;
  }
  std::function<ExprP(const ExprP&)> sub = [&](const ExprP& x) -> ExprP {
    if (x->op == Op::LoopVar)
      if (auto it = at.find(x->name); it != at.end())
        return it->second;
    if (x->op == Op::Local) // an integer local of the counters: its definition
      if (any_node(x, [](const ExprP& y) { return y->op == Op::LoopVar; }))
        return sub(x->local->def);
    return map_operands(x, sub);
  };
  ExprP out = sub(e);
  auto q = to_poly(out);
  if (!q || q->mentions_any_counter())
    return std::nullopt;
  return out;
}

// A lower (`upper`: an upper) bound of integer `e` over the enclosing loops
// that depends on the sizes only: `e` itself where it mentions no counter,
// the hull of an affine part, 0 (m - 1) for `x % m` with a constant m > 0 and
// x >= 0 (C's remainder of a non-negative value), sums and differences of
// those. Null otherwise.
std::optional<ExprP> LoopHeaders::extreme(const ExprP& e, bool upper) const {
  if (!any_node(e, [](const ExprP& x) { return x->op == Op::LoopVar; }))
    return e;
  if (auto p = to_poly(e))
    return hull(e, *p, upper);
  if (e->op == Op::Add || e->op == Op::Sub) {
    auto a = extreme(e->ops[0], upper), b = extreme(e->ops[1], upper == (e->op == Op::Add));
    if (a && b)
      return binary(e->op, *a, *b);
    return std::nullopt;
  }
  if (e->op == Op::Rem && e->ops[1]->op == Op::IntConst && e->ops[1]->ival > 0 &&
      L.provably_nonneg(e->ops[0]))
    return int_const(upper ? e->ops[1]->ival - 1 : 0);
  if (e->op == Op::Local)
    return extreme(e->local->def, upper);
  return std::nullopt;
}

int LoopHeaders::loop_step(const clang::Expr* inc, const VarDecl* var) {
  if (!inc)
    return 0;
  inc = inc->IgnoreParens();
  auto is_var = [&](const clang::Expr* e) {
    const auto* r = dyn_cast<DeclRefExpr>(e->IgnoreParenImpCasts());
    return r && r->getDecl() == var;
  };
  if (const auto* u = dyn_cast<UnaryOperator>(inc)) {
    if (!is_var(u->getSubExpr()))
      return 0;
    return u->isIncrementOp() ? 1 : u->isDecrementOp() ? -1 : 0;
  }
  if (const auto* b = dyn_cast<CompoundAssignOperator>(inc)) {
    clang::Expr::EvalResult r;
    if (!is_var(b->getLHS()) || !b->getRHS()->EvaluateAsInt(r, L.ctx_))
      return 0;
    int64_t k = r.Val.getInt().getSExtValue();
    if (k < 1 || k > 1024)
      return 0;
    return b->getOpcode() == BO_AddAssign ? int(k) : b->getOpcode() == BO_SubAssign ? -int(k) : 0;
  }
  if (const auto* a = dyn_cast<BinaryOperator>(inc); a && a->getOpcode() == BO_Assign)
    return assigned_step(a, var, L.ctx_);
  return 0;
}

} // namespace dpgen::lowering
