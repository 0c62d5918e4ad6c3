// Lowering, loops: a `for` statement lowered (unrolled when small, else a
// Loop of the nest), and the variables its body assigns (lower_loop.hpp).
#include "lower_impl.hpp"

namespace dpgen::lowering {

// Loop nests up to this deep (component loops around a 3D stencil, coarsening
// loops inside a cell loop); deeper nests are refused.
constexpr size_t kMaxLoopDepth = 6;

bool ForLoops::should_unroll(const ForStmt* f, const ForHeader& h, long long lo, long long hi) {
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
      if (const auto* v = dyn_cast<VarDecl>(r->getDecl());
          v && L.env_.count(v) && L.env_[v].kind == Binding::LocalArray)
        touches = true;
    // a constant integer table (`constexpr int cx[9]`) indexed by the
    // counter: unrolled, each copy reads one value (a constant offset)
    if (const auto* a = dyn_cast<ArraySubscriptExpr>(s))
      if (const auto* r = dyn_cast<DeclRefExpr>(a->getBase()->IgnoreParenImpCasts()))
        if (const auto* v = dyn_cast<VarDecl>(r->getDecl());
            v && L.global_decls_.count(v->getNameAsString()) &&
            L.global_decls_.at(v->getNameAsString()) == v && v->getType().isConstQualified() &&
            v->getType()->isArrayType() &&
            v->getType()->getArrayElementTypeNoTypeQual()->isIntegerType())
          if (const auto* i = dyn_cast<DeclRefExpr>(a->getIdx()->IgnoreParenImpCasts());
              i && counter && i->getDecl() == counter)
            touches = true;
    for (const Stmt* c : s->children())
      scan(c);
  };
  scan(f->getBody());
  for (const VarDecl* v : h.assigned)
    if (L.env_.count(v) && L.env_[v].kind == Binding::Value)
      touches = true;
  return touches;
}

bool ForLoops::forget_value(const VarDecl* v) {
  auto it = L.env_.find(v);
  if (it == L.env_.end() ||
      (it->second.kind != Binding::Value && it->second.kind != Binding::LocalArray))
    return false;
  it->second.value = std::nullopt;
  for (auto& el : it->second.elems)
    el = std::nullopt;
  return true;
}

// A small loop with constant bounds that should_unroll() picks: its body
// lowered once per value of the counter; false (nothing done) for any other.
bool ForLoops::unroll(const ForStmt* f, const ForHeader& h) {
  const VarDecl* const var = h.var;
  const ExprP &lo = h.lo, &hi = h.hi;
  const int step = h.step;
  {
    auto plo = to_poly(lo), phi = to_poly(hi);
    if (plo->is_constant() && phi->is_constant() && h.triangle.empty() && !h.parity_start &&
        should_unroll(f, h, plo->constant_term(), phi->constant_term())) {
      check_not_assigned(f->getBody(), var);
      for (const auto& c : h.companions)
        check_not_assigned(f->getBody(), c.var);
      const auto env_before = L.env_;
      size_t depth = L.path_.size();
      ++L.unrolling_;
      // every step-th value from lo up (i += s), or from hi - 1 down (i -= s)
      const long long stride = step > 0 ? step : -step;
      long long n = 0; // (the iteration's number, for the companions)
      for (long long k = plo->constant_term(); k < phi->constant_term(); k += stride, ++n) {
        long long v = step > 0 ? k : plo->constant_term() + phi->constant_term() - 1 - k;
        Binding b;
        b.kind = Binding::Value;
        b.value = int_const(v);
        L.env_[var] = b;
        for (const auto& c : h.companions) {
          b.value = binary(Op::Add, c.init, int_const(c.step * n));
          if (c.is_unsigned)
            check_stays_nonneg(c, *b.value, h.var);
          L.env_[c.var] = b;
        }
        lower_copy(f->getBody(), depth);
      }
      --L.unrolling_;
      counters_after(h, env_before);
      return true;
    }
  }
  return false;
}

// One copy of an unrolled loop's body (the path back at `depth` after it;
// on a refusal, the unrolling ended too).
void ForLoops::lower_copy(const Stmt* body, size_t depth) {
  try {
    L.stmts_.lower(body);
  } catch (const Rejected&) {
    --L.unrolling_;
    L.path_.resize(depth);
    throw;
  }
  L.path_.resize(depth);
}

// `for (double w : weights)` over a local array (a C array or std::array,
// whose elements dpgen keeps as values): unrolled, the variable bound to
// each element in turn; over anything else, refused.
void ForLoops::range_for(const CXXForRangeStmt* f) {
  const clang::Expr* range = f->getRangeInit()->IgnoreParenImpCasts();
  const auto* r = dyn_cast<DeclRefExpr>(range);
  auto it = r ? L.env_.find(dyn_cast<VarDecl>(r->getDecl())) : L.env_.end();
  if (it == L.env_.end() || it->second.kind != Binding::LocalArray || it->second.elems.empty())
    L.fail(f->getBeginLoc(),
           "a range-based for runs over a local array of constant length (a table: 'for "
           "(double w : weights)'); over anything else, use an integer counter",
           "dpgen-loop");
  const VarDecl* var = f->getLoopVariable();
  const std::string array = r->getDecl()->getNameAsString();
  QualType vt = var->getType();
  if (vt->isReferenceType() && !vt.getNonReferenceType().isConstQualified())
    L.fail(var->getLocation(),
           fmt::format("'{}' is a non-const reference into local array '{}'; a range-based "
                       "for reads its elements ('const double& {}' or 'double {}'): assign "
                       "them through an integer counter",
                       var->getNameAsString(), array, var->getNameAsString(),
                       var->getNameAsString()),
           "dpgen-loop");
  auto t = L.scalar_type(vt.getNonReferenceType());
  if (!t)
    L.fail(var->getLocation(),
           fmt::format("'{}' of type '{}' is outside the kernel subset (int, float or double)",
                       var->getNameAsString(), vt.getAsString()),
           "dpgen-loop");
  const std::vector<std::optional<ExprP>> elems = it->second.elems; // (the body may not change
  std::set<const VarDecl*> assigned; //              them: checked below)
  assigned_vars(f->getBody(), assigned);
  if (assigned.count(dyn_cast<VarDecl>(r->getDecl())))
    L.fail(f->getBeginLoc(),
           fmt::format("the body of a range-based for over '{}' assigns '{}'; fill the array "
                       "in a loop of its own",
                       array, array),
           "dpgen-loop");
  const size_t depth = L.path_.size();
  ++L.unrolling_;
  for (size_t k = 0; k < elems.size(); ++k) {
    if (!elems[k]) {
      --L.unrolling_;
      L.fail(range->getBeginLoc(),
             fmt::format("element {} of local array '{}' is read before it is assigned", k,
                         array),
             "dpgen-loop");
    }
    Binding b;
    b.kind = Binding::Value;
    b.value = cast(*elems[k], *t);
    L.env_[var] = b;
    lower_copy(f->getBody(), depth);
  }
  --L.unrolling_;
  L.env_.erase(var);
}

void ForLoops::for_loop(const ForStmt* f) {
  const ForHeader h = L.headers_.for_header(f);
  if (unroll(f, h))
    return;
  const VarDecl* const var = h.var;
  const ExprP &lo = h.lo, &hi = h.hi, &parity_start = h.parity_start;
  const int step = h.step, parity_step = h.parity_step;
  const auto& triangle = h.triangle;
  if (L.loops_.size() == kMaxLoopDepth)
    L.fail(f->getBeginLoc(),
           fmt::format("loops nest at most {} deep in the kernel subset", kMaxLoopDepth),
           "dpgen-loop");

  auto loop = std::make_shared<Loop>();
  // The counter keeps its name unless that would collide with a parameter,
  // a local or an enclosing counter in the generated code.
  const bool strided = step > 1 || step < -1;
  std::string base = var->getNameAsString() + (strided ? "_step" : "");
  loop->var = base;
  for (int n = 1; L.is_reserved(loop->var) || L.local_names_.count(loop->var); ++n)
    loop->var = fmt::format("{}_{}", L.unprefixed(base), n);
  L.loop_names_.insert(loop->var);
  // (a strided loop counts its steps, which may number below zero for an
  // empty range: signed, whatever the kernel's counter is)
  loop->type_name = strided && var->getType()->isUnsignedIntegerType() ? "std::ptrdiff_t"
                                                                       : L.spelled(var->getType());
  loop->lo = lo;
  loop->hi = hi;
  loop->descending = step == -1;
  ExprP counter = loop_var(loop->var);
  if (strided) {
    // for (i = lo; i < hi; i += s): the loop runs over the steps t in
    // [0, (hi - lo + s - 1) / s) and i = lo + s * t; counting down from
    // hi - 1 (i -= s), i = hi - 1 - s * t, in the kernel's order.
    const int s_abs = step > 0 ? step : -step;
    auto trips = std::make_shared<LocalVar>();
    trips->name = loop->var + "_count";
    for (int n = 1; L.local_names_.count(trips->name) || L.is_reserved(trips->name); ++n)
      trips->name = fmt::format("{}_count_{}", L.unprefixed(loop->var), n);
    L.local_names_.insert(trips->name);
    trips->type_name = "std::ptrdiff_t";
    trips->def = binary(Op::Div, binary(Op::Add, binary(Op::Sub, hi, lo), int_const(s_abs - 1)),
                        int_const(s_abs));
    trips->id = L.next_local_id_++;
    trips->kernel_level = true;
    L.k_.kernel_locals.push_back(trips);
    loop->lo = int_const(0);
    loop->hi = local_ref(trips);
    counter = step > 0 ? binary(Op::Add, lo, binary(Op::Mul, int_const(step), counter))
                       : binary(Op::Sub, binary(Op::Sub, hi, int_const(1)),
                                binary(Op::Mul, int_const(s_abs), counter));
  }

  check_not_assigned(f->getBody(), var);
  for (const auto& c : h.companions)
    check_not_assigned(f->getBody(), c.var);
  size_t depth = L.path_.size();
  auto env_before = L.env_;
  auto why_before = L.why_unset_;
  Binding b;
  b.kind = Binding::LoopVar;
  b.value = counter;
  L.env_[var] = b;
  // Companion counters: init + step * the iteration's number.
  const ExprP trip = strided     ? loop_var(loop->var)
                     : step > 0 ? binary(Op::Sub, counter, h.first)
                                : binary(Op::Sub, h.first, counter);
  for (const auto& c : h.companions) {
    b.value = binary(Op::Add, c.init, binary(Op::Mul, int_const(c.step), trip));
    L.env_[c.var] = b;
  }
  // Variables declared outside the loop and assigned in it (OpenMP
  // `private` temporaries) start each iteration without a value: a read
  // before the iteration's own assignment would be a value carried over
  // from the previous iteration.
  std::set<const VarDecl*> assigned = h.assigned; // (running indices leave it below)
  auto inductions = running_.begin(f, h, *loop, trip, assigned);
  // Scalar accumulators of this loop (`s += f(...)`, `s` read only after
  // the loop) and its min/max reductions: hidden work arrays (lower_reduce).
  const Reductions::LoopScope reductions =
      L.red_.begin_loop(f, var, assigned, L.in_loop_body_frame() && L.unrolling_ == 0);
  for (const VarDecl* v : assigned) {
    if (!forget_value(v))
      continue;
    if (auto why = L.red_.why_unset_inside(v)) {
      L.why_unset_[v] = *why;
      continue;
    }
    if (!L.in_loop_body_frame()) { // a void helper's own loop: a parallel-for (library_loops_)
      L.why_unset_[v] = fmt::format(
          "'{}' is assigned in the loop of helper '{}', which dpgen runs as a parallel loop "
          "(each iteration on its own, as a library's parallel-for): a value carried from one "
          "iteration to the next, a sum included, is outside the kernel subset there; write "
          "the loop in the kernel or in a lambda, and call the helper inside it",
          v->getNameAsString(), L.frames_.back().fn->getNameAsString());
      continue;
    }
    L.why_unset_[v] = fmt::format(
        "'{}' is declared outside the loop and assigned inside it, and read here before it is "
        "assigned in this iteration: a value carried from one iteration to the next (a "
        "recurrence, or a running sum read inside its loop) is outside the kernel subset; "
        "assign it before each use in the iteration, or only add to it (`s += ...`) or take "
        "its min/max (`m = std::max(m, ...)`) in the loop and read it after the loop{}",
        v->getNameAsString(),
        v->getType()->isIntegerType()
            ? fmt::format("; a running index is in the subset too: stepped (`k++`, `k += s`) by "
                          "the same amount in every iteration, outside any `if`, in a loop with "
                          "no `continue`, `break` or `return`, and read inside the innermost loop "
                          "that steps it{}",
                          v->getType()->isUnsignedIntegerType()
                              ? ", and, being unsigned, only stepping up (down it may wrap below "
                                "zero: make it signed)"
                              : "")
            : "");
  }
  // (after the accumulators' initial stores, which are outside the loop)
  for (const auto& [bound_at, upper] : triangle) // the triangle's side(s)
    L.path_.push_back({binary(upper ? Op::Lt : Op::Ge, counter, bound_at), true});
  if (parity_start) { // the strided loop's own iterations
    const bool up = parity_step > 0;
    L.path_.push_back({binary(up ? Op::Ge : Op::Le, counter, parity_start), true});
    L.path_.push_back(
        {binary(Op::Eq,
                binary(Op::Rem,
                       up ? binary(Op::Sub, counter, parity_start)
                          : binary(Op::Sub, parity_start, counter),
                       int_const(up ? parity_step : -parity_step)),
                int_const(0)),
         true});
  }
  L.loops_.push_back(loop);
  for (const auto& c : h.companions) // (now that the counter's range is a fact)
    if (c.is_unsigned)
      check_stays_nonneg(c, *L.env_[c.var].value, h.var);
  if (!L.in_loop_body_frame()) // a helper's loop (a parallel-for's), not one in its body
    L.library_loops_.insert(loop.get());
  L.loop_ids_.push_back(L.next_loop_id_++);
  L.segments_.push_back(--L.next_segment_);
  Escape e = L.lower_recovering(f->getBody());
  (void)e; // a body ending in continue is fine
  running_.end_body(f, inductions);
  L.library_loops_.erase(loop.get());
  L.loops_.pop_back();
  L.loop_ids_.pop_back();
  L.segments_.pop_back();
  L.path_.resize(depth);
  L.env_ = env_before;
  L.why_unset_ = why_before;
  // After the loop, an accumulator holds its sum; any other variable it
  // assigned holds what the last iteration left there: outside the subset.
  L.red_.end_loop(reductions, f);
  for (const VarDecl* v : assigned) {
    if (reductions.accumulates(v))
      continue;
    if (!forget_value(v))
      continue;
    L.why_unset_[v] = fmt::format("'{}' is read after the loop that assigns it: its value there "
                                  "is the last iteration's, outside the kernel subset",
                                  v->getNameAsString());
  }
  running_.end(inductions, *loop);
  counters_after(h, env_before);
}

// An unsigned companion (`for (unsigned i = 0, j = n - 1; i < n; ++i, --j)`
// wraps past zero only after the last iteration, where the body no longer
// sees it): `value`, its value in the body, must provably stay >= 0 there
// (dpgen's integers are signed: a wrapped value, `j = off - 2` with off = 0,
// would differ).
void ForLoops::check_stays_nonneg(const ForHeader::Companion& c, const ExprP& value,
                                  const VarDecl* counter) {
  if (L.provably_nonneg(value))
    return;
  L.fail(c.inc->getBeginLoc(),
         fmt::format("unsigned counter '{}' steps beside loop counter '{}', and dpgen "
                     "cannot prove from the loop's bounds that it stays >= 0 in the body (where "
                     "it would wrap around); use a signed counter",
                     c.var->getNameAsString(), counter->getNameAsString()),
         "dpgen-loop");
}

// After loop `h`: its counters declared in its header are gone; one declared
// before it (C89) is not a value (it would hold the value past the last).
void ForLoops::counters_after(const ForHeader& h, const std::map<const VarDecl*, Binding>& before) {
  std::vector<const VarDecl*> counters{h.var};
  for (const auto& c : h.companions)
    counters.push_back(c.var);
  for (const VarDecl* v : counters) {
    auto it = before.find(v);
    if (it == before.end()) {
      L.env_.erase(v);
      continue;
    }
    L.env_[v] = it->second;
    L.env_[v].value = std::nullopt;
    L.why_unset_[v] = fmt::format("loop counter '{}' is read after its loop; use the loop "
                                  "bound instead",
                                  v->getNameAsString());
  }
}

void ForLoops::assigned_vars(const Stmt* s, std::set<const VarDecl*>& out) {
  if (!s)
    return;
  auto target = [&](const clang::Expr* e) {
    e = e->IgnoreParenImpCasts();
    if (const auto* sub = dyn_cast<ArraySubscriptExpr>(e)) // an element of a local array
      e = sub->getBase()->IgnoreParenImpCasts();
    else if (const auto* u = dyn_cast<UnaryOperator>(e); u && u->getOpcode() == UO_Deref)
      e = u->getSubExpr()->IgnoreParenImpCasts(); // `*p`: a helper's out-pointer's local
    else if (const auto* oc = dyn_cast<CXXOperatorCallExpr>(e); // of a std::array: t[k]
             oc && oc->getOperator() == OO_Subscript && oc->getNumArgs() == 2)
      e = oc->getArg(0)->IgnoreParenImpCasts();
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

void ForLoops::check_not_assigned(const Stmt* s, const VarDecl* var) {
  if (!s)
    return;
  auto refers = [&](const clang::Expr* e) {
    const auto* r = dyn_cast<DeclRefExpr>(e->IgnoreParenImpCasts());
    return r && r->getDecl() == var;
  };
  if (const auto* b = dyn_cast<BinaryOperator>(s); b && b->isAssignmentOp() && refers(b->getLHS()))
    L.fail(b->getOperatorLoc(),
           fmt::format("loop counter '{}' is modified in the loop body", var->getNameAsString()),
           "dpgen-loop");
  if (const auto* u = dyn_cast<UnaryOperator>(s);
      u && u->isIncrementDecrementOp() && refers(u->getSubExpr()))
    L.fail(u->getOperatorLoc(),
           fmt::format("loop counter '{}' is modified in the loop body", var->getNameAsString()),
           "dpgen-loop");
  for (const Stmt* c : s->children())
    check_not_assigned(c, var);
}

} // namespace dpgen::lowering
