// Lowering, loops: headers, bounds (hulls of triangular loops, strided
// starts), unrolled small loops, scalar accumulators (lower_impl.hpp).
#include "lower_impl.hpp"

namespace dpgen::lowering {

// Loop nests up to this deep (component loops around a 3D stencil, coarsening
// loops inside a cell loop); deeper nests are refused.
constexpr size_t kMaxLoopDepth = 6;

bool Lowerer::should_unroll(const ForStmt* f, long long lo, long long hi) {
  if (hi - lo > 16 || hi <= lo)
    return false;
  bool touches = false;
  const VarDecl* counter = nullptr; // (for a constant table indexed by it, below)
  if (const auto* ds = dyn_cast_or_null<DeclStmt>(f->getInit()); ds && ds->isSingleDecl())
    counter = dyn_cast<VarDecl>(ds->getSingleDecl());
  else if (const auto* bo = dyn_cast_or_null<BinaryOperator>(f->getInit());
           bo && bo->isAssignmentOp())
    if (const auto* r = dyn_cast<DeclRefExpr>(bo->getLHS()->IgnoreParenImpCasts()))
      counter = dyn_cast<VarDecl>(r->getDecl());
  std::function<void(const Stmt*)> scan = [&](const Stmt* s) {
    if (!s)
      return;
    if (const auto* r = dyn_cast<DeclRefExpr>(s))
      if (const auto* v = dyn_cast<VarDecl>(r->getDecl()); v && env_.count(v) &&
                                                            env_[v].kind == Binding::LocalArray)
        touches = true;
    // a constant integer table (`constexpr int cx[9]`) indexed by the
    // counter: unrolled, each copy reads one value (a constant offset)
    if (const auto* a = dyn_cast<ArraySubscriptExpr>(s))
      if (const auto* r = dyn_cast<DeclRefExpr>(a->getBase()->IgnoreParenImpCasts()))
        if (const auto* v = dyn_cast<VarDecl>(r->getDecl());
            v && global_decls_.count(v->getNameAsString()) &&
            global_decls_.at(v->getNameAsString()) == v && v->getType().isConstQualified() &&
            v->getType()->isArrayType() &&
            v->getType()->getArrayElementTypeNoTypeQual()->isIntegerType())
          if (const auto* i = dyn_cast<DeclRefExpr>(a->getIdx()->IgnoreParenImpCasts());
              i && counter && i->getDecl() == counter)
            touches = true;
    for (const Stmt* c : s->children())
      scan(c);
  };
  scan(f->getBody());
  std::set<const VarDecl*> assigned;
  assigned_vars(f->getBody(), assigned);
  for (const VarDecl* v : assigned)
    if (env_.count(v) && env_[v].kind == Binding::Value)
      touches = true;
  return touches;
}

bool Lowerer::forget_value(const VarDecl* v) {
  auto it = env_.find(v);
  if (it == env_.end() ||
      (it->second.kind != Binding::Value && it->second.kind != Binding::LocalArray))
    return false;
  it->second.value = std::nullopt;
  for (auto& el : it->second.elems)
    el = std::nullopt;
  return true;
}

void Lowerer::for_loop(const ForStmt* f) {
  // A loop in a void helper (a library parallel-for: `ParallelFor(box, f)`
  // runs f(i, j, k) in a nest) is a loop of the kernel; a helper that
  // returns a value computes it without loops.
  if (!frames_.empty() && !frames_.back().is_void)
    fail(f->getBeginLoc(), fmt::format("a loop in helper '{}', which returns a value: helpers "
                                       "that compute a value do it without loops; write the "
                                       "loop in the kernel",
                                       frames_.back().fn->getNameAsString()), "dpgen-loop");
  // init: `int i = lo` or, C89 style, `i = lo` for a counter declared earlier.
  const VarDecl* var = nullptr;
  const clang::Expr* init = nullptr;
  if (const auto* ds = dyn_cast_or_null<DeclStmt>(f->getInit())) {
    if (!ds->isSingleDecl())
      fail(f->getBeginLoc(), "a kernel loop declares one counter: 'for (int i = lo; i < hi; "
                             "++i)'", "dpgen-loop");
    var = dyn_cast<VarDecl>(ds->getSingleDecl());
    if (!var || !var->getInit())
      fail(f->getBeginLoc(), "loop counter needs an initial value", "dpgen-loop");
    init = var->getInit();
  } else if (const auto* a = init_assignment(f); a) {
    const auto* r = dyn_cast<DeclRefExpr>(a->getLHS()->IgnoreParenImpCasts());
    var = r ? dyn_cast<VarDecl>(r->getDecl()) : nullptr;
    auto it = var ? env_.find(var) : env_.end();
    if (!var || it == env_.end() || it->second.kind != Binding::Value)
      fail(a->getLHS()->getBeginLoc(), "the loop counter must be a local variable of the "
                                       "kernel: 'for (i = lo; i < hi; ++i)'", "dpgen-loop");
    init = a->getRHS();
  } else {
    fail(f->getBeginLoc(), "a kernel loop must set its counter: 'for (int i = lo; i < hi; ++i)' "
                           "or, with 'int i;' declared earlier, 'for (i = lo; i < hi; ++i)'", "dpgen-loop");
  }
  QualType vt = var->getType().getCanonicalType();
  if (!vt->isIntegerType() || vt->isBooleanType())
    fail(var->getLocation(), fmt::format("loop counter '{}' must have an integer type",
                                         var->getNameAsString()), "dpgen-loop");
  in_loop_bounds_ = true; // (reset below, also when lowering them fails)
  struct Reset {
    bool& flag;
    ~Reset() { flag = false; }
  } reset{in_loop_bounds_};
  ExprP init_value = expr(init);
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
  // down: the body sees i = n - 1, ..., lo.
  bool post_decrement = false;
  if (c && cond_op == BO_GT && !f->getInc())
    if (const auto* u = dyn_cast<UnaryOperator>(c->getLHS()->IgnoreParenImpCasts());
        u && u->getOpcode() == UO_PostDec)
      if (const auto* r = dyn_cast<DeclRefExpr>(u->getSubExpr()->IgnoreParenImpCasts());
          r && r->getDecl() == var)
        post_decrement = true;
  ExprP bound = post_decrement                    ? expr(c->getRHS())
                : c && c->isRelationalOp() ? loop_bound(c, var, cond_op)
                                           : nullptr;
  in_loop_bounds_ = false;
  if (!bound)
    fail(f->getCond() ? f->getCond()->getBeginLoc() : f->getBeginLoc(),
         fmt::format("loop condition must compare the counter '{}' with a bound: "
                     "'{} < hi'",
                     var->getNameAsString(), var->getNameAsString()), "dpgen-loop");
  // inc: ++i, i++, i += 1 (or the decrements for a loop that counts down)
  int step = post_decrement ? -1 : loop_step(f->getInc(), var);
  if (step == 0)
    fail(f->getInc() ? f->getInc()->getBeginLoc() : f->getBeginLoc(),
         "loop increment must be ++i, i++ or i += s for a constant s (or --i for a loop "
         "counting down)", "dpgen-loop");
  if (step < -1)
    fail(f->getInc()->getBeginLoc(), "a loop counting down steps by 1; count a strided loop up", "dpgen-loop");
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
    fail(c->getOperatorLoc(), "loop condition must be <, <=, > or >=", "dpgen-loop");
  }
  if ((step > 0) != (cond_op == BO_LT || cond_op == BO_LE))
    fail(f->getInc()->getBeginLoc(), "loop direction does not match its condition", "dpgen-loop");
  // Counting an unsigned counter down is safe when the counter stays above
  // zero: `i > b` (b >= 0), or `i >= b` with b >= 1; `i >= 0` wraps.
  bool stays_positive = cond_op == BO_GT ||
                        (cond_op == BO_GE && provably_nonneg(binary(Op::Sub, bound, int_const(1))));
  if (vt->isUnsignedIntegerType() && step < 0 && !post_decrement && !stays_positive)
    fail(f->getInc()->getBeginLoc(),
         fmt::format("unsigned counter '{}' counts down: its bound check wraps around at 0; "
                     "count up, use a signed counter, or write 'for ({} = n; {}-- > 0;)'",
                     var->getNameAsString(), var->getNameAsString(), var->getNameAsString()), "dpgen-loop");
  // A strided loop whose start moves with outer counters (red-black:
  // `for (i = 1 + (j + 1) % 2; i < nx - 1; i += 2)`, or `i = j; ...; i += 2`)
  // runs as a unit-step loop from the smallest start over the outer ranges,
  // its body under `i >= start && (i - start) % step == 0`: the same
  // iterations, with a box the rules and the gather can range over.
  ExprP parity_start; // the moving start, and the original step
  int parity_step = 0;
  if (step > 1 && any_node(lo, [](const ExprP& x) { return x->op == Op::LoopVar; }))
    if (auto least = smallest(lo)) {
      parity_start = lo;
      parity_step = step;
      lo = *least;
      step = 1;
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
    if (!upper && step != 1 && step != -1)
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
      for (int n = 1; is_reserved(l->name) || local_names_.count(l->name); ++n)
        l->name = fmt::format("{}_{}_{}", unprefixed(var->getNameAsString()),
                              b == &lo ? "lo" : "hi", n);
      local_names_.insert(l->name);
      l->type_name = "std::ptrdiff_t";
      l->def = *b;
      l->id = next_local_id_++;
      l->kernel_level = true;
      k_.kernel_locals.push_back(l);
      *b = local_ref(l);
    }
  for (const auto& [what, e, loc] :
       {std::tuple{"lower", lo, init->getBeginLoc()},
        std::tuple{"upper", hi, c->getRHS()->getBeginLoc()}}) {
    auto p = to_poly(e);
    if (!p)
      fail(loc, fmt::format("{} bound of loop '{}' must be a polynomial in the integer "
                            "parameters",
                            what, var->getNameAsString()), "dpgen-loop");
    for (const auto& [m, coef] : p->terms())
      for (const auto& s : m)
        if (s.is_counter())
          fail(loc, fmt::format("{} bound of loop '{}' depends on loop '{}' in a way dpgen "
                                "cannot make rectangular: a bound may move with outer "
                                "counters by constant multiples (j <= i, j < i + 3, "
                                "std::min(n, i + w + 1), a strided start 1 + (j + 1) % 2)",
                                what, var->getNameAsString(), s.name), "dpgen-loop");
  }
  {
    auto plo = to_poly(lo), phi = to_poly(hi);
    if (plo->is_constant() && phi->is_constant() && triangle.empty() && !parity_start &&
        should_unroll(f, plo->constant_term(), phi->constant_term())) {
      check_not_assigned(f->getBody(), var);
      auto saved = env_.count(var) ? std::optional<Binding>(env_[var]) : std::nullopt;
      size_t depth = path_.size();
      ++unrolling_;
      // every step-th value from lo up (i += s), or each from hi - 1 down
      const long long stride = step > 0 ? step : 1;
      for (long long k = plo->constant_term(); k < phi->constant_term(); k += stride) {
        long long v = step > 0 ? k : plo->constant_term() + phi->constant_term() - 1 - k;
        Binding b;
        b.kind = Binding::Value;
        b.value = int_const(v);
        env_[var] = b;
        try {
          lower(f->getBody());
        } catch (const Rejected&) {
          --unrolling_;
          path_.resize(depth);
          throw;
        }
        path_.resize(depth);
      }
      --unrolling_;
      if (saved) {
        env_[var] = *saved;
        env_[var].value = std::nullopt;
        why_unset_[var] = fmt::format("loop counter '{}' is read after its loop; use the loop "
                                      "bound instead",
                                      var->getNameAsString());
      } else {
        env_.erase(var);
      }
      return;
    }
  }
  if (loops_.size() == kMaxLoopDepth)
    fail(f->getBeginLoc(), fmt::format("loops nest at most {} deep in the kernel subset",
                                       kMaxLoopDepth),
         "dpgen-loop");

  auto loop = std::make_shared<Loop>();
  // The counter keeps its name unless that would collide with a parameter,
  // a local or an enclosing counter in the generated code.
  std::string base = var->getNameAsString() + (step > 1 ? "_step" : "");
  loop->var = base;
  for (int n = 1; is_reserved(loop->var) || local_names_.count(loop->var); ++n)
    loop->var = fmt::format("{}_{}", unprefixed(base), n);
  loop_names_.insert(loop->var);
  loop->type_name = spelled(var->getType());
  loop->lo = lo;
  loop->hi = hi;
  loop->descending = step < 0;
  ExprP counter = loop_var(loop->var);
  if (step > 1) {
    // for (i = lo; i < hi; i += s): the loop runs over the steps t in
    // [0, (hi - lo + s - 1) / s) and i = lo + s * t.
    auto trips = std::make_shared<LocalVar>();
    trips->name = loop->var + "_count";
    for (int n = 1; local_names_.count(trips->name) || is_reserved(trips->name); ++n)
      trips->name = fmt::format("{}_count_{}", unprefixed(loop->var), n);
    local_names_.insert(trips->name);
    trips->type_name = "std::ptrdiff_t";
    trips->def = binary(Op::Div, binary(Op::Add, binary(Op::Sub, hi, lo), int_const(step - 1)),
                        int_const(step));
    trips->id = next_local_id_++;
    trips->kernel_level = true;
    k_.kernel_locals.push_back(trips);
    loop->lo = int_const(0);
    loop->hi = local_ref(trips);
    counter = binary(Op::Add, lo, binary(Op::Mul, int_const(step), counter));
  }

  check_not_assigned(f->getBody(), var);
  size_t depth = path_.size();
  auto env_before = env_;
  auto why_before = why_unset_;
  Binding b;
  b.kind = Binding::LoopVar;
  b.value = counter;
  env_[var] = b;
  // Variables declared outside the loop and assigned in it (OpenMP
  // `private` temporaries) start each iteration without a value: a read
  // before the iteration's own assignment would be a value carried over
  // from the previous iteration.
  std::set<const VarDecl*> assigned;
  assigned_vars(f->getBody(), assigned);
  // Scalar accumulators of this loop (`s += f(...)`, `s` read only after
  // the loop): a hidden work array each (start_accumulator).
  std::vector<const VarDecl*> accumulating;
  const size_t element_reductions_before = element_reductions_.size();
  if (in_loop_body_frame() && unrolling_ == 0)
    start_element_reductions(f, var, assigned);
  for (const VarDecl* v : assigned) {
    if (!in_loop_body_frame() || unrolling_ != 0)
      break;
    int extremum = is_accumulator(f->getBody(), v) ? 0 : extremum_kind(f->getBody(), {v, nullptr});
    if ((extremum != 0 || is_accumulator(f->getBody(), v)) &&
        start_accumulator(v, f->getForLoc(), extremum))
      accumulating.push_back(v);
  }
  for (const VarDecl* v : assigned) {
    if (!forget_value(v))
      continue;
    if (auto acc = accumulators_.find(v); acc != accumulators_.end()) {
      why_unset_[v] = acc->second.extremum != 0
                          ? fmt::format("'{}' is a {} reduction in this loop: its value is "
                                        "known after the loop, read it there",
                                        v->getNameAsString(),
                                        acc->second.extremum > 0 ? "max" : "min")
                          : fmt::format("'{}' accumulates in this loop ('+='): its sum is known "
                                        "after the loop, read it there",
                                        v->getNameAsString());
      continue;
    }
    why_unset_[v] = fmt::format(
        "'{}' is declared outside the loop and assigned inside it, and read here before it is "
        "assigned in this iteration: a value carried from one iteration to the next (a "
        "recurrence, or a running sum read inside its loop) is outside the kernel subset; "
        "assign it before each use in the iteration, or only add to it (`s += ...`) or take "
        "its min/max (`m = std::max(m, ...)`) in the loop and read it after the loop",
        v->getNameAsString());
  }
  // (after the accumulators' initial stores, which are outside the loop)
  for (const auto& [bound_at, upper] : triangle) // the triangle's side(s)
    path_.push_back({binary(upper ? Op::Lt : Op::Ge, counter, bound_at), true});
  if (parity_start) { // the strided loop's own iterations
    path_.push_back({binary(Op::Ge, counter, parity_start), true});
    path_.push_back({binary(Op::Eq,
                            binary(Op::Rem, binary(Op::Sub, counter, parity_start),
                                   int_const(parity_step)),
                            int_const(0)),
                     true});
  }
  loops_.push_back(loop);
  if (!in_loop_body_frame()) // a helper's loop (a parallel-for's), not one in its body
    library_loops_.insert(loop.get());
  loop_ids_.push_back(next_loop_id_++);
  segments_.push_back(--next_segment_);
  Escape e = lower_recovering(f->getBody());
  (void)e; // a body ending in continue is fine
  library_loops_.erase(loop.get());
  loops_.pop_back();
  loop_ids_.pop_back();
  segments_.pop_back();
  path_.resize(depth);
  env_ = env_before;
  why_unset_ = why_before;
  finish_element_reductions(element_reductions_before, f->getEndLoc());
  // After the loop, a variable it assigned holds what the last iteration
  // left there: outside the subset; an accumulator holds its sum.
  for (const VarDecl* v : assigned) {
    if (std::find(accumulating.begin(), accumulating.end(), v) != accumulating.end()) {
      finish_accumulator(v, f->getEndLoc());
      continue;
    }
    if (!forget_value(v))
      continue;
    why_unset_[v] = fmt::format("'{}' is read after the loop that assigns it: its value there "
                                "is the last iteration's, outside the kernel subset",
                                v->getNameAsString());
  }
  if (const auto* d = dyn_cast_or_null<DeclStmt>(f->getInit()); !d) {
    // A C89 counter is not a value after its loop either.
    env_[var].value = std::nullopt;
    why_unset_[var] = fmt::format("loop counter '{}' is read after its loop; use the loop "
                                  "bound instead",
                                  var->getNameAsString());
  }
}

// The bound of a loop condition as `counter op bound` (op returned in `op`):
// `i < n`, `i + 1 < n` (i < n - 1), `n > i` (i < n). Null when the sides do
// not differ by exactly +-counter plus something free of the counter.
ExprP Lowerer::loop_bound(const BinaryOperator* c, const VarDecl* var, BinaryOperatorKind& op) {
  const auto* lhs = dyn_cast<DeclRefExpr>(c->getLHS()->IgnoreParenImpCasts());
  if (lhs && lhs->getDecl() == var)
    return expr(c->getRHS());
  // The counter is bound to a placeholder counter while the sides are
  // lowered, named apart from every counter already named.
  std::string placeholder = "dpgen_counter";
  for (int n = 1; loop_names_.count(placeholder); ++n)
    placeholder = fmt::format("dpgen_counter_{}", n);
  auto saved = env_.find(var) != env_.end() ? std::optional<Binding>(env_[var]) : std::nullopt;
  Binding b;
  b.kind = Binding::LoopVar;
  b.value = loop_var(placeholder);
  env_[var] = b;
  ExprP l = expr(c->getLHS()), r = expr(c->getRHS());
  if (saved)
    env_[var] = *saved;
  else
    env_.erase(var);
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
    switch (op) {
    case BO_LT: op = BO_GT; break;
    case BO_LE: op = BO_GE; break;
    case BO_GT: op = BO_LT; break;
    case BO_GE: op = BO_LE; break;
    default: break;
    }
    return poly_expr(rest);
  }
  return poly_expr(-rest); // i + rest op 0  <=>  i op -rest
}

// An integer expression for a polynomial over parameters and kernel-level
// locals (symbols resolve to what they name).
ExprP Lowerer::poly_expr(const Poly& p) {
  ExprP sum;
  for (const auto& [m, coef] : p.terms()) {
    ExprP term = int_const(coef);
    for (const auto& sym : m)
      term = binary(Op::Mul, term, symbol_expr(sym));
    sum = sum ? binary(Op::Add, sum, term) : term;
  }
  return sum ? sum : int_const(0);
}

ExprP Lowerer::symbol_expr(const Sym& sym) {
  if (sym.is_counter())
    throw std::logic_error("lower: a loop counter in a size: " + sym.name);
  if (const Param* p = k_.find_param(sym.name))
    return param(p->name, p->elem);
  for (const auto& l : k_.kernel_locals)
    if (l->name == sym.name)
      return local_ref(l);
  if (object_values_.count(sym.name)) // bx.smallEnd(0), u.extent(1) (lower_view.cpp)
    return param(sym.name, Type::Int);
  throw std::logic_error("lower: unknown symbol " + sym.name);
}

// Every local variable assigned (=, op=, ++, --) somewhere in `s`.
// The extreme (the largest if `upper`, else the smallest) of loop bound `e`
// (`p` as a polynomial) over the enclosing loops' ranges: each outer counter
// replaced by its first or last value, by the sign of its coefficient. Null
// where a coefficient is not a constant.
std::optional<ExprP> Lowerer::hull(const ExprP& e, const Poly& p, bool upper) const {
  std::map<std::string, ExprP> at;
  for (const auto& l : loops_) {
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

// A lower bound of integer `e` over the enclosing loops that depends on the
// sizes only: `e` itself where it mentions no counter, the hull of an
// affine part, 0 for `x % m` with a constant m > 0 and x >= 0 (C's
// remainder of a non-negative value), sums of those. Null otherwise.
std::optional<ExprP> Lowerer::smallest(const ExprP& e) const {
  if (!any_node(e, [](const ExprP& x) { return x->op == Op::LoopVar; }))
    return e;
  if (auto p = to_poly(e))
    return hull(e, *p, false);
  if (e->op == Op::Add) {
    auto a = smallest(e->ops[0]), b = smallest(e->ops[1]);
    if (a && b)
      return binary(Op::Add, *a, *b);
    return std::nullopt;
  }
  if (e->op == Op::Rem && e->ops[1]->op == Op::IntConst && e->ops[1]->ival > 0 &&
      provably_nonneg(e->ops[0]))
    return int_const(0);
  if (e->op == Op::Local)
    return smallest(e->local->def);
  return std::nullopt;
}

// The term `e` of `v = v + e`, `v = v - e` (negate set) or `v = e + v`,
// where `e` does not mention v; null for any other form.
const clang::Expr* Lowerer::accumulated_term(const clang::Expr* rhs, const VarDecl* v, bool& negate) {
  const auto* b = dyn_cast<BinaryOperator>(rhs->IgnoreParenImpCasts());
  if (!b || (b->getOpcode() != BO_Add && b->getOpcode() != BO_Sub))
    return nullptr;
  auto is_v = [&](const clang::Expr* e) {
    const auto* r = dyn_cast<DeclRefExpr>(e->IgnoreParenImpCasts());
    return r && r->getDecl() == v;
  };
  const clang::Expr* term = nullptr;
  if (is_v(b->getLHS()))
    term = b->getRHS();
  else if (b->getOpcode() == BO_Add && is_v(b->getRHS()))
    term = b->getLHS();
  if (!term || mentions(term, v))
    return nullptr;
  negate = b->getOpcode() == BO_Sub;
  return term;
}

bool Lowerer::mentions(const Stmt* s, const ValueDecl* v) {
  if (!s)
    return false;
  if (const auto* r = dyn_cast<DeclRefExpr>(s); r && r->getDecl() == v)
    return true;
  for (const Stmt* c : s->children())
    if (mentions(c, v))
      return true;
  return false;
}

// Every mention of `v` in `body` is the target of `v += e`, `v -= e` or
// `v = v + e` (and its `v`), with `e` free of v, and there is at least one.
bool Lowerer::is_accumulator(const Stmt* body, const VarDecl* v) {
  int updates = 0;
  bool other = false;
  std::function<void(const Stmt*)> visit = [&](const Stmt* s) {
    if (!s || other)
      return;
    if (const auto* b = dyn_cast<BinaryOperator>(s); b && b->isAssignmentOp()) {
      const auto* r = dyn_cast<DeclRefExpr>(b->getLHS()->IgnoreParenImpCasts());
      if (r && r->getDecl() == v) {
        bool negate = false;
        bool ok = b->getOpcode() == BO_AddAssign || b->getOpcode() == BO_SubAssign
                      ? !mentions(b->getRHS(), v)
                      : b->getOpcode() == BO_Assign &&
                            accumulated_term(b->getRHS(), v, negate) != nullptr;
        if (!ok)
          other = true;
        ++updates;
        return;
      }
    }
    if (const auto* r = dyn_cast<DeclRefExpr>(s); r && r->getDecl() == v) {
      other = true;
      return;
    }
    for (const Stmt* c : s->children())
      visit(c);
  };
  visit(body);
  return updates > 0 && !other;
}

bool Lowerer::same_expr(const clang::Expr* a, const clang::Expr* b) const {
  llvm::FoldingSetNodeID x, y;
  a->IgnoreParenImpCasts()->Profile(x, ctx_, true);
  b->IgnoreParenImpCasts()->Profile(y, ctx_, true);
  return x == y;
}

bool Lowerer::is_target(const clang::Expr* e, const ReductionTarget& t) const {
  if (t.element)
    return same_expr(e, t.element);
  const auto* r = dyn_cast<DeclRefExpr>(e->IgnoreParenImpCasts());
  return r && r->getDecl() == t.decl;
}

Lowerer::ReductionTarget Lowerer::target_of(const clang::Expr* lhs) {
  lhs = lhs->IgnoreParenImpCasts();
  if (const auto* r = dyn_cast<DeclRefExpr>(lhs))
    return {dyn_cast<VarDecl>(r->getDecl()), nullptr};
  const clang::Expr* base = nullptr;
  if (const auto* u = dyn_cast<UnaryOperator>(lhs); u && u->getOpcode() == UO_Deref)
    base = u->getSubExpr();
  else if (const auto* sub = dyn_cast<ArraySubscriptExpr>(lhs))
    base = sub->getBase();
  while (base) { // p[j][i]: p
    base = base->IgnoreParenImpCasts();
    if (const auto* sub = dyn_cast<ArraySubscriptExpr>(base)) {
      base = sub->getBase();
      continue;
    }
    if (const auto* r = dyn_cast<DeclRefExpr>(base))
      if (isa<ParmVarDecl>(r->getDecl()))
        return {r->getDecl(), lhs};
    break;
  }
  return {};
}

// The term `e` of a min/max update of `t` (lower_impl.hpp).
const clang::Expr* Lowerer::extremum_term(const clang::Expr* rhs, const ReductionTarget& t,
                                          int& extremum) const {
  auto is_t = [&](const clang::Expr* e) { return is_target(e, t); };
  rhs = rhs->IgnoreParenImpCasts();
  // std::max(v, e), fmax(e, v), fminf(v, e), ...
  if (const auto* c = dyn_cast<CallExpr>(rhs); c && c->getNumArgs() == 2) {
    const FunctionDecl* f = c->getDirectCallee();
    const MathFn* m =
        f && !isa<CXXMethodDecl>(f) ? find_math_function(f->getNameAsString()) : nullptr;
    bool from_library = f && (sm_.isInSystemHeader(sm_.getExpansionLoc(f->getLocation())) ||
                              f->getBuiltinID() != 0);
    if (!m || !from_library || (m->name != "max" && m->name != "min"))
      return nullptr;
    const clang::Expr *a = c->getArg(0), *b = c->getArg(1);
    const clang::Expr* term = is_t(a) ? b : is_t(b) ? a : nullptr;
    if (!term || mentions(term, t.decl))
      return nullptr;
    extremum = m->name == "max" ? 1 : -1;
    return term;
  }
  // v > e ? v : e, e < v ? v : e, v < e ? v : e (min), ... (a MAX macro)
  const auto* co = dyn_cast<ConditionalOperator>(rhs);
  if (!co)
    return nullptr;
  const auto* cmp = dyn_cast<BinaryOperator>(co->getCond()->IgnoreParenImpCasts());
  if (!cmp || !cmp->isRelationalOp())
    return nullptr;
  const clang::Expr *yes = co->getTrueExpr(), *no = co->getFalseExpr();
  const clang::Expr* term = is_t(yes) ? no : is_t(no) ? yes : nullptr;
  if (!term || mentions(term, t.decl))
    return nullptr;
  // The comparison's sides are the target and the same e as the other arm.
  const clang::Expr *l = cmp->getLHS(), *r = cmp->getRHS();
  bool t_left = is_t(l) && same_expr(r, term), t_right = is_t(r) && same_expr(l, term);
  if (!t_left && !t_right)
    return nullptr;
  // `l > r ? l : r` is a max, `l > r ? r : l` a min; `<` the other way.
  bool greater = cmp->getOpcode() == BO_GT || cmp->getOpcode() == BO_GE;
  bool picks_left = t_left ? is_t(yes) : !is_t(yes);
  extremum = greater == picks_left ? 1 : -1;
  return term;
}

// `if (e > v) v = e;` (lower_impl.hpp).
const clang::Expr* Lowerer::extremum_if(const IfStmt* s, ReductionTarget& t, int& extremum,
                                        const clang::Expr** extra) const {
  if (s->getElse() || s->getInit() || s->getConditionVariable() || s->isConstexpr())
    return nullptr;
  const Stmt* body = s->getThen();
  if (const auto* cs = dyn_cast<CompoundStmt>(body)) {
    if (cs->size() != 1)
      return nullptr;
    body = cs->body_front();
  }
  const auto* as = dyn_cast<BinaryOperator>(body);
  if (!as || as->getOpcode() != BO_Assign)
    return nullptr;
  t = target_of(as->getLHS());
  if (!t.decl)
    return nullptr;
  const auto* cmp = dyn_cast<BinaryOperator>(s->getCond()->IgnoreParenImpCasts());
  // `if (e > m && i > 0) m = e;`: the update where the other conjunct holds.
  const clang::Expr* rest = nullptr;
  if (cmp && cmp->getOpcode() == BO_LAnd) {
    for (const clang::Expr* side : {cmp->getLHS(), cmp->getRHS()}) {
      const auto* b = dyn_cast<BinaryOperator>(side->IgnoreParenImpCasts());
      if (b && b->isRelationalOp() && mentions(b, t.decl)) {
        rest = side == cmp->getLHS() ? cmp->getRHS() : cmp->getLHS();
        cmp = b;
        break;
      }
    }
    if (!rest || mentions(rest, t.decl) || !extra)
      return nullptr;
  }
  if (!cmp || !cmp->isRelationalOp())
    return nullptr;
  if (extra)
    *extra = rest;
  const clang::Expr* term = as->getRHS();
  if (mentions(term, t.decl))
    return nullptr;
  bool t_left = is_target(cmp->getLHS(), t) && same_expr(cmp->getRHS(), term);
  bool t_right = is_target(cmp->getRHS(), t) && same_expr(cmp->getLHS(), term);
  if (!t_left && !t_right)
    return nullptr;
  // `if (e > v) v = e` keeps the larger: a max; `if (v > e) v = e` a min.
  bool greater = cmp->getOpcode() == BO_GT || cmp->getOpcode() == BO_GE;
  extremum = greater == t_right ? 1 : -1;
  return term;
}

// +1 or -1 if every mention of `t.decl` in `body` is in a min/max update of
// `t` of one kind (lower_impl.hpp).
int Lowerer::extremum_kind(const Stmt* body, const ReductionTarget& t) const {
  int kind = 0, updates = 0;
  bool other = false;
  std::function<void(const Stmt*)> visit = [&](const Stmt* s) {
    if (!s || other)
      return;
    int k = 0;
    if (const auto* i = dyn_cast<IfStmt>(s)) {
      ReductionTarget u;
      const clang::Expr* rest = nullptr;
      bool same = extremum_if(i, u, k, &rest) && u.decl == t.decl &&
                  (t.element ? u.element && same_expr(u.element, t.element) : !u.element);
      if (same) {
        other = other || (kind != 0 && k != kind);
        kind = k;
        ++updates;
        return;
      }
    }
    if (const auto* b = dyn_cast<BinaryOperator>(s); b && b->isAssignmentOp()) {
      if (is_target(b->getLHS(), t)) {
        if (b->getOpcode() != BO_Assign || !extremum_term(b->getRHS(), t, k) ||
            (kind != 0 && k != kind)) {
          other = true;
          return;
        }
        kind = k;
        ++updates;
        return;
      }
    }
    if (const auto* r = dyn_cast<DeclRefExpr>(s); r && r->getDecl() == t.decl) {
      other = true;
      return;
    }
    for (const Stmt* c : s->children())
      visit(c);
  };
  visit(body);
  return updates > 0 && !other ? kind : 0;
}

// A read of hidden work array `array` at `idx` by a later nest.
ExprP Lowerer::hidden_read(const std::string& array, const ExprP& idx, SourceLocation loc) {
  const Param* h = k_.find_param(array);
  ExprP r = read(array, idx, h->elem, pos(loc), {});
  std::const_pointer_cast<Expr>(r)->source = h->spelling;
  k_.intermediates.insert(array);
  acc_.work_reads.push_back({array, cur_key(), next_store_seq_, idx, path_, pos(loc)});
  return r;
}

// The update `v = max(v, e)` here (lower_impl.hpp).
void Lowerer::extremum_update(Accumulator& a, const clang::Expr* term, Type t,
                              SourceLocation loc) {
  ExprP e = cast(expr(term), t);
  add_store(a.array, a.index, call("dpgen_nograd", {e}, t), true, pos(loc), loc, a.extremum);
  ExtremumUpdate u;
  u.term = e;
  u.path = path_;
  for (size_t d = a.depth; d < loops_.size(); ++d)
    u.loops.push_back(*loops_[d]);
  u.pos = pos(loc);
  a.updates.push_back(u);
}

// After the reducing loop: the ties and the result (lower_impl.hpp).
void Lowerer::finish_extremum(const Accumulator& a, SourceLocation loc) {
  const Type t = k_.find_param(a.array)->elem;
  auto ng = [&](const ExprP& x) { return call("dpgen_nograd", {x}, t); };
  auto one = real_const(1, t), nil = real_const(0, t);
  // A store after every nest so far that stores `array`'s inputs.
  auto straight = [&](const std::string& reads, const std::string& array, auto&& value) {
    order_after_later_stores(reads);
    add_store(array, a.index, value(), false, pos(loc), loc);
  };
  // One nest per update, with the update's loops and path.
  auto per_update = [&](const std::string& array, auto&& value) {
    for (const auto& u : a.updates) {
      auto path_before = path_;
      for (const auto& l : u.loops) {
        loops_.push_back(std::make_shared<Loop>(l));
        loop_ids_.push_back(next_loop_id_++);
        segments_.push_back(--next_segment_);
      }
      path_ = u.path;
      add_store(array, a.index, value(u.term), true, u.pos, loc);
      for (size_t i = 0; i < u.loops.size(); ++i) {
        loops_.pop_back();
        loop_ids_.pop_back();
        segments_.pop_back();
      }
      path_ = path_before;
    }
  };
  // T = [S == M] + sum [e == M]
  straight(a.array, a.ties, [&] {
    ExprP m = ng(hidden_read(a.array, a.index, loc));
    return select(binary(Op::Eq, hidden_read(a.start, a.index, loc), m), one, nil);
  });
  per_update(a.ties, [&](const ExprP& e) {
    ExprP m = ng(hidden_read(a.array, a.index, loc));
    return select(binary(Op::Eq, e, m), one, nil);
  });
  // R = M + [S == M](S - M)/T + sum [e == M](e - M)/T
  auto share = [&](const ExprP& x) {
    ExprP m = ng(hidden_read(a.array, a.index, loc));
    ExprP ties = ng(hidden_read(a.ties, a.index, loc));
    return select(binary(Op::Eq, x, m), binary(Op::Div, binary(Op::Sub, x, m), ties), nil);
  };
  straight(a.ties, a.result, [&] {
    return binary(Op::Add, ng(hidden_read(a.array, a.index, loc)),
                  share(hidden_read(a.start, a.index, loc)));
  });
  per_update(a.result, share);
}

// Makes `v` (a real scalar with a value here) an accumulator of the loop
// about to be lowered (a min/max reduction if `extremum`); false (and
// nothing done) where it cannot be one.
bool Lowerer::start_accumulator(const VarDecl* v, SourceLocation loc, int extremum) {
  auto it = env_.find(v);
  if (it == env_.end() || it->second.kind != Binding::Value || !it->second.value ||
      !is_real((*it->second.value)->type) || v->getType()->isReferenceType())
    return false;
  auto a = make_accumulator(v->getNameAsString(), v->getNameAsString(), *it->second.value,
                            extremum, loc, nullptr);
  if (!a)
    return false;
  accumulators_[v] = *a;
  return true;
}

// The hidden arrays of an accumulator of the loop about to be lowered, from
// value `init`, and their stores before the loop (lower_impl.hpp); `start`:
// a store of `init` to reuse as the start's.
std::optional<Lowerer::Accumulator> Lowerer::make_accumulator(const std::string& name,
                                                              const std::string& spelling,
                                                              ExprP init, int extremum,
                                                              SourceLocation loc, Store* start) {
  // One element per iteration of the enclosing loops: (outer - lo) * extent
  // of the inner ones + ..., which needs polynomial bounds.
  ExprP idx = int_const(0);
  for (size_t d = 0; d < loops_.size(); ++d) {
    const Loop& l = *loops_[d];
    if (!to_poly(l.lo) || !to_poly(l.hi))
      return std::nullopt;
    ExprP here = binary(Op::Sub, loop_var(l.var), l.lo);
    idx = d == 0 ? here
                 : binary(Op::Add, binary(Op::Mul, idx, binary(Op::Sub, l.hi, l.lo)), here);
  }
  if (k_.hidden.size() + (extremum ? 4 : 1) > k_.hidden.capacity())
    return std::nullopt; // (pointers into it must stay valid while lowering)
  const Type t = init->type;
  auto hidden = [&](const char* what) {
    Param h;
    h.name = fmt::format("dpgen_{}_{}", what, name);
    for (int n = 2; k_.find_param(h.name); ++n)
      h.name = fmt::format("dpgen_{}_{}_{}", what, name, n);
    h.kind = ParamKind::Out;
    h.elem = t;
    h.elem_name = type_spelling(h.elem);
    h.spelling = spelling; // the user's accumulator, for messages
    h.declaration = fmt::format("{}* {}", h.elem_name, h.name);
    k_.hidden.push_back(h);
    return h.name;
  };
  Accumulator a;
  a.index = idx;
  a.extremum = extremum;
  a.depth = loops_.size();
  if (extremum == 0) {
    a.array = hidden("sum");
    add_store(a.array, idx, init, false, pos(loc), loc);
    return a;
  }
  a.start = hidden("start");
  a.array = hidden("scan");
  a.ties = hidden("ties");
  a.result = hidden(extremum > 0 ? "max" : "min");
  if (start) { // (before add_store, which may move it)
    start->array = a.start;
    start->index = idx;
  } else {
    add_store(a.start, idx, init, false, pos(loc), loc);
  }
  add_store(a.array, idx, call("dpgen_nograd", {init}, t), false, pos(loc), loc);
  return a;
}

// The element reductions of loop `f` (lower_impl.hpp): assignments in its
// body to an element of a DPGEN_OUT parameter at an index the loop does not
// change, every one a min/max update of that element.
void Lowerer::start_element_reductions(const ForStmt* f, const VarDecl* counter_decl,
                                       const std::set<const VarDecl*>& assigned) {
  std::vector<ReductionTarget> targets;
  std::function<void(const Stmt*)> visit = [&](const Stmt* s) {
    if (!s)
      return;
    const clang::Expr* lhs = nullptr;
    if (const auto* b = dyn_cast<BinaryOperator>(s); b && b->getOpcode() == BO_Assign)
      lhs = b->getLHS();
    ReductionTarget t = lhs ? target_of(lhs) : ReductionTarget{};
    if (t.element && isa<ParmVarDecl>(t.decl)) {
      bool known = std::any_of(targets.begin(), targets.end(), [&](const ReductionTarget& o) {
        return same_expr(o.element, t.element);
      });
      // (its subscripts mention neither the loop's counter nor a variable
      // the loop assigns)
      std::vector<const clang::Expr*> subscripts;
      for (const clang::Expr* e = t.element->IgnoreParenImpCasts();
           const auto* sub = dyn_cast<ArraySubscriptExpr>(e);
           e = sub->getBase()->IgnoreParenImpCasts())
        subscripts.push_back(sub->getIdx());
      bool loop_invariant = true;
      for (const clang::Expr* x : subscripts) {
        loop_invariant = loop_invariant && !mentions(x, counter_decl);
        for (const VarDecl* v : assigned)
          loop_invariant = loop_invariant && !mentions(x, v);
      }
      if (!known && loop_invariant)
        targets.push_back(t);
    }
    for (const Stmt* c : s->children())
      visit(c);
  };
  visit(f->getBody());
  for (const auto& t : targets) {
    bool active = std::any_of( // (an outer loop's reduction)
        element_reductions_.begin(), element_reductions_.end(),
        [&](const ElementReduction& r) { return same_expr(r.target.element, t.element); });
    int kind = active ? 0 : extremum_kind(f->getBody(), t);
    if (kind == 0)
      continue;
    auto acc = element(t.element);
    if (!acc || !acc->dims.empty() || acc->param->kind != ParamKind::Out || acc->param->inout || acc->param->global)
      continue;
    const Param* p = acc->param;
    auto nit = nest_index_.find(cur_key());
    Store* prev = nit == nest_index_.end()
                      ? nullptr
                      : visible_store(k_.nests[nit->second], p->name, acc->index);
    if (!prev || prev->accumulate)
      fail(t.element->getBeginLoc(),
           fmt::format("the {} reduction into '{}' in this loop starts from the value it has "
                       "before the loop, which the kernel does not set (the caller's, which the "
                       "adjoint does not have): store the start value first (`{} = 0.0;`), or "
                       "reduce into a local and store that after the loop",
                       kind > 0 ? "max" : "min", text(t.element), text(t.element)),
           "dpgen-reduction");
    ExprP init = prev->value;
    auto a = make_accumulator(p->name, text(t.element), init, kind, f->getForLoc(), prev);
    if (!a)
      fail(t.element->getBeginLoc(),
           fmt::format("the {} reduction into '{}': dpgen cannot number the iterations of the "
                       "loops around it (bounds that are not polynomials in the sizes)",
                       kind > 0 ? "max" : "min", text(t.element)),
           "dpgen-reduction");
    element_reductions_.push_back({t, p->name, acc->index, *a});
  }
}

// After the reducing loop: each element reduction started at or after `from`
// is stored its result.
void Lowerer::finish_element_reductions(size_t from, SourceLocation loc) {
  while (element_reductions_.size() > from) {
    const ElementReduction r = element_reductions_.back();
    element_reductions_.pop_back();
    finish_extremum(r.acc, loc);
    order_after_later_stores(r.acc.result);
    ExprP v = hidden_read(r.acc.result, r.acc.index, loc);
    add_store(r.array, r.index, v, false, pos(loc), loc);
  }
}

// After the accumulating loop: `v` is the sum, a read of its element.
void Lowerer::finish_accumulator(const VarDecl* v, SourceLocation loc) {
  const Accumulator a = accumulators_.at(v);
  accumulators_.erase(v);
  if (a.extremum != 0)
    finish_extremum(a, loc);
  const std::string& sum = a.extremum != 0 ? a.result : a.array;
  order_after_later_stores(sum);
  ExprP r = hidden_read(sum, a.index, loc);
  std::const_pointer_cast<Expr>(r)->source = v->getNameAsString();
  env_[v].value = r;
  why_unset_.erase(v);
}

void Lowerer::assigned_vars(const Stmt* s, std::set<const VarDecl*>& out) {
  if (!s)
    return;
  auto target = [&](const clang::Expr* e) {
    e = e->IgnoreParenImpCasts();
    if (const auto* sub = dyn_cast<ArraySubscriptExpr>(e)) // an element of a local array
      e = sub->getBase()->IgnoreParenImpCasts();
    if (const auto* r = dyn_cast<DeclRefExpr>(e))
      if (const auto* v = dyn_cast<VarDecl>(r->getDecl()))
        out.insert(v);
  };
  if (const auto* b = dyn_cast<BinaryOperator>(s); b && b->isAssignmentOp())
    target(b->getLHS());
  if (const auto* u = dyn_cast<UnaryOperator>(s); u && u->isIncrementDecrementOp())
    target(u->getSubExpr());
  // Assigned through a call: a local passed to a helper's non-const
  // reference (`setv(s, x)`) or by address (`upd(&s, x)`), and what a lambda
  // called here assigns among the variables it captures by reference (its
  // body names them directly). Without this, `s` after the loop would keep
  // the value it had before it.
  if (const auto* c = dyn_cast<CallExpr>(s)) {
    const FunctionDecl* f = c->getDirectCallee();
    // (a member operator's call, `v(i, j, k)`: argument 0 is the object)
    const unsigned shift = isa<CXXOperatorCallExpr>(c) && f && isa<CXXMethodDecl>(f) ? 1 : 0;
    for (unsigned i = shift; i < c->getNumArgs(); ++i) {
      const clang::Expr* a = c->getArg(i)->IgnoreParenImpCasts();
      bool by_address = false;
      if (const auto* u = dyn_cast<UnaryOperator>(a); u && u->getOpcode() == UO_AddrOf) {
        a = u->getSubExpr();
        by_address = true;
      }
      const unsigned pi = i - shift;
      QualType pt = f && pi < f->getNumParams() ? f->getParamDecl(pi)->getType() : QualType();
      bool writable = by_address || (pt.isNull() && !f) ||
                      (pt->isReferenceType() && !pt.getNonReferenceType().isConstQualified()) ||
                      (pt->isPointerType() && !pt->getPointeeType().isConstQualified());
      if (writable)
        target(a);
    }
  }
  if (const auto* r = dyn_cast<DeclRefExpr>(s)) {
    const auto* rd = r->getType().getNonReferenceType()->getAsCXXRecordDecl();
    if (rd && rd->isLambda() && lambdas_seen_.insert(rd).second) {
      if (const CXXMethodDecl* call = rd->getLambdaCallOperator())
        assigned_vars(call->getBody(), out);
      lambdas_seen_.erase(rd);
    }
  }
  if (const auto* le = dyn_cast<LambdaExpr>(s)) { // (a lambda written at its use)
    if (lambdas_seen_.insert(le->getLambdaClass()).second) {
      assigned_vars(le->getBody(), out);
      lambdas_seen_.erase(le->getLambdaClass());
    }
    return;
  }
  for (const Stmt* c : s->children())
    assigned_vars(c, out);
}

int Lowerer::loop_step(const clang::Expr* inc, const VarDecl* var) {
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
    if (!is_var(b->getLHS()) || !b->getRHS()->EvaluateAsInt(r, ctx_))
      return 0;
    int64_t k = r.Val.getInt().getSExtValue();
    if (k < 1 || k > 1024)
      return 0;
    return b->getOpcode() == BO_AddAssign ? int(k) : b->getOpcode() == BO_SubAssign ? -int(k) : 0;
  }
  return 0;
}

void Lowerer::check_not_assigned(const Stmt* s, const VarDecl* var) {
  if (!s)
    return;
  auto refers = [&](const clang::Expr* e) {
    const auto* r = dyn_cast<DeclRefExpr>(e->IgnoreParenImpCasts());
    return r && r->getDecl() == var;
  };
  if (const auto* b = dyn_cast<BinaryOperator>(s); b && b->isAssignmentOp() && refers(b->getLHS()))
    fail(b->getOperatorLoc(), fmt::format("loop counter '{}' is modified in the loop body",
                                          var->getNameAsString()), "dpgen-loop");
  if (const auto* u = dyn_cast<UnaryOperator>(s);
      u && u->isIncrementDecrementOp() && refers(u->getSubExpr()))
    fail(u->getOperatorLoc(), fmt::format("loop counter '{}' is modified in the loop body",
                                          var->getNameAsString()), "dpgen-loop");
  for (const Stmt* c : s->children())
    check_not_assigned(c, var);
}

} // namespace dpgen::lowering
