// Lowering, statements: blocks, branches, declarations of locals and local
// arrays and lambdas, assignments and stores (lower_impl.hpp).
#include "lower_impl.hpp"

namespace dpgen::lowering {

void Lowerer::body(const Stmt* s) {
  if (!s)
    fail(fn_->getLocation(), "kernel has no body");
  if (s->getBeginLoc().isMacroID()) {
    std::string macro =
        Lexer::getImmediateMacroName(s->getBeginLoc(), sm_, ctx_.getLangOpts()).str();
    fail(sm_.getExpansionLoc(s->getBeginLoc()),
         fmt::format("the body of kernel '{}' comes from macro '{}': write the loops out, so "
                     "diagnostics and the generated code can point at them",
                     k_.name, macro));
  }
  if (lower(s) == Escape::Always && !loops_.empty())
    fail(s->getBeginLoc(), "unreachable");
}

Escape Lowerer::lower(const Stmt* s) {
  if (const auto* c = dyn_cast<CompoundStmt>(s)) {
    for (const Stmt* child : c->body()) {
      if (lower_recovering(child) == Escape::Always) {
        if (child != c->body_back())
          fail(c->body_back()->getBeginLoc(), "statement after 'continue'/'return' is never "
                                              "executed");
        return Escape::Always;
      }
    }
    return Escape::None;
  }
  if (isa<NullStmt>(s))
    return Escape::None;
  // `#pragma omp parallel for` (parsed with -fopenmp): the loop it wraps.
  if (const auto* omp = dyn_cast<OMPExecutableDirective>(s)) {
    if (!omp->hasAssociatedStmt())
      fail(s->getBeginLoc(), "this OpenMP directive is outside the kernel subset");
    return lower(omp->getInnermostCapturedStmt()->getCapturedStmt());
  }
  if (const auto* d = dyn_cast<DeclStmt>(s)) {
    for (const Decl* decl : d->decls())
      declare(decl);
    return Escape::None;
  }
  if (const auto* f = dyn_cast<ForStmt>(s)) {
    for_loop(f);
    return Escape::None;
  }
  if (const auto* i = dyn_cast<IfStmt>(s))
    return if_stmt(i);
  if (isa<ContinueStmt>(s)) {
    if (unrolling_ > 0)
      fail(s->getBeginLoc(), "'continue' in a small constant loop that dpgen unrolls (it "
                             "reads or writes a local array, or sums into a variable); use "
                             "an if/else");
    if (loops_.empty())
      fail(s->getBeginLoc(), "'continue' outside a loop");
    return Escape::Always;
  }
  if (const auto* r = dyn_cast<ReturnStmt>(s)) {
    if (!frames_.empty() && loops_.size() == frames_.back().loop_depth) {
      // `return v;` in a helper being inlined: v where this path holds.
      if (frames_.back().is_void) {
        // (an early return would have to undo the out-parameters' later
        // assignments on its path)
        if (path_.size() > frames_.back().path_depth)
          fail(s->getBeginLoc(), fmt::format("'return' inside a branch of void helper '{}': "
                                             "assign the out-parameters in if/else instead",
                                             frames_.back().fn->getNameAsString()));
        return Escape::Always;
      }
      if (!r->getRetValue())
        fail(s->getBeginLoc(), "a helper called from a kernel must return a value");
      // The value first: it may inline further helpers, which grows frames_.
      ExprP v = expr(r->getRetValue());
      InlineFrame& fr = frames_.back();
      v = cast(v, fr.ret);
      fr.returns.push_back(
          {std::vector<PathCond>(path_.begin() + long(fr.path_depth), path_.end()), v});
      return Escape::Always;
    }
    if (!loops_.empty() || unrolling_ > 0)
      fail(s->getBeginLoc(), "'return' inside a loop is outside the kernel subset; use "
                             "'continue' or an if/else");
    if (const clang::Expr* v = r->getRetValue()) {
      // `return s;` of a kernel returning a value: a store to its output
      // `<kernel>_return` (Param::returned), as the kernel's last statement.
      const Param* ret = nullptr;
      for (const auto& p : k_.params)
        if (p.returned)
          ret = &p;
      if (!ret)
        fail(s->getBeginLoc(), "a kernel returns nothing");
      if (!path_.empty())
        fail(s->getBeginLoc(), "a kernel that returns a value returns it once, as its last "
                               "statement, not inside a branch (compute it in a local first)");
      add_store(ret->name, int_const(0), cast(expr(v), ret->elem), false,
                pos(s->getBeginLoc()), s->getBeginLoc());
    }
    return Escape::Always;
  }
  if (const auto* e = dyn_cast<clang::Expr>(s)) {
    expr_stmt(e);
    return Escape::None;
  }
  if (isa<WhileStmt>(s) || isa<DoStmt>(s))
    fail(s->getBeginLoc(), "while/do loops are outside the kernel subset: write a for loop "
                           "with an integer counter and bounds that depend on parameters only");
  if (isa<GotoStmt>(s) || isa<IndirectGotoStmt>(s) || isa<LabelStmt>(s))
    fail(s->getBeginLoc(), "'goto' is outside the kernel subset");
  if (isa<BreakStmt>(s))
    fail(s->getBeginLoc(), "'break' is outside the kernel subset: loop bounds must fix the "
                           "iteration space");
  if (isa<SwitchStmt>(s))
    fail(s->getBeginLoc(), "'switch' is outside the kernel subset; use if/else on indices");
  if (isa<CXXForRangeStmt>(s))
    fail(s->getBeginLoc(), "range-based for is outside the kernel subset; use an integer "
                           "counter");
  fail(s->getBeginLoc(), fmt::format("statement '{}' is outside the kernel subset",
                                     s->getStmtClassName()));
}

// `if (c) A else B`; a branch ending in continue/return puts the negated
// condition on the path of everything that follows.
Escape Lowerer::if_stmt(const IfStmt* s) {
  if (s->getInit() || s->getConditionVariable())
    fail(s->getBeginLoc(), "if with an initializer or a declaration is outside the subset");
  if (s->isConstexpr()) { // `if constexpr`: only the branch the compiler keeps
    bool taken = false;
    if (!s->getCond()->EvaluateAsBooleanCondition(taken, ctx_))
      fail(s->getBeginLoc(), "dpgen cannot evaluate the condition of this 'if constexpr'");
    const Stmt* branch = taken ? s->getThen() : s->getElse();
    return branch ? lower_recovering(branch) : Escape::None;
  }
  // `if (e > m) m = e;` of a max reduction (min: `if (e < m) m = e;`): an update.
  if (red_.if_update(s))
    return Escape::None;
  ExprP c = cond(s->getCond());
  size_t depth = path_.size();
  auto env_before = env_;
  int first_local = next_local_id_;

  path_.push_back({c, true});
  Escape then_e = lower_recovering(s->getThen());
  path_.resize(depth);
  auto env_then = env_;
  int after_then = next_local_id_;

  env_ = env_before;
  Escape else_e = Escape::None;
  if (s->getElse()) {
    path_.push_back({c, false});
    else_e = lower_recovering(s->getElse());
    path_.resize(depth);
  }
  auto env_else = env_;
  int after_else = next_local_id_;

  // Merge values assigned in the branches: v = c ? v_then : v_else. A
  // branch that escaped contributes nothing to what follows.
  auto merge = [&](const VarDecl* decl, std::optional<ExprP> t,
                   std::optional<ExprP> e) -> std::optional<ExprP> {
    if (then_e == Escape::Always)
      t = e;
    if (else_e == Escape::Always)
      e = t;
    if (t == e)
      return t;
    if (!t || !e)
      return std::nullopt; // assigned in one branch only: uninitialised after
    // Values made inside a branch are inlined into the select, so nothing
    // of a branch is evaluated where the branch does not run.
    ExprP then_value = inline_locals(*t, first_local, after_then);
    ExprP else_value = inline_locals(*e, after_then, after_else);
    return make_local(decl->getNameAsString(), decl, select(c, then_value, else_value));
  };
  for (auto& [decl, b] : env_) {
    if (b.kind == Binding::Value) {
      b.value = merge(decl, env_then[decl].value, env_else[decl].value);
    } else if (b.kind == Binding::LocalArray) {
      const auto& te = env_then[decl].elems;
      const auto& ee = env_else[decl].elems;
      for (size_t i = 0; i < b.elems.size() && i < te.size() && i < ee.size(); ++i)
        b.elems[i] = merge(decl, te[i], ee[i]);
    }
  }
  if (then_e == Escape::Always && else_e == Escape::Always)
    return Escape::Always;
  if (then_e == Escape::Always)
    path_.push_back({c, false});
  if (else_e == Escape::Always)
    path_.push_back({c, true});
  // `if (n < 3) return;` in the kernel itself, outside every loop and
  // helper: a guard of the whole kernel (it is also on every later path).
  if ((then_e == Escape::Always || else_e == Escape::Always) && loops_.empty() &&
      frames_.empty())
    k_.guards.push_back(path_.back());
  return Escape::None;
}

ExprP Lowerer::inline_locals(const ExprP& e, int from, int to) {
  if (!e)
    throw std::logic_error("internal error: lower: a null expression to inline");
  if (e->op == Op::Local) {
    if (e->local->id >= from && e->local->id < to)
      return inline_locals(e->local->def, from, to);
    return e;
  }
  return map_operands(e, [&](const ExprP& o) { return inline_locals(o, from, to); });
}

ExprP Lowerer::make_local(const std::string& base, const VarDecl* decl, ExprP def) {
  auto l = std::make_shared<LocalVar>();
  std::string name = base;
  for (int n = 1; local_names_.count(name) || loop_names_.count(name) || is_reserved(name); ++n)
    name = fmt::format("{}_{}", unprefixed(base), n);
  local_names_.insert(name);
  l->name = name;
  l->def = def;
  l->id = next_local_id_++;
  // (a value computed from an accumulator's sum, `double norm = sqrt(s);`,
  // is needed only where that sum is: not a kernel-level local)
  l->kernel_level = loops_.empty() && !any_node(def, [&](const ExprP& x) {
    return x->op == Op::Read && is_hidden(x->name);
  });
  if (def->type == Type::Int) {
    // Integers become std::ptrdiff_t in the generated code (see emit.cpp:
    // index arithmetic that vectorizes and never wraps, also for unsigned
    // locals such as `size_t k = n - 1 - i;` that later go negative in the
    // adjoint's index algebra); wider types keep their own.
    QualType t = decl ? decl->getType().getNonReferenceType().getUnqualifiedType() : ctx_.IntTy;
    bool widen = !t->isIntegerType() || ctx_.getTypeSize(t) <= 64;
    l->type_name = widen ? "std::ptrdiff_t" : spelled(t);
  }
  else
    l->type_name = type_spelling(def->type);
  if (l->kernel_level)
    k_.kernel_locals.push_back(l);
  return local_ref(l);
}

void Lowerer::declare(const Decl* d) {
  // Declarations that make no value: type aliases (`using Tag = ...;`),
  // static_assert, using-declarations and -directives.
  if (isa<TypedefNameDecl>(d) || isa<StaticAssertDecl>(d) || isa<UsingDecl>(d) ||
      isa<UsingDirectiveDecl>(d))
    return;
  const auto* v = dyn_cast<VarDecl>(d);
  if (!v)
    fail(d->getLocation(), "only variable declarations are allowed in a kernel");
  if (v->isStaticLocal() || v->hasGlobalStorage())
    fail(v->getLocation(), fmt::format("static variable '{}' is global state, outside the "
                                       "kernel subset",
                                       v->getNameAsString()));
  if (const auto* at = ctx_.getAsConstantArrayType(v->getType())) {
    if (at->getSize().getZExtValue() > 64) { // a line buffer (lower_buffer.cpp)
      bufs_.declare_buffer(v, at->getElementType(),
                     int_const(static_cast<long long>(at->getSize().getZExtValue())));
      return;
    }
    declare_array(v, at);
    return;
  }
  if (const auto* vat = ctx_.getAsVariableArrayType(v->getType())) { // `double tmp[nx]`
    bufs_.declare_buffer(v, vat->getElementType(), expr(vat->getSizeExpr()));
    return;
  }
  if (bufs_.declare_array_pointer(v)) // `double (*u)[n][n] = (double (*)[n][n]) u_flat;`
    return;
  if (const auto* rd = v->getType().getNonReferenceType()->getAsCXXRecordDecl();
      rd && rd->isLambda()) {
    inl_.declare_lambda(v, rd);
    return;
  }
  if (objects_.declare_object(v)) // const auto lo = amrex::lbound(bx);
    return;
  if (const auto* rd = v->getType().getNonReferenceType()->getAsCXXRecordDecl();
      rd && objects_.is_functor_class(rd) && v->getInit()) { // const GradientFluxes f{phi, fx, ...};
    env_[v] = objects_.functor_binding(v->getInit(), rd);
    return;
  }
  if (auto sa = std_array(v->getType()); sa && sa->second > 64) { // a line buffer
    bufs_.declare_buffer(v, sa->first, int_const(static_cast<long long>(sa->second)));
    return;
  }
  if (auto sa = std_array(v->getType())) { // a coefficient table, a small buffer
    declare_array(v, ctx_.getAsConstantArrayType(
                         ctx_.getConstantArrayType(sa->first, llvm::APInt(64, sa->second),
                                                   nullptr, ArraySizeModifier::Normal, 0)));
    return;
  }
  auto t = scalar_type(v->getType());
  if (!t || v->getType()->isReferenceType())
    fail(v->getLocation(), fmt::format("local '{}' of type '{}' is outside the kernel subset "
                                       "(int, float, double or bool values, and small arrays "
                                       "of them)",
                                       v->getNameAsString(), v->getType().getAsString()));
  Binding b;
  b.kind = Binding::Value;
  b.kernel_level = loops_.empty();
  if (const clang::Expr* init = v->getInit()) {
    ExprP e = expr(init);
    b.value = make_local(v->getNameAsString(), v, cast(e, *t));
  }
  env_[v] = b;
}

// A small local array (`double w[3] = {...}`, a line buffer `double v[5]`):
// each element is a local value, indexed by constants (counters of small
// constant loops count as constants: those loops are unrolled).
void Lowerer::declare_array(const VarDecl* v, const ConstantArrayType* at) {
  auto t = scalar_type(at->getElementType());
  uint64_t n = at->getSize().getZExtValue();
  if (!t || ctx_.getAsArrayType(at->getElementType()))
    fail(v->getLocation(), fmt::format("local array '{}' of type '{}' is outside the kernel "
                                       "subset (one-dimensional arrays of int, float or "
                                       "double)",
                                       v->getNameAsString(), v->getType().getAsString()));
  if (n > 64)
    fail(v->getLocation(), fmt::format("local array '{}' has {} elements; dpgen keeps local "
                                       "arrays of up to 64 elements in registers",
                                       v->getNameAsString(), n));
  Binding b;
  b.kind = Binding::LocalArray;
  b.elem = *t;
  b.elems.assign(n, std::nullopt);
  const clang::Expr* init = v->getInit();
  if (const auto* ctor = dyn_cast_or_null<CXXConstructExpr>(init);
      ctor && ctor->getNumArgs() == 0 && !ctor->requiresZeroInitialization())
    init = nullptr; // `std::array<double, 3> d;`: no values yet
  if (init) {
    const auto* list = dyn_cast<InitListExpr>(init->IgnoreImplicit());
    // std::array<T, N> a = {...}: the list of its one member, the C array
    bool all_zero = false; // `std::array<double, 3> d{};`
    if (list && std_array(v->getType()) && list->getNumInits() == 1) {
      if (const auto* inner = dyn_cast<InitListExpr>(list->getInit(0)->IgnoreImplicit()))
        list = inner;
      else if (isa<ImplicitValueInitExpr>(list->getInit(0)))
        all_zero = true;
    }
    if (!list)
      fail(init->getBeginLoc(), "a local array is initialised with a braced list");
    for (unsigned i = 0; !all_zero && i < list->getNumInits() && i < n; ++i)
      b.elems[i] = isa<ImplicitValueInitExpr>(list->getInit(i))
                       ? cast(int_const(0), *t)
                       : make_local(fmt::format("{}_{}", v->getNameAsString(), i), nullptr,
                                    cast(expr(list->getInit(i)), *t));
    // Elements the list leaves out are zero, as in C.
    for (uint64_t i = all_zero ? 0 : list->getNumInits(); i < n; ++i)
      b.elems[i] = cast(int_const(0), *t);
  }
  env_[v] = b;
}

// The element of a local array that `idx` names: it must be a constant.
size_t Lowerer::local_index(const clang::Expr* idx_expr, const VarDecl* v, size_t n) {
  ExprP idx = expr(idx_expr);
  auto p = to_poly(idx);
  // (an affine constant, or one C's integer operators give: `m % 2`, `m >> 1`
  // of an unrolled counter)
  std::optional<long long> value =
      p && p->is_constant() ? std::optional<long long>(p->constant_term()) : int_value(idx);
  if (!value)
    fail(idx_expr->getBeginLoc(),
         fmt::format("index of local array '{}' must be a constant (or the counter of a small "
                     "loop with constant bounds, which dpgen unrolls)",
                     v->getNameAsString()));
  long long k = *value;
  if (k < 0 || k >= static_cast<long long>(n))
    fail(idx_expr->getBeginLoc(), fmt::format("index {} is outside local array '{}' of {} "
                                              "elements",
                                              k, v->getNameAsString(), n));
  return static_cast<size_t>(k);
}

// `a[k]` of a local array: its binding and element, if that is what `e` is.
std::optional<std::pair<const VarDecl*, size_t>> Lowerer::local_element(const clang::Expr* e) {
  if (const auto* oc = dyn_cast<CXXOperatorCallExpr>(e->IgnoreParens());
      oc && oc->getOperator() == OO_Subscript && oc->getNumArgs() == 2) {
    // t[m] of a std::array local
    const auto* ref = dyn_cast<DeclRefExpr>(oc->getArg(0)->IgnoreParenImpCasts());
    const auto* v = ref ? dyn_cast<VarDecl>(ref->getDecl()) : nullptr;
    auto it = v ? env_.find(v) : env_.end();
    if (it == env_.end() || it->second.kind != Binding::LocalArray)
      return std::nullopt;
    return std::pair{v, local_index(oc->getArg(1), v, it->second.elems.size())};
  }
  const auto* sub = dyn_cast<ArraySubscriptExpr>(e->IgnoreParens());
  if (!sub)
    return std::nullopt;
  const auto* ref = dyn_cast<DeclRefExpr>(sub->getBase()->IgnoreParenImpCasts());
  const auto* v = ref ? dyn_cast<VarDecl>(ref->getDecl()) : nullptr;
  auto it = v ? env_.find(v) : env_.end();
  if (it == env_.end() || it->second.kind != Binding::LocalArray)
    return std::nullopt;
  return std::pair{v, local_index(sub->getIdx(), v, it->second.elems.size())};
}

// An expression statement: an assignment to an output element or a local.
void Lowerer::expr_stmt(const clang::Expr* e) {
  e = e->IgnoreParens();
  if (const auto* w = dyn_cast<ExprWithCleanups>(e)) // temporaries: std::max(a, 0.0)
    e = w->getSubExpr()->IgnoreParens();
  if (const auto* u = dyn_cast<UnaryOperator>(e); u && u->isIncrementDecrementOp()) {
    assign(u->getSubExpr(), u->isIncrementOp() ? BO_AddAssign : BO_SubAssign, nullptr,
           u->getOperatorLoc());
    return;
  }
  // `(void)x;` (silences an unused-variable warning): nothing to do.
  if (const auto* c = dyn_cast<ExplicitCastExpr>(e);
      c && c->getType()->isVoidType() && isa<DeclRefExpr>(c->getSubExpr()->IgnoreParenImpCasts()))
    return;
  const auto* b = dyn_cast<BinaryOperator>(e);
  if (!b || !b->isAssignmentOp()) {
    if (const auto* c = dyn_cast<CallExpr>(e); c && c->getType()->isVoidType()) {
      (void)expr(e); // a void helper: its out-parameters and stores (or the unknown call)
      return;
    }
    if (isa<CallExpr>(e))
      (void)expr(e); // reports the unknown call
    fail(e->getExprLoc(), "expression statement has no effect on an output; only "
                          "assignments are in the kernel subset");
  }
  assign(b->getLHS(), b->getOpcode(), b->getRHS(), b->getOperatorLoc());
}

// `*p` of a helper's pointer parameter bound to a caller's local (`&f`).
const VarDecl* Lowerer::deref_local(const clang::Expr* e) {
  const auto* u = dyn_cast<UnaryOperator>(e->IgnoreParenImpCasts());
  if (!u || u->getOpcode() != UO_Deref)
    return nullptr;
  const auto* r = dyn_cast<DeclRefExpr>(u->getSubExpr()->IgnoreParenImpCasts());
  const auto* v = r ? dyn_cast<VarDecl>(r->getDecl()) : nullptr;
  auto it = v ? env_.find(v) : env_.end();
  return it != env_.end() && it->second.kind == Binding::Value && it->second.deref_only ? v
                                                                                         : nullptr;
}

void Lowerer::assign(const clang::Expr* lhs, BinaryOperatorKind op, const clang::Expr* rhs, SourceLocation loc) {
  lhs = lhs->IgnoreParenImpCasts();
  if (const VarDecl* v = deref_local(lhs)) {
    assign_value(v, *scalar_type(v->getType()->getPointeeType()), lhs, op, rhs, loc);
    return;
  }
  if (auto le = local_element(lhs)) {
    Binding& b = env_[le->first];
    std::optional<ExprP>& slot = b.elems[le->second];
    std::string name = fmt::format("{}_{}", le->first->getNameAsString(), le->second);
    if (op == BO_Assign) {
      slot = make_local(name, nullptr, cast(expr(rhs), b.elem));
      return;
    }
    if (!slot)
      fail(lhs->getBeginLoc(), unset_message(le->first, "used before it has a value"));
    ExprP r = rhs ? expr(rhs) : int_const(1);
    Op bop = op == BO_AddAssign ? Op::Add : op == BO_SubAssign ? Op::Sub
             : op == BO_MulAssign ? Op::Mul : op == BO_DivAssign ? Op::Div : Op::Rem;
    if (bop == Op::Rem)
      fail(loc, "this compound assignment is outside the kernel subset");
    slot = make_local(name, nullptr, cast(binary(bop, *slot, r), b.elem));
    return;
  }
  if (red_.element_update(lhs, op, rhs, loc)) // *err = fmax(*err, e)
    return;
  if (auto acc = element(lhs)) {
    const Param* p = acc->param;
    if (!acc->dims.empty())
      fail(lhs->getBeginLoc(), fmt::format("view '{}' is written at a choice of positions (a "
                                           "periodic wrap): write each element at an affine "
                                           "index, with the wrap as a branch around the store",
                                           p->name));
    if (p->inout) {
      // u[k] = v / u[k] += v on an in-place array: a store of the new value
      // into its twin; `+=` adds to the value u[k] has here (the old one, or
      // what this iteration stored).
      const Param* twin = k_.find_param(p->name + "_new");
      ExprP value = expr(rhs ? rhs : lhs);
      if (op != BO_Assign) {
        if (op != BO_AddAssign && op != BO_SubAssign && op != BO_MulAssign)
          fail(loc, "this compound assignment is outside the kernel subset");
        ExprP old = inout_value(p, acc->index, lhs->getBeginLoc(), lhs);
        ExprP r = rhs ? expr(rhs) : int_const(1);
        value = binary(op == BO_AddAssign ? Op::Add : op == BO_SubAssign ? Op::Sub : Op::Mul, old, r);
      }
      add_store(twin->name, acc->index, cast(value, p->elem), false, pos(lhs->getBeginLoc()),
                lhs->getBeginLoc());
      acc_.inout_stores.push_back({p->name, cur_key(), next_store_seq_ - 1, acc->index});
      return;
    }
    if (!frames_.empty() && !frames_.back().is_void)
      fail(lhs->getBeginLoc(), fmt::format("helper '{}' writes to array '{}': helpers return "
                                           "values; store them in the kernel",
                                           frames_.back().fn->getNameAsString(), p->name));
    if (p->global)
      fail(lhs->getBeginLoc(), fmt::format("write to '{}': global state is outside the kernel "
                                           "subset (a kernel reads globals; its results go to "
                                           "DPGEN_OUT parameters)",
                                           p->name));
    if (p->kind != ParamKind::Out)
      fail(lhs->getBeginLoc(),
           fmt::format("'{}' is written but is not a DPGEN_OUT parameter; inputs and constant "
                       "arrays are read only{}",
                       p->name,
                       p->kind == ParamKind::In
                           ? " (an array updated in place, as in Gauss-Seidel or an in-place "
                             "time step, carries values from one iteration to the next: "
                             "write the new values to a separate DPGEN_OUT array)"
                           : ""));
    ExprP value;
    bool accumulate = false;
    if (op == BO_Assign) {
      value = expr(rhs);
    } else if (op == BO_AddAssign || op == BO_SubAssign) {
      ExprP r = rhs ? expr(rhs) : int_const(1);
      value = op == BO_AddAssign ? r : unary(Op::Neg, r);
      accumulate = true;
    } else {
      fail(loc, fmt::format("compound assignment '{}' to output '{}' needs the element's "
                            "previous value, which the adjoint does not have; only '=', '+=' "
                            "and '-=' write outputs",
                            BinaryOperator::getOpcodeStr(op).str(), p->name));
    }
    if (bufs_.is_buffer(p->name)) // a line buffer: in bounds, no value carried (lower_buffer.cpp)
      bufs_.check_buffer_store(p, acc->index, accumulate, lhs);
    add_store(p->name, acc->index, cast(value, p->elem), accumulate, pos(lhs->getBeginLoc()),
              lhs->getBeginLoc());
    return;
  }
  const auto* ref = dyn_cast<DeclRefExpr>(lhs);
  const auto* var = ref ? dyn_cast<VarDecl>(ref->getDecl()) : nullptr;
  if (!var)
    fail(lhs->getBeginLoc(), "assignment target is outside the kernel subset (write to an "
                             "output element or a local variable)");
  auto it = env_.find(var);
  if (it == env_.end() || (it->second.param && it->second.param->global)) {
    if (var->hasGlobalStorage())
      fail(lhs->getBeginLoc(), fmt::format("write to '{}': global state is outside the kernel "
                                           "subset",
                                           var->getNameAsString()));
    fail(lhs->getBeginLoc(), fmt::format("'{}' is outside the kernel subset",
                                         var->getNameAsString()));
  }
  if (it->second.kind != Binding::Value)
    fail(lhs->getBeginLoc(), fmt::format("parameter '{}' is assigned; kernel parameters are "
                                         "read only",
                                         var->getNameAsString()));
  auto t = scalar_type(var->getType().getNonReferenceType());
  if (!t)
    fail(lhs->getBeginLoc(), fmt::format("'{}' has a type outside the kernel subset",
                                         var->getNameAsString()));
  assign_value(var, *t, lhs, op, rhs, loc);
}

// var = rhs, var += rhs, ... for a scalar local (or what a helper's `*p`
// stands for).
void Lowerer::assign_value(const VarDecl* var, Type t, const clang::Expr* lhs, BinaryOperatorKind op, const clang::Expr* rhs, SourceLocation loc) {
  if (red_.local_update(var, t, lhs, op, rhs, loc)) // s += e, m = std::max(m, e)
    return;
  Binding& b = env_[var];
  ExprP value;
  if (op == BO_Assign) {
    value = expr(rhs);
  } else {
    if (!b.value)
      fail(lhs->getBeginLoc(), unset_message(var, "used before it has a value"));
    ExprP r = rhs ? expr(rhs) : int_const(1);
    Op bop;
    switch (op) {
    case BO_AddAssign:
      bop = Op::Add;
      break;
    case BO_SubAssign:
      bop = Op::Sub;
      break;
    case BO_MulAssign:
      bop = Op::Mul;
      break;
    case BO_DivAssign:
      bop = Op::Div;
      break;
    default:
      fail(loc, "this compound assignment is outside the kernel subset");
    }
    value = binary(bop, *b.value, r);
    if (bop == Op::Sub && var->getType().getNonReferenceType()->isUnsignedIntegerType())
      ints_.check_unsigned_result(value, loc,
                            fmt::format("unsigned '{}' after '-='", var->getNameAsString()),
                            lhs);
  }
  b.value = make_local(var->getNameAsString(), var, cast(value, t));
}

Nest& Lowerer::current_nest() {
  auto it = nest_index_.find(cur_key());
  if (it == nest_index_.end()) {
    Nest n;
    n.key = cur_key();
    for (const auto& l : loops_)
      n.loops.push_back(*l);
    k_.nests.push_back(n);
    it = nest_index_.emplace(cur_key(), k_.nests.size() - 1).first;
  }
  return k_.nests[it->second];
}

// `prefix` holds wherever `path` holds: its conditions open `path`.
bool Lowerer::is_prefix(const std::vector<PathCond>& prefix, const std::vector<PathCond>& path) {
  if (prefix.size() > path.size())
    return false;
  for (size_t i = 0; i < prefix.size(); ++i)
    if (prefix[i].cond != path[i].cond || prefix[i].positive != path[i].positive)
      return false;
  return true;
}

void Lowerer::add_store(const std::string& array, ExprP idx, ExprP value, bool accumulate, SourcePos p, SourceLocation loc, int extremum) {
  // `(j << lg) | i` as the sum it equals, `j * n + i`, where the loops keep
  // i below n = 1 << lg (prove.hpp: bits_as_sum)
  if (!to_poly(idx)) {
    std::vector<Loop> around;
    for (const auto& l : loops_)
      around.push_back(*l);
    idx = bits_as_sum(idx, around, path_, k_.kernel_locals);
  }
  // A sum into one element from the iterations of a library parallel-for
  // (`ParallelFor(bx, [&](...) { sum += ...; })`) is a data race under its
  // parallel semantics: refused, though a serial reading would be a sum.
  if (accumulate && !library_loops_.empty()) {
    auto pi = to_poly(idx);
    for (const auto& l : loops_)
      if (library_loops_.count(l.get()) && (!pi || !pi->mentions_counter(l->var)))
        fail(loc, fmt::format("'+=' into '{}' in the body of a parallel-for ('{}'), at an "
                              "element its iterations over '{}' share: a data race under the "
                              "library's parallel semantics; write the sum as a loop nest of the "
                              "kernel (a parallel_reduce is outside the kernel subset)",
                              array, frames_.empty() ? "?" : frames_.front().fn->getNameAsString(),
                              l->var),
             "dpgen-loop");
  }
  // Updating an element this nest stored, after a later nest stored the
  // array too: the update goes after that nest.
  if (auto it = nest_index_.find(cur_key()); it != nest_index_.end())
    if (visible_store(k_.nests[it->second], array, idx))
      order_after_later_stores(array);
  Nest& nest = current_nest();
  // A second store to the same element in one iteration updates the first:
  // `x[k] = a; ... x[k] += b;` stores a + b, and a store under a further
  // condition keeps the earlier value where that condition fails.
  if (Store* prev = visible_store(nest, array, idx)) {
    // (two min/max updates in one iteration: the scan takes the extremum of
    // both, still a constant to derivatives)
    ExprP updated = extremum ? call("dpgen_nograd",
                                    {call(extremum > 0 ? "max" : "min", {prev->value, value},
                                          value->type)},
                                    value->type)
                    : accumulate ? binary(Op::Add, prev->value, value)
                                 : value;
    ExprP cond;
    for (size_t i = prev->path.size(); i < path_.size(); ++i) {
      ExprP c = path_[i].positive ? path_[i].cond : unary(Op::Not, path_[i].cond);
      cond = cond ? binary(Op::And, cond, c) : c;
    }
    prev->value = cond ? select(cond, updated, prev->value) : updated;
    prev->pos = p;
    return;
  }
  // Otherwise a store whose path is not provably disjoint from another
  // store's to an element that may be the same would overwrite it.
  for (auto& s : nest.stores) {
    if (s.array != array || paths_disjoint(s.path, path_) || (s.accumulate && accumulate))
      continue;
    auto pa = to_poly(s.index), pb = to_poly(idx);
    Facts facts;
    for (const auto& l : loops_)
      add_nonempty(*l, facts);
    for (const auto& pc : path_)
      add_facts(pc, facts);
    if (pa && pb) {
      Poly g1 = *pa - *pb - Poly::constant(1), g2 = *pb - *pa - Poly::constant(1);
      if (prove_nonneg(g1, facts) || prove_nonneg(g2, facts))
        continue;
      // A view's (row pointers') layout symbols stand for no size the
      // generated code can compare: elements in different constant planes
      // (rows) are apart (the plane symbol exceeds any offset in a plane);
      // any other difference in them is not decided here.
      if (layout_apart(*pa - *pb))
        continue;
      if (!(*pa - *pb).mentions_any_counter() && !accumulate && !s.accumulate &&
          is_prefix(path_, s.path) && !mentions_layout(*pa - *pb)) {
        // Different elements for some sizes only (u[0] and u[n - 1]): where
        // they are the same, this store overwrites the earlier one, which
        // then contributes nothing. The earlier store gets that condition.
        s.path.push_back({binary(Op::Eq, s.index, idx), false});
        continue;
      }
    }
    fail(loc, fmt::format("output '{}' may be written twice in one iteration (first at "
                          "line {}); write each element once",
                          array, s.pos.line));
  }
  Store st{array, idx, value, path_, p};
  st.accumulate = accumulate;
  st.extremum = extremum;
  st.seq = next_store_seq_++;
  nest.stores.push_back(st);
}

// The value u[k] of an in-place array has here: what this iteration stored
// at k, or the value before the call (a read of the input).
ExprP Lowerer::inout_value(const Param* p, const ExprP& idx, SourceLocation loc, const clang::Expr* e) {
  auto nit = nest_index_.find(cur_key());
  if (nit != nest_index_.end())
    if (Store* st = visible_store(k_.nests[nit->second], p->name + "_new", idx))
      return st->value;
  acc_.inout_reads.push_back({p->name, cur_key(), next_store_seq_, idx, {}, pos(loc)});
  ExprP r = read(p->name, idx, p->elem, pos(loc), shape_of(*p));
  std::const_pointer_cast<Expr>(r)->source = text(e);
  return r;
}

bool Lowerer::written_by_other_nest(const std::string& array) const {
  for (const auto& [key, idx] : nest_index_)
    if (key != cur_key())
      for (const auto& st : k_.nests[idx].stores)
        if (st.array == array)
          return true;
  return false;
}

} // namespace dpgen::lowering
