// Lowering, helpers and lambdas (lower_inline.hpp): a call of a user's function
// or lambda is lowered by inlining its body, its parameters bound to the
// arguments' values (arrays to the kernel's arrays) and its returns made one
// value, selected by the conditions under which each is reached.
#include "lower_impl.hpp"

namespace dpgen::lowering {

// `U(i, j)` or `U[i]` where U is a local the kernel made over its arrays (`const Grid2 U{u, nx};`):
// a view class's object bound as a functor's is (lower_stmt.cpp), its members known.
bool Inliner::made_accessor(const CallExpr* c) const {
  const auto* oc = dyn_cast<CXXOperatorCallExpr>(c);
  if (!oc || (oc->getOperator() != OO_Call && oc->getOperator() != OO_Subscript))
    return false;
  const auto* ref = dyn_cast<DeclRefExpr>(oc->getArg(0)->IgnoreParenImpCasts());
  const auto* lv = ref ? dyn_cast<VarDecl>(ref->getDecl()) : nullptr;
  auto it = lv ? L.env_.find(lv) : L.env_.end();
  return it != L.env_.end() && it->second.kind == Binding::Lambda && it->second.functor &&
         it->second.fields;
}

// (lower_inline.hpp) The operator()'s parameters bound to the arguments' values and the
// object's members to what the kernel made it over, while its returned element is found.
std::optional<Access> Inliner::accessor_element(const CallExpr* c) {
  if (!made_accessor(c))
    return std::nullopt;
  const auto* m = dyn_cast_or_null<CXXMethodDecl>(c->getDirectCallee());
  const FunctionDecl* def = nullptr;
  if (!m || !m->hasBody(def) || !m->getReturnType()->isLValueReferenceType())
    return std::nullopt;
  const auto* body = dyn_cast<CompoundStmt>(def->getBody());
  const auto* ret = body && body->size() == 1 ? dyn_cast<ReturnStmt>(body->body_front()) : nullptr;
  if (!ret || !ret->getRetValue())
    L.fail(c->getBeginLoc(),
           fmt::format("'{}' of '{}' returns a reference: dpgen follows one whose body is the "
                       "one statement 'return p[<index>];', the element of an array it holds",
                       def->getNameAsString(), m->getParent()->getNameAsString()));
  const auto* ref = dyn_cast<DeclRefExpr>(c->getArg(0)->IgnoreParenImpCasts());
  const Binding& object = L.env_.at(llvm::cast<VarDecl>(ref->getDecl()));
  std::vector<std::pair<const VarDecl*, std::optional<Binding>>> saved;
  for (unsigned i = 0; i < def->getNumParams(); ++i) {
    const ParmVarDecl* pd = def->getParamDecl(i);
    auto t = L.scalar_type(pd->getType().getNonReferenceType());
    if (!t || (pd->getType()->isReferenceType() &&
               !pd->getType().getNonReferenceType().isConstQualified()))
      L.fail(pd->getLocation(), fmt::format("parameter '{}' of '{}' has type '{}', outside the "
                                            "kernel subset",
                                            pd->getNameAsString(), def->getNameAsString(),
                                            pd->getType().getAsString()));
    Binding b;
    b.kind = Binding::Value;
    b.value = cast(L.exprs_.expr(c->getArg(i + 1)), *t);
    auto it = L.env_.find(pd);
    saved.push_back({pd, it == L.env_.end() ? std::nullopt : std::optional<Binding>(it->second)});
    L.env_[pd] = b;
  }
  const std::map<const FieldDecl*, Binding> outer_fields = L.fields_;
  L.fields_ = *object.fields;
  auto restore = [&] {
    L.fields_ = outer_fields;
    for (const auto& [pd, b] : saved)
      if (b)
        L.env_[pd] = *b;
      else
        L.env_.erase(pd);
  };
  std::optional<Access> a;
  try {
    a = L.exprs_.element(ret->getRetValue()->IgnoreParenImpCasts()); // (const: a no-op cast)
  } catch (const Rejected&) {
    restore();
    throw;
  }
  restore();
  if (!a)
    L.fail(ret->getBeginLoc(),
           fmt::format("'{}' of '{}' returns a reference to something other than an element of "
                       "an array it holds, outside the kernel subset",
                       def->getNameAsString(), m->getParent()->getNameAsString()));
  return a;
}

ExprP Inliner::inline_call(const CallExpr* c, const FunctionDecl* f) {
  const FunctionDecl* def = nullptr;
  f->hasBody(def);
  for (const auto& fr : L.frames_)
    if (fr.fn->getCanonicalDecl() == def->getCanonicalDecl())
      L.fail(c->getBeginLoc(), fmt::format("recursive call to '{}' is outside the kernel subset",
                                         def->getNameAsString()));
  if (L.frames_.size() == 16)
    L.fail(c->getBeginLoc(), "helper calls nest more than 16 deep");
  // A lambda of the kernel: its call operator, the closure object first.
  unsigned first = 0;
  std::shared_ptr<std::map<const FieldDecl*, Binding>> functor_fields; // (a functor's members)
  if (const auto* m = dyn_cast<CXXMethodDecl>(def);
      m && (m->getParent()->isLambda() || L.objects_.is_functor_class(m->getParent()) ||
            made_accessor(c))) {
    const auto* oc = dyn_cast<CXXOperatorCallExpr>(c);
    const auto* ref =
        oc ? dyn_cast<DeclRefExpr>(oc->getArg(0)->IgnoreParenImpCasts()) : nullptr;
    const auto* lv = ref ? dyn_cast<VarDecl>(ref->getDecl()) : nullptr;
    if (lv && L.poisoned_.count(lv))
      throw Rejected{}; // its declaration's error is reported already
    auto it = lv ? L.env_.find(lv) : L.env_.end();
    if (it == L.env_.end() || it->second.kind != Binding::Lambda)
      L.fail(c->getBeginLoc(), "a lambda is called through a local of the kernel that holds it "
                             "(auto f = [&](...) {...}; f(...))");
    if (it->second.functor && it->second.fields) // its members, while its body runs
      functor_fields = it->second.fields;
    if (!m->isConst() && it->second.functor)
      L.fail(c->getBeginLoc(),
             fmt::format("'{}' is called through a non-const operator() of '{}': an object "
                         "that may change itself from call to call is outside the kernel "
                         "subset; declare the operator() const",
                         lv->getNameAsString(), m->getParent()->getNameAsString()));
    if (!m->isConst())
      L.fail(c->getBeginLoc(), fmt::format("lambda '{}' is mutable: its copies keep their "
                                         "changes from one call to the next, which inlining "
                                         "does not; make it a plain lambda",
                                         lv->getNameAsString()));
    for (const auto& [cv, was] : it->second.captured_arrays)
      if (L.env_[cv].elems != was)
        L.fail(c->getBeginLoc(), fmt::format("lambda '{}' captured local array '{}' by copy, "
                                           "and '{}' changed before this call; capture it by "
                                           "reference, or make the lambda after the change",
                                           lv->getNameAsString(), cv->getNameAsString(),
                                           cv->getNameAsString()));
    for (const auto& [cv, was] : it->second.captured)
      if (L.env_[cv].value != was)
        L.fail(c->getBeginLoc(), fmt::format("lambda '{}' captured '{}' by copy, and '{}' "
                                           "changed before this call; capture it by "
                                           "reference, or make the lambda after the change",
                                           lv->getNameAsString(), cv->getNameAsString(),
                                           cv->getNameAsString()));
    first = 1;
  } else if ((isa<CXXMethodDecl>(def) && !L.this_call(c)) || def->isVariadic()) {
    L.fail(c->getBeginLoc(), fmt::format("'{}' is a member or variadic function; a kernel calls "
                                       "free helper functions only",
                                       def->getNameAsString()));
  }
  const bool is_void = def->getReturnType()->isVoidType();
  auto rt = is_void ? std::optional<Type>(Type::Double) : L.scalar_type(def->getReturnType());
  if (!rt || def->getReturnType()->isReferenceType())
    L.fail(c->getBeginLoc(), fmt::format("helper '{}' returns '{}'; a helper called from a kernel "
                                       "returns an int, float, double or bool value (or "
                                       "void, with its results in out-parameters)",
                                       def->getNameAsString(),
                                       def->getReturnType().getAsString()));
  if (c->getNumArgs() != def->getNumParams() + first)
    L.fail(c->getBeginLoc(), "call with default arguments is outside the kernel subset");
  // Bind the parameters (arguments are evaluated in the caller's scope).
  std::vector<std::pair<const VarDecl*, Binding>> binds;
  // Out-parameters: `double& f` and `double* f` (called with `&x`) bound to
  // a local x of the caller: copied in, and copied back after the body
  // (the same as a reference while no two of them name one local).
  std::vector<std::pair<const ParmVarDecl*, const VarDecl*>> outs;
  std::vector<std::optional<ExprP>> outs_bound; // each local's value when bound
  // `inner(f, x)` in a helper whose `double* f` is an out-parameter: f passed
  // on, bound to the same local of the caller.
  // The binding of the local that `e` names (env_'s end if none).
  auto local_of = [&](const clang::Expr* e) {
    const auto* r = e ? dyn_cast<DeclRefExpr>(e->IgnoreParenImpCasts()) : nullptr;
    const auto* v = r ? dyn_cast<VarDecl>(r->getDecl()) : nullptr;
    return v ? L.env_.find(v) : L.env_.end();
  };
  auto forwarded = [&](const clang::Expr* arg) {
    auto it = local_of(arg);
    return it != L.env_.end() && it->second.kind == Binding::Value && it->second.deref_only;
  };
  auto out_param = [&](const ParmVarDecl* pd, const clang::Expr* arg, bool pointer) {
    const clang::Expr* a = arg->IgnoreParenImpCasts();
    const bool fwd = pointer && forwarded(arg);
    if (pointer && !fwd) {
      const auto* u = dyn_cast<UnaryOperator>(a);
      a = u && u->getOpcode() == UO_AddrOf ? u->getSubExpr()->IgnoreParenImpCasts() : nullptr;
    }
    auto it = local_of(a);
    const VarDecl* v = it != L.env_.end() ? it->first : nullptr;
    if (it == L.env_.end() || it->second.kind != Binding::Value || (it->second.deref_only && !fwd))
      L.fail(arg->getBeginLoc(), fmt::format("argument for out-parameter '{}' of helper '{}' must "
                                           "be {}a local variable of the caller",
                                           pd->getNameAsString(), def->getNameAsString(),
                                           pointer ? "the address of " : ""));
    for (const auto& [q, w] : outs)
      if (w == v)
        L.fail(arg->getBeginLoc(), fmt::format("local '{}' is passed to two out-parameters of "
                                             "helper '{}'",
                                             v->getNameAsString(), def->getNameAsString()));
    if (!is_void)
      L.fail(pd->getLocation(), fmt::format("helper '{}' returns a value and has out-parameter "
                                          "'{}': return void and put every result in an "
                                          "out-parameter, or return the one result",
                                          def->getNameAsString(), pd->getNameAsString()));
    Binding b = it->second;
    b.deref_only = pointer;
    binds.push_back({pd, b});
    outs.push_back({pd, v});
    L.red_.bind_param(pd, v); // (an accumulator's updates through the parameter)
    // why `v` has no value here (a sum of the loop), said of the parameter too
    if (auto why = L.why_unset_.find(v); why != L.why_unset_.end())
      L.why_unset_[pd] = why->second;
    else
      L.why_unset_.erase(pd);
    outs_bound.push_back(it->second.value);
  };
  for (unsigned i = 0; i < def->getNumParams(); ++i) {
    const ParmVarDecl* pd = def->getParamDecl(i);
    const clang::Expr* arg = c->getArg(i + first);
    QualType pt = pd->getType();
    // A library parallel-for's body (`template <class F> void ParallelFor(Box
    // const& box, F&& f)`): a lambda, a view or an object of the caller.
    if (std::optional<Binding> b = L.objects_.class_argument(pd, arg, def)) {
      binds.push_back({pd, *b});
      continue;
    }
    if (pt->isPointerType() && !pt->getPointeeType().isConstQualified() &&
        L.scalar_type(pt->getPointeeType()) && [&] {
          const auto* u = dyn_cast<UnaryOperator>(arg->IgnoreParenImpCasts());
          return (u && u->getOpcode() == UO_AddrOf &&
                  !isa<ArraySubscriptExpr>(u->getSubExpr()->IgnoreParens())) || // (not &b[k])
                 forwarded(arg);
        }()) {
      out_param(pd, arg, true);
      continue;
    }
    if (pt->isPointerType()) {
      if (std::optional<Binding> moved = L.ptrs_.pointer_into(arg); moved && moved->offset) {
        binds.push_back({pd, *moved}); // `a + j * nx`, `&b[k]`, a pointer local (lower_pointer)
        continue;
      }
      const clang::Expr* base = arg->IgnoreParenImpCasts();
      const Param* ap =
          isa<DeclRefExpr>(base) || isa<MemberExpr>(base) ? L.exprs_.array_base(base) : nullptr;
      if (!ap)
        L.fail(arg->getBeginLoc(), fmt::format("argument for pointer parameter '{}' of helper "
                                             "'{}' must be an array parameter of the kernel "
                                             "itself (no pointer arithmetic)",
                                             pd->getNameAsString(), def->getNameAsString()));
      Binding b;
      b.kind = Binding::ArrayParam;
      b.param = ap;
      binds.push_back({pd, b});
      continue;
    }
    if (pt->isReferenceType() && !pt.getNonReferenceType().isConstQualified()) {
      if (!L.scalar_type(pt.getNonReferenceType()))
        L.fail(pd->getLocation(), fmt::format("parameter '{}' of helper '{}' has type '{}', "
                                            "outside the kernel subset",
                                            pd->getNameAsString(), def->getNameAsString(),
                                            pt.getAsString()));
      out_param(pd, arg, false);
      continue;
    }
    auto t = L.scalar_type(pt.getNonReferenceType());
    if (!t)
      L.fail(pd->getLocation(), fmt::format("parameter '{}' of helper '{}' has type '{}', outside "
                                          "the kernel subset",
                                          pd->getNameAsString(), def->getNameAsString(),
                                          pt.getAsString()));
    Binding b;
    b.kind = Binding::Value;
    ExprP v = cast(L.exprs_.expr(arg), *t);
    // A counter or a local passed as it is (a parallel-for's `f(i, j, k)`)
    // needs no name of its own: one would only alias it, and generated code
    // would define it where nothing reads it (its indices print expanded).
    b.value = v->op == Op::LoopVar || v->op == Op::Local
                  ? v
                  : L.stmts_.make_local(pd->getNameAsString(), pd, v);
    binds.push_back({pd, b});
  }
  check_aliases(c, def, binds, outs);
  // What the caller sees of the call: its variables and the out-parameters.
  std::set<const VarDecl*> visible;
  for (const auto& [v, b] : L.env_)
    if (!def->Encloses(v->getDeclContext()))
      visible.insert(v);
  for (const auto& [pd, v] : outs)
    visible.insert(pd);
  for (const auto& [pd, b] : binds)
    L.env_[pd] = b;
  L.frames_.push_back({def, L.path_.size(), L.loops_.size(), *rt, {}, is_void, L.unrolling_});
  std::map<const FieldDecl*, Binding> outer_fields;
  if (functor_fields) {
    outer_fields = L.fields_;
    L.fields_ = *functor_fields;
  }
  Escape e;
  try {
    e = L.stmts_.lower(def->getBody());
  } catch (const Rejected&) {
    for (const auto& [pd, v] : outs)
      L.red_.unbind_param(pd);
    L.path_.resize(L.frames_.back().path_depth);
    L.frames_.pop_back();
    if (functor_fields)
      L.fields_ = outer_fields;
    throw;
  }
  if (functor_fields)
    L.fields_ = outer_fields;
  for (const auto& [pd, v] : outs)
    L.red_.unbind_param(pd);
  Lowerer::InlineFrame fr = L.frames_.back();
  L.frames_.pop_back();
  L.path_.resize(fr.path_depth);
  merge_exits(fr.exits, fr.path_depth, visible);
  if (is_void) {
    for (size_t k = 0; k < outs.size(); ++k) {
      const auto& [pd, v] = outs[k];
      // (v changed since it was bound, through a lambda that captured it or
      // in another argument: the copy back would undo that)
      if (L.env_[v].value != outs_bound[k])
        L.fail(c->getBeginLoc(),
               fmt::format("'{}' is passed to out-parameter '{}' of helper '{}' and also "
                           "assigned during the call (by a lambda that captured it by "
                           "reference, or in another argument); pass the helper another "
                           "variable",
                           v->getNameAsString(), pd->getNameAsString(), def->getNameAsString()));
      if (L.env_[v].value != L.env_[pd].value) // (the caller may be a frame too)
        L.stores_.check_caller_write(v, c->getBeginLoc());
      L.env_[v].value = L.env_[pd].value;
      if (auto why = L.why_unset_.find(pd); !L.env_[v].value && why != L.why_unset_.end())
        L.why_unset_[v] = why->second; // (left without a value by the helper: why)
    }
    return nullptr;
  }
  if (e != Escape::Always || fr.returns.empty())
    L.fail(def->getBody()->getEndLoc(), fmt::format("helper '{}' may reach its end without "
                                                  "returning a value",
                                                  def->getNameAsString()));
  // The last return is reached when no earlier one was. (A value made in the
  // helper's arms, `if (i == 0) return 0.0; const double d = a[i - 1]; return
  // d * d;`, is guarded by them: the select evaluates both.)
  ExprP v = L.guards_.guarded(fr.returns.back().second, fr.path_depth);
  for (size_t i = fr.returns.size() - 1; i-- > 0;) {
    const ExprP cond = path_condition(fr.returns[i].first);
    const ExprP value = L.guards_.guarded(fr.returns[i].second, fr.path_depth);
    v = cond ? select(L.guards_.guarded(cond, fr.path_depth), value, v) : value;
  }
  return v;
}

// (lower_inline.hpp) Each way out is taken where its conditions hold and no
// earlier one's did (the statements after a return run under its negation),
// so a variable is, after the call, `c1 ? at_1 : c2 ? at_2 : ... : at_end`,
// its values guarded as a merged arm's are. (Values and local arrays only:
// an object's fields are not assigned in the kernel subset.)
void Inliner::merge_exits(const FrameExits& exits, size_t depth,
                          const std::set<const VarDecl*>& visible) {
  auto merged = [&](const VarDecl* var, std::optional<ExprP> v, auto&& at) {
    for (size_t k = exits.size(); k-- > 0;) {
      const std::optional<ExprP> x = at(exits[k].second);
      if (x == v)
        continue;
      if (!x || !v) { // (unset on one way out: unset after the call)
        v = std::nullopt;
        continue;
      }
      const ExprP cond = L.guards_.guarded(path_condition(exits[k].first), depth);
      v = L.stmts_.make_local(
          var->getNameAsString(), var,
          select(cond, L.guards_.guarded(*x, depth), L.guards_.guarded(*v, depth)));
    }
    return v;
  };
  for (const VarDecl* var : exits.empty() ? std::set<const VarDecl*>{} : visible) {
    auto find = [&](const std::map<const VarDecl*, Binding>& env) {
      auto it = env.find(var);
      return it == env.end() ? nullptr : &it->second;
    };
    auto it = L.env_.find(var);
    if (it == L.env_.end())
      continue;
    Binding& b = it->second;
    if (b.kind == Binding::Value) {
      b.value = merged(var, b.value, [&](const auto& env) {
        const Binding* e = find(env);
        return e ? e->value : std::nullopt;
      });
    } else if (b.kind == Binding::LocalArray) {
      for (size_t i = 0; i < b.elems.size(); ++i)
        b.elems[i] = merged(var, b.elems[i], [&](const auto& env) -> std::optional<ExprP> {
          const Binding* e = find(env);
          return e && i < e->elems.size() ? e->elems[i] : std::nullopt;
        });
    }
  }
}

// A local bound to an out-parameter or a `const&` parameter (a copy, and a
// copy back) and captured by reference by a lambda passed to the same call,
// or by the called lambda itself, which reads or assigns the local itself:
// the two would not see each other.
void Inliner::check_aliases(
    const CallExpr* c, const FunctionDecl* def,
    const std::vector<std::pair<const VarDecl*, Binding>>& binds,
    const std::vector<std::pair<const ParmVarDecl*, const VarDecl*>>& outs) {
  auto captured_by_ref = [](const CXXRecordDecl* closure, std::set<const VarDecl*>& out) {
    for (const LambdaCapture& lc : closure->captures())
      if (lc.capturesVariable() && lc.getCaptureKind() == LCK_ByRef)
        if (const auto* cv = dyn_cast<VarDecl>(lc.getCapturedVar()))
          out.insert(cv);
  };
  std::set<const VarDecl*> by_ref, by_self; // (by_self: the called lambda's own captures)
  for (const auto& [pd, b] : binds)
    if (b.kind == Binding::Lambda && b.closure && b.closure->isLambda())
      captured_by_ref(b.closure, by_ref);
  if (const auto* m = dyn_cast<CXXMethodDecl>(def); m && m->getParent()->isLambda())
    captured_by_ref(m->getParent(), by_self);
  if (by_ref.empty() && by_self.empty())
    return;
  std::vector<std::pair<const ParmVarDecl*, const VarDecl*>> copies = outs;
  for (unsigned i = 0; i < def->getNumParams(); ++i) {
    const ParmVarDecl* pd = def->getParamDecl(i);
    const clang::Expr* arg = c->getArg(i + (c->getNumArgs() - def->getNumParams()));
    const auto* r = dyn_cast<DeclRefExpr>(arg->IgnoreParenImpCasts());
    const auto* v = r ? dyn_cast<VarDecl>(r->getDecl()) : nullptr;
    if (pd->getType()->isReferenceType() && v)
      copies.push_back({pd, v});
  }
  for (const auto& [pd, v] : copies) {
    if (by_self.count(v))
      L.fail(c->getBeginLoc(),
             fmt::format("'{}' is passed to parameter '{}' of this lambda (inlined as a copy) "
                         "and captured by reference by the lambda itself: the two would not "
                         "see each other's changes; pass another variable",
                         v->getNameAsString(), pd->getNameAsString()));
    if (by_ref.count(v))
      L.fail(c->getBeginLoc(),
             fmt::format("'{}' is passed to parameter '{}' of helper '{}' "
                         "(inlined as a copy) and captured by reference by a "
                         "lambda passed to the same call; pass the lambda "
                         "another variable",
                         v->getNameAsString(), pd->getNameAsString(), def->getNameAsString()));
  }
}

// `auto f = [&](int i) { ... };`: called later, inlined like a helper. A
// variable captured by copy must still have the value it had here when the
// lambda is called; init-captures and `this` are outside the subset.
void Inliner::declare_lambda(const VarDecl* v, const CXXRecordDecl* rd) {
  const clang::Expr* init = v->getInit();
  const auto* le = init ? dyn_cast<LambdaExpr>(init->IgnoreImplicit()) : nullptr;
  if (!le)
    L.fail(v->getLocation(), fmt::format("lambda '{}' must be initialised with a lambda "
                                       "expression",
                                       v->getNameAsString()), "dpgen-lambda");
  (void)rd;
  L.env_[v] = lambda_binding(le, v->getNameAsString());
}

Binding Inliner::lambda_binding(const LambdaExpr* le, const std::string& name) {
  Binding b;
  b.kind = Binding::Lambda;
  b.closure = le->getLambdaClass();
  for (const LambdaCapture& c : le->captures()) {
    if (c.capturesThis() && L.self_class_) // a member kernel's object: its members are read-only
      continue;
    if (!c.capturesVariable() || le->isInitCapture(&c))
      L.fail(c.getLocation(), fmt::format("lambda '{}' captures something other than the "
                                        "kernel's variables (this, or an init-capture)",
                                        name), "dpgen-lambda");
    if (c.getCaptureKind() != LCK_ByCopy)
      continue;
    const auto* cv = dyn_cast<VarDecl>(c.getCapturedVar());
    auto it = cv ? L.env_.find(cv) : L.env_.end();
    if (it != L.env_.end() && it->second.kind == Binding::Value)
      b.captured.push_back({cv, it->second.value});
    if (it != L.env_.end() && it->second.kind == Binding::LocalArray)
      b.captured_arrays.push_back({cv, it->second.elems});
  }
  return b;
}

} // namespace dpgen::lowering
