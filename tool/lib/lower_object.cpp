// Lowering, objects (lower_object.hpp): class-typed parameters that are no
// view (AMReX's Box, a struct of grid constants) and local objects, read as
// constants of the kernel spelled as written (`bx.smallEnd(0)`,
// `u.extent(0)`, `grid.dx`); functor objects and class arguments of helpers.
#include "lower_impl.hpp"

#include "print.hpp"

#include <algorithm>

namespace dpgen::lowering {

namespace {

// `e` without what only copies or converts it: implicit nodes, temporaries,
// copy and move constructions, a functional cast (`T{...}`): the object made.
const clang::Expr* made_object(const clang::Expr* e) {
  for (;;) {
    e = e->IgnoreImplicit()->IgnoreParenImpCasts();
    if (const auto* m = dyn_cast<MaterializeTemporaryExpr>(e)) {
      e = m->getSubExpr();
    } else if (const auto* c = dyn_cast<CXXConstructExpr>(e);
               c && c->getNumArgs() == 1 && c->getConstructor()->isCopyOrMoveConstructor()) {
      e = c->getArg(0);
    } else if (const auto* f = dyn_cast<CXXFunctionalCastExpr>(e)) {
      e = f->getSubExpr();
    } else {
      return e;
    }
  }
}

// f(x) of each item joined with ", "; nullopt if any is nullopt.
template <typename Range, typename F>
std::optional<std::string> each_joined(const Range& items, F&& f) {
  std::vector<std::string> out;
  for (const auto* x : items) {
    std::optional<std::string> t = f(x);
    if (!t)
      return std::nullopt;
    out.push_back(*t);
  }
  return fmt::format("{}", fmt::join(out, ", "));
}

} // namespace

void Objects::object_param(const DeclaratorDecl* p, const std::string& ann, Param& out) {
  const CXXRecordDecl* rd = p->getType().getNonReferenceType()->getAsCXXRecordDecl();
  if (!ann.empty() && ann != "dpgen.const")
    L.fail(p->getLocation(), fmt::format("parameter '{}' of class '{}' is no array view (it has "
                                       "no operator() or operator[]): DPGEN_IN/DPGEN_OUT do not "
                                       "apply to it",
                                       out.name, rd->getQualifiedNameAsString()),
         "dpgen-signature");
  if (p->getType()->isReferenceType() && !p->getType().getNonReferenceType().isConstQualified())
    L.fail(p->getLocation(), fmt::format("parameter '{}' of class '{}' is a non-const reference: "
                                       "the kernel may only read it",
                                       out.name, rd->getQualifiedNameAsString()),
         "dpgen-signature");
  out.kind = ParamKind::Scalar;
  out.object = true;
  out.elem = Type::Bool; // (no number of its own, never shown or checked: read through members)
  out.elem_name = Lowerer::spelled(p->getType().getNonReferenceType());
  out.tag_declaration = L.views_.include_for(rd, p->getLocation(), fmt::format("parameter '{}'", out.name));
}


std::optional<std::string> Objects::object_text(const clang::Expr* e) {
  e = made_object(e); // (a copy: the object copied)
  if (const auto* r = dyn_cast<DeclRefExpr>(e)) {
    const auto* v = dyn_cast<VarDecl>(r->getDecl());
    if (!v)
      return std::nullopt;
    if (auto l = object_locals_.find(v); l != object_locals_.end())
      return l->second;
    if (auto a = object_aliases_.find(v); a != object_aliases_.end())
      return a->second;
    auto it = L.env_.find(v);
    if (it == L.env_.end() || !it->second.param)
      return std::nullopt;
    const Param* p = it->second.param;
    if (p->view || p->object)
      return p->name;
    return std::nullopt;
  }
  if (const auto* l = dyn_cast<IntegerLiteral>(e))
    return std::to_string(l->getValue().getSExtValue());
  if (const Binding* b = isa<MemberExpr>(e) ? L.bound(e) : nullptr) {
    // a view or object member of a member kernel's class: its parameter
    if (b->param && (b->param->view || b->param->object))
      return b->param->name;
    return std::nullopt;
  }
  if (const auto* m = dyn_cast<MemberExpr>(e)) {
    if (!isa<FieldDecl>(m->getMemberDecl()) && !isa<CXXMethodDecl>(m->getMemberDecl()))
      return std::nullopt;
    auto base = object_text(m->getBase());
    if (!base)
      return std::nullopt;
    return *base + (m->isArrow() ? "->" : ".") + m->getMemberDecl()->getNameAsString();
  }
  if (const auto* c = dyn_cast<CXXMemberCallExpr>(e)) {
    const CXXMethodDecl* md = c->getMethodDecl();
    const auto* callee = dyn_cast<MemberExpr>(c->getCallee()->IgnoreParens());
    if (!md || !callee || !md->isConst())
      return std::nullopt;
    auto head = object_text(callee);
    if (!head)
      return std::nullopt;
    std::vector<std::string> args;
    for (const clang::Expr* a : c->arguments()) {
      clang::Expr::EvalResult r;
      if (!a->getType()->isIntegerType() || !a->EvaluateAsInt(r, L.ctx_))
        return std::nullopt; // (arguments that are constants only: no loop counter)
      args.push_back(std::to_string(r.Val.getInt().getExtValue()));
    }
    return fmt::format("{}({})", *head, fmt::join(args, ", "));
  }
  if (const auto* oc = dyn_cast<CXXOperatorCallExpr>(e);
      oc && oc->getOperator() == OO_Subscript && oc->getNumArgs() == 2) {
    // an element of an object (a std::array, an IntVect) at a constant index (`lo[0]`)
    const CXXRecordDecl* rd = oc->getArg(0)->getType()->getAsCXXRecordDecl();
    clang::Expr::EvalResult r;
    if (!rd || L.views_.is_view_class(rd) || !oc->getArg(1)->EvaluateAsInt(r, L.ctx_))
      return std::nullopt;
    auto base = object_text(oc->getArg(0));
    if (!base)
      return std::nullopt;
    return fmt::format("{}[{}]", *base, r.Val.getInt().getExtValue());
  }
  if (const auto* c = dyn_cast<CallExpr>(e)) {
    // a free function of objects (amrex::lbound(bx)): constexpr, or inline
    // and taking every argument by value or const reference
    const FunctionDecl* f = c->getDirectCallee();
    if (!f || isa<CXXMethodDecl>(f) || !f->isInlined() || !f->getReturnType()->isRecordType())
      return std::nullopt;
    for (const ParmVarDecl* pv : f->parameters())
      if (pv->getType()->isReferenceType() && !pv->getType().getNonReferenceType().isConstQualified())
        return std::nullopt;
    auto args = each_joined(c->arguments(), [&](const clang::Expr* a) { return object_text(a); });
    if (!args)
      return std::nullopt;
    return fmt::format("{}({})", f->getQualifiedNameAsString(), *args);
  }
  if (const auto* s = dyn_cast<ArraySubscriptExpr>(e)) {
    // a member array at a constant index (`geom.dx[0]`)
    clang::Expr::EvalResult r;
    auto base = object_text(s->getBase());
    if (!base || !s->getIdx()->EvaluateAsInt(r, L.ctx_) || !s->getBase()->IgnoreParenImpCasts()
                                                             ->getType()
                                                             ->isConstantArrayType())
      return std::nullopt;
    return fmt::format("{}[{}]", *base, r.Val.getInt().getExtValue());
  }
  return std::nullopt;
}

std::optional<ExprP> Objects::object_value(const clang::Expr* e) {
  const clang::Expr* s = e->IgnoreParenImpCasts();
  const auto* oc = dyn_cast<CXXOperatorCallExpr>(s);
  if (!isa<MemberExpr>(s) && !isa<CXXMemberCallExpr>(s) && !isa<ArraySubscriptExpr>(s) &&
      !(oc && oc->getOperator() == OO_Subscript))
    return std::nullopt;
  auto t = L.scalar_type(s->getType());
  if (!t)
    return std::nullopt;
  auto text = object_text(s);
  if (!text)
    return std::nullopt;
  // (an unsigned value, `u.extent(0)`, is read as a signed 64-bit one: index
  // arithmetic goes below zero; an enum, `p.bc`, as the integer its
  // enumerators are in the IR)
  if (*t == Type::Int && (s->getType()->isUnsignedIntegerType() || s->getType()->isEnumeralType()))
    text = fmt::format("static_cast<std::ptrdiff_t>({})", *text);
  if (*t == Type::Int)
    object_values_.insert(*text);
  return param(*text, *t);
}

bool Objects::declare_object(const VarDecl* v) {
  const CXXRecordDecl* rd = v->getType().getNonReferenceType()->getAsCXXRecordDecl();
  if (!rd || rd->isLambda() || L.views_.is_view_class(rd) || !v->getInit())
    return false;
  auto text = object_text(v->getInit());
  if (!text)
    return false;
  if (!L.loops_.empty())
    L.fail(v->getLocation(), fmt::format("local object '{}' is declared inside a loop; declare it "
                                       "before the loops",
                                       v->getNameAsString()));
  // (in a helper, or a second call of one, it gets a name of its own)
  std::string name = v->getNameAsString();
  for (int n = 1; L.local_names_.count(name) || L.k_.names.count(name) || L.is_reserved(name); ++n)
    name = fmt::format("{}_{}", v->getNameAsString(), n);
  auto l = std::make_shared<LocalVar>();
  l->name = name;
  l->type_name = "auto";
  l->def = param(*text, Type::Int); // (printed only: its members are read by name)
  l->id = L.next_local_id_++;
  l->kernel_level = true;
  l->opaque = true;
  L.local_names_.insert(name);
  L.k_.kernel_locals.push_back(l);
  object_locals_[v] = name;
  return true;
}

std::optional<Binding> Objects::class_argument(const ParmVarDecl* pd, const clang::Expr* arg,
                                               const FunctionDecl* helper) {
  QualType pt = pd->getType();
  const CXXRecordDecl* rd = pt.getNonReferenceType()->getAsCXXRecordDecl();
  if (!rd)
    return std::nullopt;
  const clang::Expr* a = made_object(arg); // (passed by value: the object copied)
  if (rd->isEmpty() && !rd->isLambda() && !is_functor_class(rd)) {
    Binding b; // a tag (`Tag{}` choosing an overload): no value
    b.kind = Binding::Value;
    return b;
  }
  if (rd->isLambda() || is_functor_class(rd)) {
    if (const auto* le = dyn_cast<LambdaExpr>(a))
      return L.inl_.lambda_binding(le, pd->getNameAsString());
    if (!isa<DeclRefExpr>(a))
      return functor_binding(a, rd);
    if (const auto* r = dyn_cast<DeclRefExpr>(a))
      if (const auto* v = dyn_cast<VarDecl>(r->getDecl())) {
        auto it = L.env_.find(v);
        if (it != L.env_.end() && it->second.kind == Binding::Lambda)
          return it->second;
      }
    L.fail(arg->getBeginLoc(), fmt::format("argument for parameter '{}' of helper '{}' must be a "
                                         "lambda expression or a functor, or a local holding one",
                                         pd->getNameAsString(), helper->getNameAsString()),
         "dpgen-lambda");
  }
  if (pt->isReferenceType() && !pt.getNonReferenceType().isConstQualified() &&
      !L.views_.is_view_class(rd))
    return std::nullopt; // (an out-parameter: not a class the kernel can pass)
  if (L.views_.is_view_class(rd)) {
    const Binding* b = L.bound(a);
    if (b && b->kind == Binding::Lambda && b->functor && b->fields)
      return *b; // an accessor the kernel made over its arrays (`const Grid2 U{u, nx}`)
    if (!b || b->kind != Binding::ArrayParam || !b->param->view)
      L.fail(arg->getBeginLoc(),
             fmt::format("argument for view parameter '{}' of helper '{}' "
                         "must be a view parameter of the kernel or an accessor it made over its "
                         "arrays",
                         pd->getNameAsString(), helper->getNameAsString()));
    return *b;
  }
  auto text = object_text(a);
  if (!text)
    text = materialize(a, rd);
  const auto* ctor = dyn_cast<CXXConstructExpr>(a);
  const bool label =
      isa<StringLiteral>(a) || (ctor && ctor->getNumArgs() >= 1 &&
                                isa<StringLiteral>(ctor->getArg(0)->IgnoreParenImpCasts()));
  if (!text && label) { // a label (Kokkos::parallel_for("name", ...))
    Binding b;
    b.kind = Binding::Value; // (no value: the helper must not read it)
    return b;
  }
  if (!text)
    L.fail(arg->getBeginLoc(), fmt::format("argument for parameter '{}' of helper '{}' (of class "
                                         "'{}') must be an object parameter of the kernel or "
                                         "made from one (a Box, lbound(bx))",
                                         pd->getNameAsString(), helper->getNameAsString(),
                                         rd->getQualifiedNameAsString()));
  object_aliases_[pd] = *text;
  Binding b;
  b.kind = Binding::Value; // (no value: read only through object_text)
  return b;
}

// A temporary object made for a helper from values of the kernel
// (`Kokkos::MDRangePolicy<Kokkos::Rank<2>>({1, 1}, {nx - 1, ny - 1})`, a
// RangePolicy(0, n)): a kernel-level local object of generated code,
// constructed from the same values; nullopt where `e` is no such construction.
std::optional<std::string> Objects::materialize(const clang::Expr* e, const CXXRecordDecl* rd) {
  const auto* c = dyn_cast<CXXConstructExpr>(e);
  if (!c || !L.loops_.empty() || rd->isInStdNamespace() || !rd->hasDefinition())
    return std::nullopt;
  // each argument a value of the kernel, or a brace list of them
  std::function<std::optional<std::string>(const clang::Expr*)> arg =
      [&](const clang::Expr* a) -> std::optional<std::string> {
    a = made_object(a);
    if (const auto* il = dyn_cast<InitListExpr>(a)) {
      if (il->isSyntacticForm() == false && il->getSyntacticForm())
        il = il->getSyntacticForm();
      auto items = each_joined(il->inits(), arg);
      return items ? std::optional<std::string>("{" + *items + "}") : std::nullopt;
    }
    if (!L.scalar_type(a->getType()))
      return std::nullopt;
    ExprP v = L.exprs_.expr(a);
    if (any_node(v, [](const ExprP& x) {
          return x->op == Op::LoopVar || x->op == Op::Read || is_real(x->type);
        }))
      return std::nullopt;
    return print(v);
  };
  std::optional<std::string> args = each_joined(c->arguments(), arg);
  if (!args)
    return std::nullopt;
  // Classes of the kernel file in its type (a work tag: MDRangePolicy<FaceX,
  // Rank<2>>) are declared by the generated files; they must be empty.
  std::function<bool(QualType)> declarable = [&](QualType t) {
    const CXXRecordDecl* r = t->getAsCXXRecordDecl();
    if (!r)
      return true;
    if (L.sm_.getFileID(L.sm_.getExpansionLoc(r->getLocation())) == L.sm_.getMainFileID()) {
      if (!r->isEmpty() || isa<ClassTemplateSpecializationDecl>(r) ||
          !r->getDeclContext()->getRedeclContext()->isFileContext())
        return false;
      std::string decl = fmt::format("struct {};", r->getNameAsString());
      for (const DeclContext* dc = r->getDeclContext(); dc; dc = dc->getParent())
        if (const auto* ns = dyn_cast<NamespaceDecl>(dc))
          decl = fmt::format("namespace {} {{ {} }}", ns->getNameAsString(), decl);
      if (std::find(L.k_.declarations.begin(), L.k_.declarations.end(), decl) ==
          L.k_.declarations.end())
        L.k_.declarations.push_back(decl);
      return true;
    }
    if (const auto* spec = dyn_cast<ClassTemplateSpecializationDecl>(r))
      for (const TemplateArgument& a : spec->getTemplateArgs().asArray()) {
        if (a.getKind() == TemplateArgument::Type && !declarable(a.getAsType()))
          return false;
        if (a.getKind() == TemplateArgument::Pack)
          for (const TemplateArgument& x : a.pack_elements())
            if (x.getKind() == TemplateArgument::Type && !declarable(x.getAsType()))
              return false;
      }
    return true;
  };
  if (!declarable(e->getType()))
    return std::nullopt;
  std::string name = "dpgen_object";
  // (a dpgen_ name: the prefix is dpgen's own, no kernel may use it)
  for (int n = 1; L.local_names_.count(name) || L.k_.names.count(name); ++n)
    name = fmt::format("dpgen_object_{}", n);
  auto l = std::make_shared<LocalVar>();
  l->name = name;
  l->type_name = "auto";
  l->def = param(fmt::format("{}({})", Lowerer::spelled(e->getType()), *args), Type::Int);
  l->id = L.next_local_id_++;
  l->kernel_level = true;
  l->opaque = true;
  L.local_names_.insert(name);
  L.k_.kernel_locals.push_back(l);
  return name;
}


bool Objects::is_functor_class(const CXXRecordDecl* rd) const {
  if (!rd || rd->isLambda() || !rd->hasDefinition() || rd->isInStdNamespace())
    return false;
  for (const NamedDecl* d : call_operators(rd, L.ctx_)) {
    const FunctionDecl* f = d->getAsFunction();
    if (f && f->getReturnType()->isVoidType())
      return true;
  }
  return false;
}

namespace {
// A constructor whose body is empty and which sets every member, in declaration order, to one
// of its parameters (`: p(p), nx(nx) {}`), with no base class.
bool copying_constructor(const CXXConstructExpr* cc) {
  const CXXConstructorDecl* ctor = cc->getConstructor();
  const FunctionDecl* def = nullptr;
  if (!ctor || !ctor->hasBody(def) || ctor->isCopyOrMoveConstructor())
    return false;
  const auto* body = dyn_cast<CompoundStmt>(def->getBody());
  const auto* d = llvm::cast<CXXConstructorDecl>(def);
  if (!body || !body->body_empty() || d->getParent()->getNumBases() != 0)
    return false;
  auto field = d->getParent()->field_begin();
  for (const CXXCtorInitializer* ci : d->inits()) {
    if (!ci->isMemberInitializer() || field == d->getParent()->field_end() ||
        ci->getMember() != *field++)
      return false;
    const auto* r = dyn_cast<DeclRefExpr>(ci->getInit()->IgnoreImplicit()->IgnoreParenImpCasts());
    if (!r || !isa<ParmVarDecl>(r->getDecl()))
      return false;
  }
  return field == d->getParent()->field_end();
}
} // namespace

Binding Objects::functor_binding(const clang::Expr* init, const CXXRecordDecl* rd) {
  const clang::Expr* e = made_object(init);
  Binding b;
  b.kind = Binding::Lambda;
  b.functor = true;
  b.closure = rd;
  if (const auto* u = dyn_cast<UnaryOperator>(e);
      u && u->getOpcode() == UO_Deref && isa<CXXThisExpr>(u->getSubExpr()->IgnoreParenImpCasts())) {
    if (rd != L.self_class_)
      L.fail(init->getBeginLoc(), "'*this' of a class other than the member kernel's");
    return b; // the member kernel's own object: its members are L.fields_
  }
  // Each member's value: the aggregate's initializer in order, or the argument that a
  // constructor which only copies its parameters into the members (`Grid2(const double* p,
  // int nx) : p(p), nx(nx) {}`) gives it.
  std::vector<const clang::Expr*> values;
  if (rd->getNumBases() != 0)
    L.fail(init->getBeginLoc(),
           fmt::format("'{}' has a base class: an object the kernel makes must hold its "
                       "members itself",
                       rd->getNameAsString()),
           "dpgen-lambda");
  if (const auto* il = dyn_cast<InitListExpr>(e)) {
    for (unsigned i = 0; i < il->getNumInits(); ++i)
      values.push_back(il->getInit(i));
  } else if (const auto* cc = dyn_cast<CXXConstructExpr>(e); cc && copying_constructor(cc)) {
    const FunctionDecl* def = nullptr; // (the definition: a declaration has no initializers)
    cc->getConstructor()->hasBody(def);
    for (const CXXCtorInitializer* ci : llvm::cast<CXXConstructorDecl>(def)->inits()) {
      const auto* r = dyn_cast<DeclRefExpr>(ci->getInit()->IgnoreImplicit()->IgnoreParenImpCasts());
      values.push_back(cc->getArg(llvm::cast<ParmVarDecl>(r->getDecl())->getFunctionScopeIndex()));
    }
  } else {
    L.fail(init->getBeginLoc(),
           fmt::format("functor '{}' must be made here from the kernel's "
                       "views, arrays and values ({}{{...}}, members in "
                       "order, or a constructor that copies its parameters "
                       "into the members), or be '*this' of a member kernel",
                       rd->getNameAsString(), rd->getNameAsString()),
           "dpgen-lambda");
  }
  b.fields = std::make_shared<std::map<const FieldDecl*, Binding>>();
  unsigned i = 0;
  for (const FieldDecl* f : rd->fields()) {
    if (i >= values.size())
      L.fail(init->getBeginLoc(),
             fmt::format("functor '{}': member '{}' has no value here", rd->getNameAsString(),
                         f->getNameAsString()),
             "dpgen-lambda");
    const clang::Expr* v = values[i++];
    QualType t = f->getType();
    const CXXRecordDecl* frd = t->getAsCXXRecordDecl();
    if (t->isPointerType() || (frd && L.views_.is_view_class(frd))) {
      // (a view member is copied, or converted to const elements, from the kernel's)
      const clang::Expr* src = v->IgnoreImplicit()->IgnoreParenImpCasts();
      if (const auto* cc = dyn_cast<CXXConstructExpr>(src); cc && cc->getNumArgs() == 1)
        src = cc->getArg(0);
      const Binding* a = L.bound(src);
      std::optional<Binding> moved; // `u + j * nx`: a row of the kernel's array, at its offset
      if (!a && t->isPointerType() && (moved = L.ptrs_.pointer_into(src)) && moved->offset)
        a = &*moved;
      if (!a || a->kind != Binding::ArrayParam)
        L.fail(v->getBeginLoc(), fmt::format("member '{}' of functor '{}' must be made from an "
                                           "array or view parameter of the kernel",
                                           f->getNameAsString(), rd->getNameAsString()),
             "dpgen-lambda");
      (*b.fields)[f] = *a;
      continue;
    }
    auto st = L.scalar_type(t);
    if (!st)
      L.fail(v->getBeginLoc(), fmt::format("member '{}' of functor '{}' has type '{}', outside the "
                                         "kernel subset (views, arrays and numbers)",
                                         f->getNameAsString(), rd->getNameAsString(),
                                         t.getAsString()),
           "dpgen-lambda");
    Binding value;
    value.kind = Binding::Value;
    value.value = cast(L.exprs_.expr(v), *st);
    (*b.fields)[f] = value;
  }
  return b;
}


} // namespace dpgen::lowering
