// Lowering, statements: blocks, branches, returns, declarations of locals
// and local arrays and lambdas (lower_stmt.hpp).
#include "lower_impl.hpp"
#include "lower_while.hpp"

namespace dpgen::lowering {

namespace {
const char* const kReturnInLoop =
    "'return' inside a loop is outside the kernel subset (it would leave every loop and the "
    "kernel); to skip the rest of an iteration, use an if/else (or 'continue' in a for loop)";
// A small local array indexed by a counter that is not unrolled.
std::string small_array_index(const std::string& name) {
  return fmt::format("index of local array '{}' must be a constant (or the counter of a small "
                     "loop with constant bounds, which dpgen unrolls): an array of up to 64 "
                     "elements is kept in registers; a work array that loops fill and read is a "
                     "line buffer, of more than 64 elements or a run-time length (`double "
                     "{}[n];`, `std::vector<double> {}(n);`)",
                     name, name, name);
}
} // namespace

void Statements::body(const Stmt* s) {
  if (!s)
    L.fail(L.fn_->getLocation(), "kernel has no body");
  if (s->getBeginLoc().isMacroID()) {
    std::string macro =
        Lexer::getImmediateMacroName(s->getBeginLoc(), L.sm_, L.ctx_.getLangOpts()).str();
    L.fail(L.sm_.getExpansionLoc(s->getBeginLoc()),
           fmt::format("the body of kernel '{}' comes from macro '{}': write the loops out, so "
                       "diagnostics and the generated code can point at them",
                       L.k_.name, macro));
  }
  if (lower(s) == Escape::Always && !L.loops_.empty())
    L.fail(s->getBeginLoc(), "unreachable");
}

// `what` (continue, return) met in a loop dpgen unrolls.
static std::string in_unrolled_loop(const char* what) {
  return fmt::format("'{}' in a small constant loop that dpgen unrolls (it reads or writes a "
                     "local array, or sums into a variable); use an if/else",
                     what);
}

Escape Statements::lower(const Stmt* s) {
  if (const auto* c = dyn_cast<CompoundStmt>(s))
    return sequence(std::vector<const Stmt*>(c->body_begin(), c->body_end()));
  if (isa<NullStmt>(s))
    return Escape::None;
  // `#pragma omp parallel for` (parsed with -fopenmp): the loop it wraps.
  if (const auto* omp = dyn_cast<OMPExecutableDirective>(s)) {
    if (!omp->hasAssociatedStmt())
      L.fail(s->getBeginLoc(), "this OpenMP directive is outside the kernel subset");
    return lower(omp->getInnermostCapturedStmt()->getCapturedStmt());
  }
  if (const auto* d = dyn_cast<DeclStmt>(s)) {
    for (const Decl* decl : d->decls())
      declare(decl);
    return Escape::None;
  }
  if (const auto* w = dyn_cast<WhileStmt>(s)) // one that counts: as the for loop it is
    s = while_as_for(L.ctx_, w, [&](auto at, auto& why) { L.fail(at, why, "dpgen-loop"); });
  if (const auto* f = dyn_cast<ForStmt>(s)) {
    L.for_loops_.for_loop(f);
    return Escape::None;
  }
  if (const auto* i = dyn_cast<IfStmt>(s))
    return if_stmt(i);
  if (isa<ContinueStmt>(s)) {
    if (L.unrolling_ > 0)
      L.fail(s->getBeginLoc(), in_unrolled_loop("continue"));
    if (L.loops_.empty())
      L.fail(s->getBeginLoc(), "'continue' outside a loop");
    return Escape::Always;
  }
  if (const auto* r = dyn_cast<ReturnStmt>(s)) {
    if (!L.frames_.empty() && L.loops_.size() == L.frames_.back().loop_depth) {
      // `return v;` in a helper being inlined: v where this path holds.
      // (An unrolled loop's copies would not see that it escaped.)
      if (L.unrolling_ > L.frames_.back().unrolling)
        L.fail(s->getBeginLoc(), in_unrolled_loop("return"));
      ExprP v;
      if (!L.frames_.back().is_void) {
        if (!r->getRetValue())
          L.fail(s->getBeginLoc(), "a helper called from a kernel must return a value");
        // The value first: it may inline further helpers, which grows frames_.
        v = L.exprs_.expr(r->getRetValue());
      }
      Lowerer::InlineFrame& fr = L.frames_.back();
      std::vector<PathCond> here(L.path_.begin() + long(fr.path_depth), L.path_.end());
      if (v)
        fr.returns.push_back({here, cast(v, fr.ret)});
      // A way out inside a branch: the bindings it leaves (Inliner::merge_exits).
      if (!here.empty())
        fr.exits.push_back({std::move(here), L.env_});
      return Escape::Always;
    }
    if (!L.loops_.empty() || L.unrolling_ > 0)
      L.fail(s->getBeginLoc(), kReturnInLoop);
    if (const clang::Expr* v = r->getRetValue()) {
      // `return s;` of a kernel returning a value: a store to its output
      // `<kernel>_return` (Param::returned), as the kernel's last statement.
      const Param* ret = nullptr;
      for (const auto& p : L.k_.params)
        if (p.returned)
          ret = &p;
      if (!ret)
        L.fail(s->getBeginLoc(), "a kernel returns nothing");
      if (!L.path_.empty())
        L.fail(s->getBeginLoc(), "a kernel that returns a value returns it once, as its last "
                                 "statement, not inside a branch (compute it in a local first)");
      L.stores_.add_store(ret->name, int_const(0), cast(L.exprs_.expr(v), ret->elem), false,
                          L.pos(s->getBeginLoc()), s->getBeginLoc());
    }
    return Escape::Always;
  }
  if (const auto* e = dyn_cast<clang::Expr>(s)) {
    expr_stmt(e);
    return Escape::None;
  }
  if (isa<DoStmt>(s))
    L.fail(s->getBeginLoc(), "do/while loops are outside the kernel subset: write a for loop "
                             "with an integer counter and bounds that depend on parameters only");
  if (isa<GotoStmt>(s) || isa<IndirectGotoStmt>(s) || isa<LabelStmt>(s))
    L.fail(s->getBeginLoc(), "'goto' is outside the kernel subset");
  if (isa<BreakStmt>(s))
    L.fail(s->getBeginLoc(), "'break' is outside the kernel subset: loop bounds must fix the "
                             "iteration space");
  if (const auto* sw = dyn_cast<SwitchStmt>(s))
    return switch_stmt(sw);
  if (const auto* rf = dyn_cast<CXXForRangeStmt>(s)) {
    L.for_loops_.range_for(rf);
    return Escape::None;
  }
  L.fail(s->getBeginLoc(),
         fmt::format("statement '{}' is outside the kernel subset", s->getStmtClassName()));
}

// (lower_stmt.hpp)
Escape Statements::if_stmt(const IfStmt* s) {
  if (s->getInit() || s->getConditionVariable())
    L.fail(s->getBeginLoc(), "if with an initializer or a declaration is outside the subset");
  if (s->isConstexpr()) { // `if constexpr`: only the branch the compiler keeps
    bool taken = false;
    if (!s->getCond()->EvaluateAsBooleanCondition(taken, L.ctx_))
      L.fail(s->getBeginLoc(), "dpgen cannot evaluate the condition of this 'if constexpr'");
    const Stmt* branch = taken ? s->getThen() : s->getElse();
    return branch ? L.lower_recovering(branch) : Escape::None;
  }
  // `if (e > m) m = e;` of a max reduction (min: `if (e < m) m = e;`): an update.
  if (L.red_.if_update(s))
    return Escape::None;
  ExprP c = L.exprs_.cond(s->getCond());
  return branch(
      c, [&] { return L.lower_recovering(s->getThen()); },
      [&] { return s->getElse() ? L.lower_recovering(s->getElse()) : Escape::None; });
}

// The statements of a block (or of a switch's case), in order.
Escape Statements::sequence(const std::vector<const Stmt*>& body) {
  for (const Stmt* child : body) {
    if (L.lower_recovering(child) == Escape::Always) {
      // (after an `if constexpr` that escapes: code of other instantiations)
      const auto* cx = dyn_cast<IfStmt>(child);
      if (child != body.back() && !(cx && cx->isConstexpr()))
        L.fail(body.back()->getBeginLoc(), "statement after 'continue'/'return' is never "
                                           "executed");
      return Escape::Always;
    }
  }
  return Escape::None;
}

namespace {

// A value made in an arm (locals with ids in [from, to)) with those locals'
// definitions in their place, to evaluate where the arm ran; a local the
// value names more than once is `shared(local)` instead (a copy guarded by
// the arm's conditions, Guards::guarded): inlined, a chain of locals each
// used twice grew as 3^depth.
ExprP inline_locals(const ExprP& e, int from, int to,
                    const std::function<ExprP(const ExprP&)>& shared) {
  if (!e)
    throw std::logic_error("internal error: lower: a null expression to inline");
  std::map<const LocalVar*, int> uses;
  std::set<const LocalVar*> seen;
  walk(
      e,
      [&](const ExprP& x) {
        if (x->op == Op::Local)
          ++uses[x->local.get()];
        return true;
      },
      [](const ExprP&) { return true; }, seen);
  std::function<ExprP(const ExprP&)> in = [&](const ExprP& x) -> ExprP {
    if (x->op == Op::Local) {
      // (not a kernel-level local, defined before every loop, nor a view's row
      // symbol, whose definition is a placeholder)
      const LocalVar& l = *x->local;
      if (l.id < from || l.id >= to || l.kernel_level || l.opaque)
        return x;
      return uses[&l] > 1 ? shared(x) : in(l.def);
    }
    return map_operands(x, in);
  };
  return in(e);
}

} // namespace

// `if (c) then_arm() else else_arm()`: each arm lowered on its side of the
// path, the values either assigns merged into selects after it.
Escape Statements::branch(const ExprP& c, const std::function<Escape()>& then_arm,
                          const std::function<Escape()>& else_arm) {
  size_t depth = L.path_.size();
  auto env_before = L.env_;
  int first_local = L.next_local_id_;

  // An arm's path at its end holds, past its own condition, the conditions
  // under which it did not escape (`if (n < 3) return;` inside it): what
  // follows the if runs only where the arm that ran went on to its end.
  auto run_arm = [&](bool positive, const std::function<Escape()>& arm,
                     std::vector<PathCond>& goes_on) {
    ++L.open_arms_; // (an arm's errors are recovered in it: it returns)
    L.path_.push_back({c, positive});
    Escape e = arm();
    --L.open_arms_;
    goes_on.assign(L.path_.begin() + std::ptrdiff_t(depth) + 1, L.path_.end());
    L.path_.resize(depth);
    return e;
  };
  std::vector<PathCond> then_goes_on, else_goes_on;
  Escape then_e = run_arm(true, then_arm, then_goes_on);
  auto env_then = L.env_;
  int after_then = L.next_local_id_;

  L.env_ = env_before;
  Escape else_e = run_arm(false, else_arm, else_goes_on);
  auto env_else = L.env_;
  int after_else = L.next_local_id_;
  // (an arm's escape conditions may read values made in the arm: inlined, so
  // nothing of an arm is evaluated where the arm does not run)
  auto shared = [&](const ExprP& local) { return L.guards_.guarded(local, depth); };
  for (auto& pc : then_goes_on)
    pc.cond = inline_locals(pc.cond, first_local, after_then, shared);
  for (auto& pc : else_goes_on)
    pc.cond = inline_locals(pc.cond, after_then, after_else, shared);

  // Merge values assigned in the branches: v = c ? v_then : v_else. A branch
  // that escaped contributes nothing after it (a return: InlineFrame::exits).
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
    ExprP then_value = inline_locals(*t, first_local, after_then, shared);
    ExprP else_value = inline_locals(*e, after_then, after_else, shared);
    return make_local(decl->getNameAsString(), decl, select(c, then_value, else_value));
  };
  for (auto& [decl, b] : L.env_) {
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
  // What follows runs where the arm that ran did not escape: the other arm's
  // side where one always escapes (then what that arm went on under), else
  // (c && then_goes_on) || (!c && else_goes_on) where an arm escaped in part.
  const size_t before = L.path_.size();
  auto went_on = [](const ExprP& first, const std::vector<PathCond>& rest) {
    return rest.empty() ? first : binary(Op::And, first, path_condition(rest));
  };
  if (then_e == Escape::Always || else_e == Escape::Always) {
    const bool then_runs = else_e == Escape::Always;
    L.path_.push_back({c, then_runs});
    for (const auto& pc : then_runs ? then_goes_on : else_goes_on)
      L.path_.push_back(pc);
  } else if (!then_goes_on.empty() || !else_goes_on.empty()) {
    L.path_.push_back(
        {binary(Op::Or, went_on(c, then_goes_on), went_on(unary(Op::Not, c), else_goes_on)), true});
  }
  // `if (n < 3) return;` in the kernel itself, outside every loop, helper and
  // other if: a guard of the whole kernel (it is also on every later path).
  if (L.loops_.empty() && L.frames_.empty() && L.open_arms_ == 0)
    for (size_t i = before; i < L.path_.size(); ++i)
      L.k_.guards.push_back(L.path_[i]);
  return Escape::None;
}

// Whether `s` holds a `break` that ends the switch around it (not one of a
// nested switch).
static const BreakStmt* switch_break(const Stmt* s) {
  if (!s || isa<SwitchStmt>(s) || isa<ForStmt>(s) || isa<CXXForRangeStmt>(s) || isa<WhileStmt>(s) ||
      isa<DoStmt>(s)) // (a loop's own break: refused with the loop)
    return nullptr;
  if (const auto* b = dyn_cast<BreakStmt>(s))
    return b;
  for (const Stmt* c : s->children())
    if (const BreakStmt* b = switch_break(c))
      return b;
  return nullptr;
}

// `switch (x) { case 1: case 2: A; break; default: B; }` on an integer:
// if/else arms on `x == 1 || x == 2`, the default on none of the labels.
// Each case ends in `break` (or in `continue`/`return`, or is the last):
// a case that falls through into the next, or breaks from inside an if, is
// refused.
Escape Statements::switch_stmt(const SwitchStmt* s) {
  if (s->getInit() || s->getConditionVariable())
    L.fail(s->getBeginLoc(), "switch with an initializer or a declaration is outside the subset");
  const auto* body = dyn_cast<CompoundStmt>(s->getBody());
  if (!body)
    L.fail(s->getBeginLoc(), "a switch's body is a block of cases: 'switch (x) { case 0: ... "
                             "break; }'");
  ExprP x = L.exprs_.expr(s->getCond());
  if (x->type != Type::Int)
    L.fail(s->getCond()->getBeginLoc(), "a switch on a value that is not an integer");
  struct Case {
    std::vector<int64_t> labels;
    bool is_default = false;
    std::vector<const Stmt*> stmts;
    SourceLocation loc;
  };
  std::vector<Case> cases;
  for (const Stmt* child : body->body()) {
    const Stmt* st = child;
    if (isa<SwitchCase>(st)) {
      cases.push_back({});
      cases.back().loc = st->getBeginLoc();
      // `case 1: case 2: A`: labels nest, the statement innermost
      while (const auto* sc = dyn_cast<SwitchCase>(st)) {
        if (const auto* c = dyn_cast<CaseStmt>(sc)) {
          clang::Expr::EvalResult r;
          if (c->caseStmtIsGNURange() || !c->getLHS()->EvaluateAsInt(r, L.ctx_))
            L.fail(c->getBeginLoc(), "a case label is one integer constant");
          cases.back().labels.push_back(L.ints_.constant(r.Val.getInt(), c->getBeginLoc()));
        } else {
          cases.back().is_default = true;
        }
        st = sc->getSubStmt();
      }
    } else if (cases.empty()) {
      L.fail(st->getBeginLoc(), "statement before the first case of a switch is never executed");
    }
    cases.back().stmts.push_back(st);
  }
  for (size_t k = 0; k < cases.size(); ++k) {
    auto& c = cases[k];
    const bool last = k + 1 == cases.size();
    // `case 2: { ...; break; }`: the block's statements
    if (const auto* block = c.stmts.empty() ? nullptr : dyn_cast<CompoundStmt>(c.stmts.back());
        block && !block->body_empty() && isa<BreakStmt>(block->body_back())) {
      c.stmts.pop_back();
      c.stmts.insert(c.stmts.end(), block->body_begin(), block->body_end());
    }
    if (!c.stmts.empty() && isa<BreakStmt>(c.stmts.back()))
      c.stmts.pop_back();
    else if (!last && (c.stmts.empty() ||
                       !(isa<ReturnStmt>(c.stmts.back()) || isa<ContinueStmt>(c.stmts.back()))))
      L.fail(c.loc,
             "a case that falls through into the next is outside the kernel subset; end "
             "each case with 'break' (cases that share their statements are labels of "
             "one case: 'case 1: case 2: ...')",
             "dpgen-unsupported");
    for (const Stmt* st : c.stmts)
      if (const BreakStmt* b = switch_break(st))
        L.fail(b->getBeginLoc(),
               "a 'break' ends its case only as the case's last statement; "
               "put what follows it under an if/else",
               "dpgen-unsupported");
  }
  // The cases in source order, each on its labels (the earlier ones do not
  // hold there), and the default's statements (a case with a `default:`
  // label among its labels) where none holds.
  auto matches = [&](const Case& c) {
    ExprP m;
    for (int64_t v : c.labels) {
      ExprP eq = binary(Op::Eq, x, int_const(v));
      m = m ? binary(Op::Or, m, eq) : eq;
    }
    return m;
  };
  const Case* fallback = nullptr;
  std::vector<const Case*> labelled;
  for (const auto& c : cases)
    (c.is_default ? fallback : labelled.emplace_back()) = &c;
  std::function<Escape(size_t)> arms = [&](size_t k) -> Escape {
    if (k == labelled.size())
      return fallback ? sequence(fallback->stmts) : Escape::None;
    return branch(
        matches(*labelled[k]), [&] { return sequence(labelled[k]->stmts); },
        [&] { return arms(k + 1); });
  };
  return arms(0);
}

ExprP Statements::make_local(const std::string& base, const VarDecl* decl, ExprP def) {
  auto l = std::make_shared<LocalVar>();
  std::string name = base;
  for (int n = 1; L.local_names_.count(name) || L.loop_names_.count(name) || L.is_reserved(name);
       ++n)
    name = fmt::format("{}_{}", L.unprefixed(base), n);
  L.local_names_.insert(name);
  l->name = name;
  l->def = def;
  l->id = L.next_local_id_++;
  l->made_under = L.path_;
  // (a value computed from an accumulator's sum, `double norm = sqrt(s);`,
  // is needed only where that sum is: not a kernel-level local)
  l->kernel_level = L.loops_.empty() && !any_node(def, [&](const ExprP& x) {
                      return x->op == Op::Read && L.is_hidden(x->name);
                    });
  // A kernel-level value made under a condition (in an arm, after a guard:
  // `if (n == 0) return; double last = a[n - 1];`) is computed before every
  // loop: where it reads an array or divides integers by a variable, only
  // where the condition holds (`!(n == 0) ? a[n - 1] : 0.0`).
  if (l->kernel_level && !L.path_.empty() && may_fault(def))
    l->def = when(path_condition(L.path_), def);
  if (def->type == Type::Int) {
    // Integers become std::ptrdiff_t in the generated code (see emit.cpp:
    // index arithmetic that vectorizes and never wraps, also for unsigned
    // locals such as `size_t k = n - 1 - i;` that later go negative in the
    // adjoint's index algebra); wider types keep their own.
    QualType t = decl ? decl->getType().getNonReferenceType().getUnqualifiedType() : L.ctx_.IntTy;
    bool widen = !t->isIntegerType() || L.ctx_.getTypeSize(t) <= 64;
    l->type_name = widen ? "std::ptrdiff_t" : L.spelled(t);
  } else
    l->type_name = type_spelling(def->type);
  if (l->kernel_level)
    L.k_.kernel_locals.push_back(l);
  return local_ref(l);
}

void Statements::declare(const Decl* d) {
  // Declarations that make no value: type aliases (`using Tag = ...;`),
  // static_assert, using-declarations and -directives.
  if (isa<TypedefNameDecl>(d) || isa<StaticAssertDecl>(d) || isa<UsingDecl>(d) ||
      isa<UsingDirectiveDecl>(d))
    return;
  const auto* v = dyn_cast<VarDecl>(d);
  if (!v)
    L.fail(d->getLocation(), "only variable declarations are allowed in a kernel");
  // `static const double w[3] = {...}` or `static constexpr double c = 0.5`: a constant with a
  // constant initializer holds the same values on every call, as it would without `static`.
  const bool constant =
      v->getType().isConstant(L.ctx_) && v->getInit() && v->hasConstantInitialization();
  if ((v->isStaticLocal() || v->hasGlobalStorage()) && !constant)
    L.fail(v->getLocation(),
           fmt::format("static variable '{}' is global state (it keeps its value from call to "
                       "call), outside the kernel subset; a constant table is 'static const' "
                       "or 'static constexpr' with a constant initializer",
                       v->getNameAsString()));
  if (const auto* at = L.ctx_.getAsConstantArrayType(v->getType())) {
    if (at->getSize().getZExtValue() > 64) { // a line buffer (lower_buffer.cpp)
      L.bufs_.declare_buffer(v, at->getElementType(),
                             int_const(static_cast<long long>(at->getSize().getZExtValue())));
      return;
    }
    declare_array(v, at);
    return;
  }
  if (const auto* vat = L.ctx_.getAsVariableArrayType(v->getType())) { // `double tmp[nx]`
    L.bufs_.declare_buffer(v, vat->getElementType(), L.exprs_.expr(vat->getSizeExpr()));
    return;
  }
  if (L.bufs_.declare_array_pointer(v) || L.bufs_.declare_vector(v) || // a std::vector local
      L.ptrs_.declare(v)) // `double (*u)[n][n]`, `double* row`
    return;
  if (const auto* rd = v->getType().getNonReferenceType()->getAsCXXRecordDecl();
      rd && rd->isLambda()) {
    L.inl_.declare_lambda(v, rd);
    return;
  }
  if (L.objects_.declare_object(v)) // const auto lo = amrex::lbound(bx);
    return;
  if (const auto* rd = v->getType().getNonReferenceType()->getAsCXXRecordDecl();
      rd && (L.objects_.is_functor_class(rd) || L.views_.is_view_class(rd)) &&
      v->getInit()) { // const GradientFluxes f{phi, fx, ...}; const Grid2 U{u, nx};
    // (an accessor made here over the kernel's arrays: its operator() is inlined with its
    // members bound, as a functor's is)
    L.env_[v] = L.objects_.functor_binding(v->getInit(), rd);
    return;
  }
  if (auto sa = L.std_array(v->getType()); sa && sa->second > 64) { // a line buffer
    L.bufs_.declare_buffer(v, sa->first, int_const(static_cast<long long>(sa->second)));
    return;
  }
  if (auto sa = L.std_array(v->getType())) { // a coefficient table, a small buffer
    declare_array(
        v, L.ctx_.getAsConstantArrayType(L.ctx_.getConstantArrayType(
               sa->first, llvm::APInt(64, sa->second), nullptr, ArraySizeModifier::Normal, 0)));
    return;
  }
  auto t = L.scalar_type(v->getType());
  if (!t || v->getType()->isReferenceType())
    L.fail(v->getLocation(),
           fmt::format("{} of type '{}' is outside the kernel subset (int, float, double or bool "
                       "values, and small arrays of them)",
                       isa<DecompositionDecl>(v) ? "a structured binding (auto [x, y] = ...)"
                                                 : fmt::format("local '{}'", v->getNameAsString()),
                       v->getType().getAsString()));
  Binding b;
  b.kind = Binding::Value;
  b.kernel_level = L.loops_.empty();
  if (const clang::Expr* init = v->getInit()) {
    ExprP e = L.exprs_.expr(init);
    b.value = make_local(v->getNameAsString(), v, cast(e, *t));
  }
  L.env_[v] = b;
}

// A small local array (`double w[3] = {...}`, a line buffer `double v[5]`):
// each element is a local value, indexed by constants (counters of small
// constant loops count as constants: those loops are unrolled).
void Statements::declare_array(const VarDecl* v, const ConstantArrayType* at) {
  auto t = L.scalar_type(at->getElementType());
  uint64_t n = at->getSize().getZExtValue();
  if (!t || L.ctx_.getAsArrayType(at->getElementType()))
    L.fail(v->getLocation(), fmt::format("local array '{}' of type '{}' is outside the kernel "
                                         "subset (one-dimensional arrays of int, float or "
                                         "double)",
                                         v->getNameAsString(), v->getType().getAsString()));
  if (n > 64)
    L.fail(v->getLocation(), fmt::format("local array '{}' has {} elements; dpgen keeps local "
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
    if (list && L.std_array(v->getType()) && list->getNumInits() == 1) {
      if (const auto* inner = dyn_cast<InitListExpr>(list->getInit(0)->IgnoreImplicit()))
        list = inner;
      else if (isa<ImplicitValueInitExpr>(list->getInit(0)))
        all_zero = true;
    }
    if (!list)
      L.fail(init->getBeginLoc(), "a local array is initialised with a braced list");
    for (unsigned i = 0; !all_zero && i < list->getNumInits() && i < n; ++i)
      b.elems[i] = isa<ImplicitValueInitExpr>(list->getInit(i))
                       ? cast(int_const(0), *t)
                       : make_local(fmt::format("{}_{}", v->getNameAsString(), i), nullptr,
                                    cast(L.exprs_.expr(list->getInit(i)), *t));
    // Elements the list leaves out are zero, as in C.
    for (uint64_t i = all_zero ? 0 : list->getNumInits(); i < n; ++i)
      b.elems[i] = cast(int_const(0), *t);
  }
  L.env_[v] = b;
}

// The element of a local array that `idx` names: it must be a constant.
size_t Statements::local_index(const clang::Expr* idx_expr, const VarDecl* v, size_t n) {
  ExprP idx = L.exprs_.expr(idx_expr);
  auto p = to_poly(idx);
  // (an affine constant, or one C's integer operators give: `m % 2`, `m >> 1`
  // of an unrolled counter)
  std::optional<long long> value =
      p && p->is_constant() ? std::optional<long long>(p->constant_term()) : int_value(idx);
  if (!value)
    L.fail(idx_expr->getBeginLoc(), small_array_index(v->getNameAsString()));
  long long k = *value;
  if (k < 0 || k >= static_cast<long long>(n))
    L.fail(idx_expr->getBeginLoc(), fmt::format("index {} is outside local array '{}' of {} "
                                                "elements",
                                                k, v->getNameAsString(), n));
  return static_cast<size_t>(k);
}

// `a[k]` of a local array: its binding and element, if that is what `e` is.
std::optional<std::pair<const VarDecl*, size_t>> Statements::local_element(const clang::Expr* e) {
  const clang::Expr *base = nullptr, *idx = nullptr;
  if (const auto* oc = dyn_cast<CXXOperatorCallExpr>(e->IgnoreParens());
      oc && oc->getOperator() == OO_Subscript && oc->getNumArgs() == 2) { // t[m] of a std::array
    base = oc->getArg(0);
    idx = oc->getArg(1);
  } else if (const auto* sub = dyn_cast<ArraySubscriptExpr>(e->IgnoreParens())) {
    base = sub->getBase();
    idx = sub->getIdx();
  } else {
    return std::nullopt;
  }
  const auto* ref = dyn_cast<DeclRefExpr>(base->IgnoreParenImpCasts());
  const auto* v = ref ? dyn_cast<VarDecl>(ref->getDecl()) : nullptr;
  auto it = v ? L.env_.find(v) : L.env_.end();
  if (it == L.env_.end() || it->second.kind != Binding::LocalArray)
    return std::nullopt;
  return std::pair{v, local_index(idx, v, it->second.elems.size())};
}

// An expression statement: an assignment to an output element or a local.
void Statements::expr_stmt(const clang::Expr* e) {
  e = e->IgnoreParens();
  if (const auto* w = dyn_cast<ExprWithCleanups>(e)) // temporaries: std::max(a, 0.0)
    e = w->getSubExpr()->IgnoreParens();
  if (const auto* u = dyn_cast<UnaryOperator>(e); u && u->isIncrementDecrementOp()) {
    L.ptrs_.check_not_stepped(u);
    L.stores_.assign(u->getSubExpr(), u->isIncrementOp() ? BO_AddAssign : BO_SubAssign, nullptr,
                     u->getOperatorLoc());
    return;
  }
  if (L.for_loops_.running_.lower_inner_steps(e)) // b[idx++] = x
    return;
  // `(void)x;` (silences an unused-variable warning): nothing to do.
  if (const auto* c = dyn_cast<ExplicitCastExpr>(e);
      c && c->getType()->isVoidType() && isa<DeclRefExpr>(c->getSubExpr()->IgnoreParenImpCasts()))
    return;
  const auto* b = dyn_cast<BinaryOperator>(e);
  if (!b || !b->isAssignmentOp()) {
    if (L.stores_.swap(e)) // std::swap(a, b)
      return;
    if (isa<CallExpr>(e)) { // a void helper: its out-parameters and stores (or the unknown call)
      (void)L.exprs_.expr(e);
      if (e->getType()->isVoidType())
        return;
    }
    L.fail(e->getExprLoc(), "expression statement has no effect on an output; only "
                            "assignments are in the kernel subset");
  }
  if (!L.ptrs_.assign(b)) // (`row = a + j * nx;` of a C89 row pointer: PointerLocals)
    L.stores_.assign(b->getLHS(), b->getOpcode(), b->getRHS(), b->getOperatorLoc());
}

} // namespace dpgen::lowering
