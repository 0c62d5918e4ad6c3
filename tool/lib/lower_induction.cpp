// Lowering, running indices: an integer local declared before a loop and
// stepped in its body (`b[idx] = ...; idx++;`, a flat index that C codes
// carry through a nest, `idx += 2` past the ghost cells of a row). Where every
// step is unconditional, its value at an iteration's start is a closed form,
// the value before the loop plus the iteration's number times the loop's step
// per iteration, so each iteration can run alone as the adjoint's gather and
// the parallel forward need (lower_loop.hpp: RunningIndices).
#include "lower_impl.hpp"
#include "lower_while.hpp"

namespace dpgen::lowering {

namespace {

// `s` steps `v` by itself: `v++`, `++v`, `v--`, `--v`, `v += e`, `v -= e`, `v = v + e`
// with `e` free of `v`. `up`: the step adds (++ or +=).
bool is_step(const Stmt* s, const VarDecl* v, bool& up) {
  if (const auto* e = dyn_cast<clang::Expr>(s)) // (`(k++);`, a macro's `((k) += 2)`)
    s = e->IgnoreParens();
  auto names_v = [&](const clang::Expr* e) {
    const auto* r = dyn_cast<DeclRefExpr>(e->IgnoreParenImpCasts());
    return r && r->getDecl() == v;
  };
  if (const auto* u = dyn_cast<UnaryOperator>(s); u && u->isIncrementDecrementOp()) {
    up = u->isIncrementOp();
    return names_v(u->getSubExpr());
  }
  if (const auto* c = dyn_cast<CompoundAssignOperator>(s);
      c && (c->getOpcode() == BO_AddAssign || c->getOpcode() == BO_SubAssign)) {
    up = c->getOpcode() == BO_AddAssign;
    return names_v(c->getLHS()) && !LoopHeaders::mentions(c->getRHS(), v);
  }
  const VarDecl* assigned = nullptr; // `v = v + e`, as C codes spell `v += e`
  bool adds = true;
  if (const auto* a = dyn_cast<BinaryOperator>(s))
    if (const clang::Expr* e = self_step(a, assigned, adds); e && assigned == v) {
      up = adds;
      return !LoopHeaders::mentions(e, v);
    }
  return false;
}

std::vector<const UnaryOperator*> inner_steps(const clang::Expr* e);

// `s` reads `v` and steps it by one inside an expression (`b[v++] = x`;
// RunningIndices::lower_inner_steps).
bool is_inner_step(const Stmt* s, const VarDecl* v, bool& up) {
  const auto* e = dyn_cast<clang::Expr>(s);
  if (!e)
    return false;
  for (const UnaryOperator* u : inner_steps(e))
    if (llvm::cast<DeclRefExpr>(u->getSubExpr()->IgnoreParenImpCasts())->getDecl() == v) {
      up = u->isIncrementOp();
      return true;
    }
  return false;
}

// The increments and decrements of integer variables inside expression
// statement `e` (`b[idx++] = x`, `out[k++] += y`), not `e` itself, each of a
// variable that `e` names nowhere else (so the step may run before or after
// the rest of the statement alike).
std::vector<const UnaryOperator*> inner_steps(const clang::Expr* e) {
  std::vector<const UnaryOperator*> steps;
  std::map<const Decl*, int> mentions;
  bool calls_lambda = false;
  // (`sure`: the step runs whenever the statement does; not in an arm of
  // `?:` nor right of `&&`, `||`; a lambda's body counts its mentions only)
  std::function<void(const Stmt*, bool)> walk = [&](const Stmt* s, bool sure) {
    if (!s || isa<UnaryExprOrTypeTraitExpr>(s)) // (sizeof: not evaluated)
      return;
    calls_lambda = calls_lambda || isa<LambdaExpr>(s);
    if (const auto* r = dyn_cast<DeclRefExpr>(s)) {
      ++mentions[r->getDecl()];
      const auto* rd = r->getType().getNonReferenceType()->getAsCXXRecordDecl();
      calls_lambda = calls_lambda || (rd && rd->isLambda()); // (it may read the variable)
    }
    if (const auto* u = dyn_cast<UnaryOperator>(s);
        sure && u && u != e && u->isIncrementDecrementOp())
      if (const auto* r = dyn_cast<DeclRefExpr>(u->getSubExpr()->IgnoreParenImpCasts());
          r && isa<VarDecl>(r->getDecl()) && r->getType()->isIntegerType())
        steps.push_back(u);
    const auto* b = dyn_cast<BinaryOperator>(s);
    const bool logical = b && (b->getOpcode() == BO_LAnd || b->getOpcode() == BO_LOr);
    const auto* c = dyn_cast<AbstractConditionalOperator>(s);
    for (const Stmt* child : s->children())
      walk(child, sure && !isa<LambdaExpr>(s) && !(logical && child == b->getRHS()) &&
                      !(c && child != c->getCond()));
  };
  walk(e, true);
  if (calls_lambda)
    return {};
  std::vector<const UnaryOperator*> out;
  for (const UnaryOperator* u : steps)
    if (mentions[llvm::cast<DeclRefExpr>(u->getSubExpr()->IgnoreParenImpCasts())->getDecl()] == 1)
      out.push_back(u);
  return out;
}

// A jump in `s` that may skip a statement after it in the loop body `s` is
// part of: a `continue` or `break` of that loop (not of a loop or switch
// inside it), a `return`, a `goto`. (A lambda's `return` is its own.)
bool may_skip(const Stmt* s, bool in_loop, bool in_switch) {
  if (!s || isa<LambdaExpr>(s))
    return false;
  if (isa<ReturnStmt>(s) || isa<GotoStmt>(s))
    return true;
  if (isa<ContinueStmt>(s))
    return !in_loop;
  if (isa<BreakStmt>(s))
    return !in_loop && !in_switch;
  const bool loop =
      in_loop || isa<ForStmt>(s) || isa<WhileStmt>(s) || isa<DoStmt>(s) || isa<CXXForRangeStmt>(s);
  const bool sw = in_switch || isa<SwitchStmt>(s);
  for (const Stmt* c : s->children())
    if (may_skip(c, loop, sw))
      return true;
  return false;
}

// The statements of a body, blocks opened.
void top_level(const Stmt* s, std::vector<const Stmt*>& out) {
  if (const auto* c = dyn_cast_or_null<CompoundStmt>(s)) {
    for (const Stmt* x : c->body())
      top_level(x, out);
  } else if (s) {
    out.push_back(s);
  }
}

} // namespace

// Whether loop body `body` steps `v` as a running index: every assignment of
// `v` is a step at the body's top level (blocks aside) or inside one `for`
// loop (or `while` loop that counts) of that level whose body does the same; no jump may skip a
// step; and where such an inner loop is there, `v` is read only inside it (where that loop runs, so
// its number of iterations, which the closed form counts, is the one it makes). `read`: `v` is read
// somewhere besides its steps. `up`: every step adds.
bool RunningIndices::steps_only(const Stmt* body, const VarDecl* v, bool& read, bool& up) {
  std::vector<const Stmt*> stmts;
  top_level(body, stmts);
  const Stmt* inner = nullptr; // (a for loop, or a while loop that counts)
  bool read_here = false;
  for (const Stmt* s : stmts) {
    bool adds = true;
    if (is_step(s, v, adds)) {
      up = up && adds;
      continue;
    }
    if (is_inner_step(s, v, adds)) {
      up = up && adds;
      read_here = true;
      continue;
    }
    std::set<const VarDecl*> as;
    L.for_loops_.assigned_vars(s, as);
    if (!as.count(v)) {
      read_here = read_here || LoopHeaders::mentions(s, v);
      continue;
    }
    if (inner)
      return false;
    if (const auto* g = dyn_cast<ForStmt>(s)) {
      for (const Stmt* part : {g->getInit(), static_cast<const Stmt*>(g->getCond()),
                               static_cast<const Stmt*>(g->getInc())})
        if (part && LoopHeaders::mentions(part, v))
          return false;
    } else if (const auto* w = dyn_cast<WhileStmt>(s)) {
      // A `while` that counts is the for loop it is (lower_while.hpp): its condition and its
      // counter's step, the body's last statement, are its header.
      const VarDecl* counter = while_counter(w);
      if (!counter || counter == v || LoopHeaders::mentions(w->getCond(), v))
        return false;
    } else {
      return false;
    }
    const Stmt* loop_body =
        isa<ForStmt>(s) ? llvm::cast<ForStmt>(s)->getBody() : llvm::cast<WhileStmt>(s)->getBody();
    if (!steps_only(loop_body, v, read, up))
      return false;
    inner = s;
  }
  read = read || read_here;
  return !(inner && read_here) && !may_skip(body, false, false);
}

// Before loop `f`'s body (its counter bound, `trip` the iteration's number
// from 0): each running index among `assigned` (which loses it) gets its
// closed form, `entry + trip * <v>_per_<counter>`, that local's definition
// (the step per iteration) known once the body is lowered (end_body).
std::vector<RunningIndices::Induction> RunningIndices::begin(const ForStmt* f, const ForHeader& h,
                                                             const Loop& loop, const ExprP& trip,
                                                             std::set<const VarDecl*>& assigned) {
  std::vector<const VarDecl*> candidates(assigned.begin(), assigned.end());
  std::sort(candidates.begin(), candidates.end(), [](const VarDecl* a, const VarDecl* b) {
    return a->getLocation().getRawEncoding() < b->getLocation().getRawEncoding();
  });
  std::vector<Induction> out;
  if (!h.triangle.empty() || h.parity_start) // (the body does not run in every iteration)
    return out;
  for (const VarDecl* v : candidates) {
    auto it = L.env_.find(v);
    if (it == L.env_.end() || it->second.kind != Binding::Value || !it->second.value ||
        (*it->second.value)->type != Type::Int || !v->getType()->isIntegerType())
      continue;
    bool read = false, up = true;
    if (!steps_only(f->getBody(), v, read, up) || !read)
      continue;
    Induction ind;
    ind.var = v;
    ind.entry = *it->second.value;
    ind.is_unsigned = v->getType()->isUnsignedIntegerType();
    if (ind.is_unsigned && !up)
      continue; // (an unsigned index stepping down may wrap: refused as before)
    auto per = std::make_shared<LocalVar>();
    per->name = fmt::format("{}_per_{}", L.unprefixed(v->getNameAsString()), loop.var);
    for (int n = 1; L.is_reserved(per->name) || L.local_names_.count(per->name); ++n)
      per->name = fmt::format("{}_per_{}_{}", L.unprefixed(v->getNameAsString()), loop.var, n);
    L.local_names_.insert(per->name);
    per->type_name = "std::ptrdiff_t";
    per->def = param(per->name, Type::Int); // (a symbol until the body is lowered)
    per->opaque = true;
    per->kernel_level = true;
    ind.per = per;
    ind.start = binary(Op::Add, ind.entry, binary(Op::Mul, trip, local_ref(per)));
    ind.enclosed = active_.count(v) > 0;
    it->second.value = ind.start;
    L.why_unset_.erase(v);
    active_.insert(v);
    assigned.erase(v);
    out.push_back(ind);
  }
  return out;
}

// The running indices' values at the end of loop `f`'s body:
// each step per iteration must be the same in every iteration (free of the
// counters: it becomes a kernel-level local).
void RunningIndices::end_body(const ForStmt* f, std::vector<Induction>& inductions) {
  for (Induction& ind : inductions) {
    std::optional<Poly> step;
    auto it = L.env_.find(ind.var);
    if (it != L.env_.end() && it->second.value)
      if (auto a = to_poly(*it->second.value), b = to_poly(ind.start); a && b)
        step = *a - *b;
    const std::string name = ind.var->getNameAsString();
    if (!step || step->mentions_any_counter() || step->mentions(Sym::size(ind.per->name)))
      L.fail(f->getBeginLoc(),
             fmt::format("'{}' is stepped in this loop by an amount that changes from one "
                         "iteration to the next (or is not an integer sum of sizes): a running "
                         "index must step by the same amount in every iteration; compute it "
                         "from the counters instead",
                         name),
             "dpgen-loop");
    ind.per->def = L.headers_.poly_expr(*step);
    ind.per->opaque = false;
    ind.per->id = L.next_local_id_++;
    L.k_.kernel_locals.push_back(ind.per);
    if (ind.is_unsigned && !L.provably_nonneg(ind.per->def))
      L.fail(f->getBeginLoc(),
             fmt::format("unsigned running index '{}' may step below zero in this loop, where it "
                         "would wrap around; use a signed index",
                         name),
             "dpgen-loop");
  }
}

// After loop `loop`: a running index holds its value before the loop plus
// the number of iterations times its step, where the loop runs a number of
// times dpgen proves non-negative (else `hi - lo` counts a loop that does not
// run as running backwards). Inside a loop that steps it too, that value
// feeds the enclosing loop's step, which the closed form uses only where this
// loop runs (the index is read in the innermost stepping loop alone); after
// the outermost loop it is a value only where every loop that stepped it
// provably ran so.
void RunningIndices::end(const std::vector<Induction>& inductions, const Loop& loop) {
  const ExprP trips = binary(Op::Sub, loop.hi, loop.lo);
  const bool counted = L.provably_nonneg(trips);
  for (const Induction& ind : inductions) {
    bool exact = counted && !unproved_.count(ind.var);
    if (ind.enclosed) {
      if (!counted)
        unproved_.insert(ind.var);
      exact = true;
    } else {
      active_.erase(ind.var);
      unproved_.erase(ind.var);
    }
    auto it = L.env_.find(ind.var);
    if (it == L.env_.end())
      continue;
    if (exact) {
      it->second.value = binary(Op::Add, ind.entry, binary(Op::Mul, trips, local_ref(ind.per)));
      L.why_unset_.erase(ind.var);
      continue;
    }
    it->second.value = std::nullopt;
    L.why_unset_[ind.var] =
        fmt::format("'{}' is read after the loops that step it, and dpgen cannot prove that "
                    "each of them runs (its upper bound at least its lower one) to count its "
                    "steps; compute it from the loops' bounds",
                    ind.var->getNameAsString());
  }
}

// Expression statement `e` with steps inside it (`b[idx++] = x`): each step
// a statement of its own, `++idx` before the rest, `idx++` after it, the
// expression reading the variable's value in between. False (nothing done)
// where `e` has no such step.
bool RunningIndices::lower_inner_steps(const clang::Expr* e) {
  std::vector<const UnaryOperator*> steps;
  for (const UnaryOperator* u : inner_steps(e))
    if (!inline_steps_.count(u))
      steps.push_back(u);
  if (steps.empty())
    return false;
  auto step = [&](const UnaryOperator* u) {
    L.stores_.assign(u->getSubExpr(), u->isIncrementOp() ? BO_AddAssign : BO_SubAssign, nullptr,
                     u->getOperatorLoc());
  };
  for (const UnaryOperator* u : steps) {
    if (u->isPrefix())
      step(u);
    inline_steps_.insert(u);
  }
  (void)L.stmts_.lower(e);
  for (const UnaryOperator* u : steps) {
    inline_steps_.erase(u);
    if (u->isPostfix())
      step(u);
  }
  return true;
}

} // namespace dpgen::lowering
