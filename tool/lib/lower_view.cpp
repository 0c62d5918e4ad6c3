// Lowering, array views and objects (lower_impl.hpp): parameters of a class
// type. A view (a pointer member indexed by an inline, affine, one-to-one
// operator(): AMReX Array4, Kokkos::View, mdspan, an AthenaArray-like class)
// is an array whose element a(k, j, i) is the flat k * P + j * R + i of the
// IR, as for rows reached through pointers (ir.hpp: Param::view); any other
// class-typed parameter (AMReX's Box, a struct of grid constants) is an
// object the kernel reads integer and floating values from (`bx.smallEnd(0)`,
// `u.extent(0)`, `grid.dx`), constants of the kernel spelled as written.
#include "lower_impl.hpp"

#include "print.hpp"

#include <algorithm>

namespace dpgen::lowering {

namespace {

// The operator() (or operator[]) overloads of a class, templates included.
std::vector<const NamedDecl*> call_operators(const CXXRecordDecl* rd, ASTContext& ctx) {
  std::vector<const NamedDecl*> out;
  if (!rd || !rd->hasDefinition())
    return out;
  for (auto op : {OO_Call, OO_Subscript})
    for (const NamedDecl* d : rd->lookup(ctx.DeclarationNames.getCXXOperatorName(op)))
      out.push_back(d);
  return out;
}

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

// `t` with const dropped at every level (`const double* const*` -> `double**`).
QualType without_const(QualType t, ASTContext& ctx) {
  t = t.getCanonicalType();
  if (t->isPointerType())
    return ctx.getPointerType(without_const(t->getPointeeType(), ctx));
  return t.getUnqualifiedType();
}

} // namespace

bool Lowerer::is_view_class(const CXXRecordDecl* rd) const {
  if (!rd || rd->isLambda() || rd->isInStdNamespace()) // (std::string has an operator[])
    return false;
  // a pointer member (the data; an IntVect's operator[] reads an array of
  // its own: an object) ...
  std::function<bool(const CXXRecordDecl*)> has_pointer = [&](const CXXRecordDecl* r) {
    if (!r || !r->hasDefinition())
      return false;
    for (const FieldDecl* f : r->fields())
      if (f->getType()->isPointerType() || has_pointer(f->getType()->getAsCXXRecordDecl()))
        return true;
    for (const CXXBaseSpecifier& b : r->bases())
      if (has_pointer(b.getType()->getAsCXXRecordDecl()))
        return true;
    return false;
  };
  if (!has_pointer(rd))
    return false;
  // ... and a call operator that returns an element (a functor's returns void)
  for (const NamedDecl* d : call_operators(rd, ctx_)) {
    const FunctionDecl* f = d->getAsFunction();
    if (f && !f->getReturnType()->isVoidType())
      return true;
  }
  return false;
}

std::string Lowerer::include_for(const CXXRecordDecl* rd, SourceLocation use,
                                 const std::string& what) {
  const Decl* d = rd;
  if (const auto* s = dyn_cast<ClassTemplateSpecializationDecl>(rd))
    d = s->getSpecializedTemplate();
  FileID fid = sm_.getFileID(sm_.getExpansionLoc(d->getLocation()));
  const FileID main = sm_.getMainFileID();
  if (fid == main)
    fail(use, fmt::format("{} has a class defined in the kernel file ('{}'): the generated "
                          "files must see its definition, so move it to a header the kernel "
                          "file includes",
                          what, rd->getQualifiedNameAsString()),
         "dpgen-signature");
  SourceLocation inc;
  for (int depth = 0; depth < 256; ++depth) {
    inc = sm_.getIncludeLoc(fid);
    if (inc.isInvalid())
      break;
    FileID parent = sm_.getFileID(sm_.getExpansionLoc(inc));
    if (parent == main)
      break;
    fid = parent;
  }
  if (inc.isInvalid() || sm_.getFileID(sm_.getExpansionLoc(inc)) != main)
    fail(use, fmt::format("{}: dpgen cannot find the #include of the kernel file that declares "
                          "class '{}'",
                          what, rd->getQualifiedNameAsString()),
         "dpgen-signature");
  // The whole line of the directive, as written.
  auto [file, offset] = sm_.getDecomposedLoc(sm_.getExpansionLoc(inc));
  llvm::StringRef buffer = sm_.getBufferData(file);
  size_t begin = buffer.rfind('\n', offset);
  begin = begin == llvm::StringRef::npos ? 0 : begin + 1;
  size_t end = buffer.find('\n', offset);
  std::string line = buffer.slice(begin, end).trim().str();
  if (line.empty() || line[0] != '#')
    fail(use, fmt::format("{}: the directive that includes class '{}' is not a plain #include "
                          "line",
                          what, rd->getQualifiedNameAsString()),
         "dpgen-signature");
  return line;
}

// The view's type with non-const elements: a template argument that is a
// const type (Array4<const double>, View<const double**>, mdspan<const
// double, ...>) loses its const at every level; a class without one
// (AthenaArray<double> by const&) is the same class, taken by non-const
// reference (its const operator() reads a value, the other one returns the
// element).
// `t` as generated code spells it with const dropped from every element type
// it is made of (Array4<const double> -> Array4<double>; mdspan<const double,
// E, L, default_accessor<const double>> -> mdspan<double, E, L,
// default_accessor<double>>); `changed` says whether there was any.
std::string Lowerer::without_element_const(QualType t, bool& changed) const {
  t = t.getCanonicalType();
  QualType m = without_const(t, ctx_);
  if (m != t)
    changed = true;
  const auto* spec = dyn_cast_or_null<ClassTemplateSpecializationDecl>(m->getAsCXXRecordDecl());
  if (!spec)
    return spelled(m);
  PrintingPolicy policy{LangOptions()};
  policy.Bool = true;
  policy.SuppressTagKeyword = true;
  std::vector<std::string> args;
  auto arg_text = [&](const TemplateArgument& a) {
    if (a.getKind() == TemplateArgument::Type)
      return without_element_const(a.getAsType(), changed);
    std::string s;
    llvm::raw_string_ostream os(s);
    a.print(policy, os, /*IncludeType=*/true);
    return os.str();
  };
  for (const TemplateArgument& a : spec->getTemplateArgs().asArray()) {
    if (a.getKind() == TemplateArgument::Pack) {
      for (const TemplateArgument& e : a.pack_elements())
        args.push_back(arg_text(e));
    } else {
      args.push_back(arg_text(a));
    }
  }
  return fmt::format("{}<{}>", spec->getSpecializedTemplate()->getQualifiedNameAsString(),
                     fmt::join(args, ", "));
}

std::string Lowerer::mutable_view_type(const DeclaratorDecl* p) const {
  QualType q = p->getType();
  bool ref = q->isReferenceType();
  QualType cls = q.getNonReferenceType();
  bool changed = false;
  std::string type = without_element_const(cls.getUnqualifiedType(), changed);
  if (!ref)
    return type;
  // Taken by const reference where the view is shallow (its const operator()
  // returns a non-const element: Array4<double>, View<double**>) or its
  // elements' constness was in its template arguments; else (a deep-const
  // class, AthenaArray) by non-const reference.
  bool shallow = changed;
  for (const NamedDecl* d : call_operators(cls->getAsCXXRecordDecl(), ctx_)) {
    const auto* m = dyn_cast_or_null<CXXMethodDecl>(d->getAsFunction());
    if (m && m->isConst() && m->getReturnType()->isLValueReferenceType() &&
        !m->getReturnType().getNonReferenceType().isConstQualified())
      shallow = true;
  }
  return shallow ? "const " + type + "&" : type + "&";
}

void Lowerer::view_param(const DeclaratorDecl* p, const std::string& ann, Param& out) {
  const CXXRecordDecl* rd = p->getType().getNonReferenceType()->getAsCXXRecordDecl();
  if (ann == "dpgen.inout")
    fail(p->getLocation(), fmt::format("DPGEN_INOUT view '{}': pass its old values and its new "
                                       "ones as two views (DPGEN_IN and DPGEN_OUT)",
                                       out.name),
         "dpgen-signature");
  if (p->getType()->isReferenceType() && !p->getType().getNonReferenceType().isConstQualified() &&
      ann.empty())
    fail(p->getLocation(), fmt::format("unmarked view '{}' is a non-const reference: mark it "
                                       "DPGEN_OUT, or make it const",
                                       out.name),
         "dpgen-signature");
  // The element type: what operator() returns, without reference and const.
  std::optional<Type> et;
  std::string elem_name;
  for (const NamedDecl* d : call_operators(rd, ctx_)) {
    const FunctionDecl* f = d->getAsFunction();
    if (!f || isa<FunctionTemplateDecl>(d)) {
      // (a member template, as mdspan's: its instantiations say, at the calls)
      if (const auto* ft = dyn_cast<FunctionTemplateDecl>(d))
        for (const FunctionDecl* s : ft->specializations())
          f = s;
      if (!f)
        continue;
    }
    QualType r = f->getReturnType().getNonReferenceType().getCanonicalType().getUnqualifiedType();
    if (r->isDependentType())
      continue;
    et = scalar_type(r);
    elem_name = spelled(r);
    if (et)
      break;
  }
  if (!et || *et == Type::Bool)
    fail(p->getLocation(), fmt::format("view '{}' of class '{}': its operator() must return "
                                       "float, double or an integer type (by value or by "
                                       "reference)",
                                       out.name, rd->getQualifiedNameAsString()),
         "dpgen-signature");
  if ((ann == "dpgen.in" || ann == "dpgen.out") && !is_real(*et))
    fail(p->getLocation(), fmt::format("{} view '{}' must hold float or double",
                                       ann == "dpgen.in" ? "DPGEN_IN" : "DPGEN_OUT", out.name),
         "dpgen-signature");
  out.elem = *et;
  out.elem_name = elem_name;
  out.kind = ann == "dpgen.in"    ? ParamKind::In
             : ann == "dpgen.out" ? ParamKind::Out
                                  : ParamKind::ConstArray;
  out.view = true;
  out.view_rank = 0; // from its first element access (view_element)
  out.view_type = spelled(p->getType(), /*keep_const=*/true);
  out.view_mutable = mutable_view_type(p);
  out.tag_declaration = include_for(rd, p->getLocation(), fmt::format("view '{}'", out.name));
}

void Lowerer::object_param(const DeclaratorDecl* p, const std::string& ann, Param& out) {
  const CXXRecordDecl* rd = p->getType().getNonReferenceType()->getAsCXXRecordDecl();
  if (!ann.empty() && ann != "dpgen.const")
    fail(p->getLocation(), fmt::format("parameter '{}' of class '{}' is no array view (it has "
                                       "no operator() or operator[]): DPGEN_IN/DPGEN_OUT do not "
                                       "apply to it",
                                       out.name, rd->getQualifiedNameAsString()),
         "dpgen-signature");
  if (p->getType()->isReferenceType() && !p->getType().getNonReferenceType().isConstQualified())
    fail(p->getLocation(), fmt::format("parameter '{}' of class '{}' is a non-const reference: "
                                       "the kernel may only read it",
                                       out.name, rd->getQualifiedNameAsString()),
         "dpgen-signature");
  out.kind = ParamKind::Scalar;
  out.object = true;
  out.elem = Type::Bool; // (no number of its own, never shown or checked: read through members)
  out.elem_name = spelled(p->getType().getNonReferenceType());
  out.tag_declaration = include_for(rd, p->getLocation(), fmt::format("parameter '{}'", out.name));
}

ExprP Lowerer::level_symbol(const Param& p, int level) {
  auto& table = level == 1 ? row_lengths_ : level == 2 ? plane_lengths_ : cube_lengths_;
  auto it = table.find(p.name);
  if (it != table.end())
    return it->second;
  // each level's value above any offset within it (ir.hpp)
  const int levels = pointer_levels(p);
  long long value = 0;
  if (level == 1)
    value = levels == 3 ? kCubeRowSymbolValue : levels == 2 ? kPlaneRowSymbolValue : kRowSymbolValue;
  else if (level == 2)
    value = levels == 3 ? kCubePlaneSymbolValue : kPlaneSymbolValue;
  else
    value = kCubeSymbolValue;
  const std::string name = level == 1   ? row_symbol(p.name)
                           : level == 2 ? plane_symbol(p.name)
                                        : cube_symbol(p.name);
  ExprP s = opaque_symbol(name, value);
  table[p.name] = s;
  return s;
}

// A view's layout: its operator() must return `ptr[index]` for a pointer
// member `ptr` and an index affine in the operator's parameters, each with a
// stride of its own (a member, a product of members, a constant); which
// gives distinct indices distinct elements within the view's bounds (the
// documented assumption, as for rows of their own). mdspan's standard
// layouts, which compute the offset through their mapping, are one-to-one
// by the standard.
void Lowerer::check_layout(const FunctionDecl* op, const Param& p, SourceLocation use) {
  if (layouts_ok_.count(op))
    return;
  const auto* rd = dyn_cast<CXXRecordDecl>(op->getDeclContext());
  auto standard_mdspan = [&] {
    const auto* spec = dyn_cast_or_null<ClassTemplateSpecializationDecl>(rd);
    if (!spec || spec->getName() != "mdspan" || spec->getTemplateArgs().size() < 3)
      return false;
    const TemplateArgument& layout = spec->getTemplateArgs()[2];
    if (layout.getKind() != TemplateArgument::Type)
      return false;
    const CXXRecordDecl* l = layout.getAsType()->getAsCXXRecordDecl();
    return l && (l->getName() == "layout_right" || l->getName() == "layout_left");
  };
  std::string why;
  const FunctionDecl* def = op->getDefinition();
  const Stmt* body = def ? def->getBody() : nullptr;
  const auto* cs = dyn_cast_or_null<CompoundStmt>(body);
  const ReturnStmt* ret = cs && cs->size() == 1 ? dyn_cast<ReturnStmt>(cs->body_front()) : nullptr;
  const auto* sub = ret && ret->getRetValue()
                        ? dyn_cast<ArraySubscriptExpr>(ret->getRetValue()->IgnoreParenImpCasts())
                        : nullptr;
  const auto* base = sub ? dyn_cast<MemberExpr>(sub->getBase()->IgnoreParenImpCasts()) : nullptr;
  if (!base || !isa<CXXThisExpr>(base->getBase()->IgnoreParenImpCasts()) ||
      !base->getType()->isPointerType()) {
    if (standard_mdspan()) {
      layouts_ok_.insert(op);
      return;
    }
    fail(use, fmt::format("view '{}': the body of {}::operator() is not 'return ptr[index];' "
                          "with a pointer member (dpgen must see the index to know that "
                          "distinct indices are distinct elements)",
                          p.name, rd ? rd->getQualifiedNameAsString() : "?"),
         "dpgen-signature");
  }
  // The index as a polynomial in the operator's parameters (counters) and
  // the members it reads (sizes).
  std::function<std::optional<Poly>(const clang::Expr*)> poly =
      [&](const clang::Expr* e) -> std::optional<Poly> {
    e = e->IgnoreParenImpCasts();
    if (const auto* c = dyn_cast<ExplicitCastExpr>(e))
      return poly(c->getSubExpr());
    if (const auto* l = dyn_cast<IntegerLiteral>(e))
      return Poly::constant(static_cast<long long>(l->getValue().getSExtValue()));
    if (const auto* r = dyn_cast<DeclRefExpr>(e)) {
      if (const auto* pv = dyn_cast<ParmVarDecl>(r->getDecl()))
        return Poly::counter(fmt::format("dpgen_arg{}", pv->getFunctionScopeIndex()));
      return std::nullopt;
    }
    if (isa<MemberExpr>(e) || isa<ArraySubscriptExpr>(e)) {
      // a member (`jstride`, `begin.x`, `stride_[0]`): a size
      if (!e->getType()->isIntegerType())
        return std::nullopt;
      std::string s;
      llvm::raw_string_ostream os(s);
      e->printPretty(os, nullptr, PrintingPolicy(ctx_.getLangOpts()));
      if (os.str().find('(') != std::string::npos)
        return std::nullopt;
      return Poly::symbol("member:" + os.str());
    }
    if (const auto* u = dyn_cast<UnaryOperator>(e)) {
      if (u->getOpcode() == UO_Minus)
        if (auto a = poly(u->getSubExpr()))
          return -*a;
      if (u->getOpcode() == UO_Plus)
        return poly(u->getSubExpr());
      return std::nullopt;
    }
    if (const auto* b = dyn_cast<BinaryOperator>(e)) {
      auto l = poly(b->getLHS()), r = poly(b->getRHS());
      if (!l || !r)
        return std::nullopt;
      switch (b->getOpcode()) {
      case BO_Add:
        return *l + *r;
      case BO_Sub:
        return *l - *r;
      case BO_Mul:
        return *l * *r;
      default:
        return std::nullopt;
      }
    }
    return std::nullopt;
  };
  std::optional<Poly> index = poly(sub->getIdx());
  if (!index)
    why = "its index is not a sum of the indices times members or constants";
  if (why.empty())
    for (const auto& [m, c] : index->terms())
      if (std::count_if(m.begin(), m.end(), [](const Sym& s) { return s.is_counter(); }) > 1)
        why = "it multiplies two indices";
  std::vector<Poly> strides;
  for (unsigned d = 0; why.empty() && d < op->getNumParams(); ++d) {
    Sym arg = Sym::counter(fmt::format("dpgen_arg{}", d));
    Poly stride = index->coefficient(arg);
    if (stride == Poly())
      why = fmt::format("its index does not depend on index {}", d + 1);
    else if (std::find(strides.begin(), strides.end(), stride) != strides.end() ||
             std::find(strides.begin(), strides.end(), -stride) != strides.end())
      why = fmt::format("indices share the stride {}", stride.str());
    strides.push_back(stride);
  }
  if (why.empty()) {
    int constant = 0;
    for (const Poly& s : strides)
      constant += s.is_constant();
    if (constant > 1)
      why = "more than one index has a constant stride";
  }
  if (!why.empty()) {
    if (standard_mdspan()) {
      layouts_ok_.insert(op);
      return;
    }
    fail(use, fmt::format("view '{}': {}::operator() does not map distinct indices to distinct "
                          "elements as a layout does: {}",
                          p.name, rd ? rd->getQualifiedNameAsString() : "?", why),
         "dpgen-signature");
  }
  layouts_ok_.insert(op);
}

auto Lowerer::view_element(const CXXOperatorCallExpr* oc) -> std::optional<Access> {
  if (oc->getOperator() != OO_Call && oc->getOperator() != OO_Subscript)
    return std::nullopt;
  const Binding* b = bound(oc->getArg(0)); // (throws for a poisoned one)
  if (!b || b->kind != Binding::ArrayParam || !b->param->view)
    return std::nullopt;
  const Param* p = b->param;
  const FunctionDecl* op = oc->getDirectCallee();
  if (!op)
    fail(oc->getBeginLoc(), fmt::format("view '{}': dpgen cannot see which operator() this is",
                                        p->name));
  const unsigned rank = oc->getNumArgs() - 1;
  if (oc->getOperator() == OO_Subscript)
    fail(oc->getBeginLoc(), fmt::format("view '{}' is indexed with []: index it with its "
                                        "operator(), {}(i)",
                                        p->name, p->name));
  if (rank < 1 || rank > 4)
    fail(oc->getBeginLoc(), fmt::format("view '{}' is indexed with {} indices: dpgen takes "
                                        "views of rank 1 to 4",
                                        p->name, rank));
  if (p->view_rank != 0 && p->view_rank != static_cast<int>(rank))
    fail(oc->getBeginLoc(), fmt::format("view '{}' is indexed with {} indices here and {} "
                                        "elsewhere: use one operator() per view",
                                        p->name, rank, p->view_rank));
  check_layout(op, *p, oc->getBeginLoc());
  if (p->view_rank == 0) // k_.params owns it: the rank is known from here on
    const_cast<Param*>(p)->view_rank = static_cast<int>(rank);
  std::vector<ExprP> idx;
  bool piecewise = false;
  for (unsigned d = 1; d <= rank; ++d) {
    ExprP x = expr(oc->getArg(d));
    if (x->type != Type::Int)
      fail(oc->getArg(d)->getBeginLoc(), "array index must be an integer");
    if (rank > 1 && !to_poly(x)) {
      // A periodic wrap, `i == 0 ? nx - 1 : i - 1` (through locals): a
      // select whose arms are affine, or selects of such.
      std::function<bool(const ExprP&)> arms = [&](const ExprP& y) {
        if (y->op == Op::Local)
          return arms(y->local->def);
        if (y->op == Op::Select)
          return arms(y->ops[1]) && arms(y->ops[2]);
        return to_poly(y).has_value();
      };
      if (!arms(x))
        fail(oc->getArg(d)->getBeginLoc(),
             fmt::format("view '{}' is indexed at a data-dependent position; dpgen needs every "
                         "index of a view of rank 2 to 4 affine in the loop counters and "
                         "sizes, or a choice between affine ones (a periodic wrap)",
                         p->name));
      piecewise = true;
    }
    idx.push_back(x);
  }
  if (!piecewise)
    return Access{p, view_flat(*p, idx), {}};
  std::vector<ExprP> first = idx; // (the first arms: an affine index for messages)
  for (auto& x : first)
    while (!to_poly(x))
      x = x->op == Op::Local ? x->local->def : x->ops[1];
  return Access{p, view_flat(*p, first), idx};
}

// a(k, j, i): k * P + j * R + i (the innermost index last); a(n, k, j, i)
// adds n * C.
ExprP Lowerer::view_flat(const Param& p, const std::vector<ExprP>& idx) {
  const size_t rank = idx.size();
  ExprP flat = idx.back();
  for (size_t d = 0; d + 1 < rank; ++d) {
    int level = static_cast<int>(rank - 1 - d);
    flat = binary(Op::Add, binary(Op::Mul, idx[d], level_symbol(p, level)), flat);
  }
  return flat;
}

// q(k, j, i == 0 ? nx - 1 : i - 1) is i == 0 ? q(k, j, nx - 1) : q(k, j, i - 1):
// each arm an affine read, and the adjoint of a select is its arms' under
// their conditions.
ExprP Lowerer::piecewise_read(const Access& a, size_t d, std::vector<ExprP> idx, SourcePos at,
                              const std::string& source) {
  if (d == idx.size()) {
    ExprP r = read(a.param->name, view_flat(*a.param, idx), a.param->elem, at, shape_of(*a.param));
    std::const_pointer_cast<Expr>(r)->source = source;
    return r;
  }
  ExprP x = idx[d];
  while (x->op == Op::Local && !to_poly(x))
    x = x->local->def;
  if (to_poly(x)) {
    idx[d] = x;
    return piecewise_read(a, d + 1, idx, at, source);
  }
  auto arm = [&](const ExprP& y) {
    std::vector<ExprP> with = idx;
    with[d] = y;
    return piecewise_read(a, d, with, at, source);
  };
  return select(x->ops[0], arm(x->ops[1]), arm(x->ops[2]));
}

std::optional<std::string> Lowerer::object_text(const clang::Expr* e) {
  e = made_object(e); // (a copy: the object copied)
  if (const auto* r = dyn_cast<DeclRefExpr>(e)) {
    const auto* v = dyn_cast<VarDecl>(r->getDecl());
    if (!v)
      return std::nullopt;
    if (auto l = object_locals_.find(v); l != object_locals_.end())
      return l->second;
    if (auto a = object_aliases_.find(v); a != object_aliases_.end())
      return a->second;
    auto it = env_.find(v);
    if (it == env_.end() || !it->second.param)
      return std::nullopt;
    const Param* p = it->second.param;
    if (p->view || p->object)
      return p->name;
    return std::nullopt;
  }
  if (const auto* l = dyn_cast<IntegerLiteral>(e))
    return std::to_string(l->getValue().getSExtValue());
  if (const Binding* b = isa<MemberExpr>(e) ? bound(e) : nullptr) {
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
      if (!a->getType()->isIntegerType() || !a->EvaluateAsInt(r, ctx_))
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
    if (!rd || is_view_class(rd) || !oc->getArg(1)->EvaluateAsInt(r, ctx_))
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
    if (!base || !s->getIdx()->EvaluateAsInt(r, ctx_) || !s->getBase()->IgnoreParenImpCasts()
                                                             ->getType()
                                                             ->isConstantArrayType())
      return std::nullopt;
    return fmt::format("{}[{}]", *base, r.Val.getInt().getExtValue());
  }
  return std::nullopt;
}

std::optional<ExprP> Lowerer::object_value(const clang::Expr* e) {
  const clang::Expr* s = e->IgnoreParenImpCasts();
  const auto* oc = dyn_cast<CXXOperatorCallExpr>(s);
  if (!isa<MemberExpr>(s) && !isa<CXXMemberCallExpr>(s) && !isa<ArraySubscriptExpr>(s) &&
      !(oc && oc->getOperator() == OO_Subscript))
    return std::nullopt;
  auto t = scalar_type(s->getType());
  if (!t)
    return std::nullopt;
  auto text = object_text(s);
  if (!text)
    return std::nullopt;
  // (an unsigned value, `u.extent(0)`, is read as a signed 64-bit one: index
  // arithmetic goes below zero)
  if (*t == Type::Int && s->getType()->isUnsignedIntegerType())
    text = fmt::format("static_cast<std::ptrdiff_t>({})", *text);
  if (*t == Type::Int)
    object_values_.insert(*text);
  return param(*text, *t);
}

bool Lowerer::declare_object(const VarDecl* v) {
  const CXXRecordDecl* rd = v->getType().getNonReferenceType()->getAsCXXRecordDecl();
  if (!rd || rd->isLambda() || is_view_class(rd) || !v->getInit())
    return false;
  auto text = object_text(v->getInit());
  if (!text)
    return false;
  if (!loops_.empty())
    fail(v->getLocation(), fmt::format("local object '{}' is declared inside a loop; declare it "
                                       "before the loops",
                                       v->getNameAsString()));
  // (in a helper, or a second call of one, it gets a name of its own)
  std::string name = v->getNameAsString();
  for (int n = 1; local_names_.count(name) || k_.names.count(name) || is_reserved(name); ++n)
    name = fmt::format("{}_{}", v->getNameAsString(), n);
  auto l = std::make_shared<LocalVar>();
  l->name = name;
  l->type_name = "auto";
  l->def = param(*text, Type::Int); // (printed only: its members are read by name)
  l->id = next_local_id_++;
  l->kernel_level = true;
  l->opaque = true;
  local_names_.insert(name);
  k_.kernel_locals.push_back(l);
  object_locals_[v] = name;
  return true;
}

std::optional<Binding> Lowerer::class_argument(const ParmVarDecl* pd, const clang::Expr* arg,
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
      return lambda_binding(le, pd->getNameAsString());
    if (!isa<DeclRefExpr>(a))
      return functor_binding(a, rd);
    if (const auto* r = dyn_cast<DeclRefExpr>(a))
      if (const auto* v = dyn_cast<VarDecl>(r->getDecl())) {
        auto it = env_.find(v);
        if (it != env_.end() && it->second.kind == Binding::Lambda)
          return it->second;
      }
    fail(arg->getBeginLoc(), fmt::format("argument for parameter '{}' of helper '{}' must be a "
                                         "lambda expression or a functor, or a local holding one",
                                         pd->getNameAsString(), helper->getNameAsString()),
         "dpgen-lambda");
  }
  if (pt->isReferenceType() && !pt.getNonReferenceType().isConstQualified() &&
      !is_view_class(rd))
    return std::nullopt; // (an out-parameter: not a class the kernel can pass)
  if (is_view_class(rd)) {
    const Binding* b = bound(a);
    if (!b || b->kind != Binding::ArrayParam || !b->param->view)
      fail(arg->getBeginLoc(), fmt::format("argument for view parameter '{}' of helper '{}' "
                                           "must be a view parameter of the kernel",
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
    fail(arg->getBeginLoc(), fmt::format("argument for parameter '{}' of helper '{}' (of class "
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
std::optional<std::string> Lowerer::materialize(const clang::Expr* e, const CXXRecordDecl* rd) {
  const auto* c = dyn_cast<CXXConstructExpr>(e);
  if (!c || !loops_.empty() || rd->isInStdNamespace() || !rd->hasDefinition())
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
    if (!scalar_type(a->getType()))
      return std::nullopt;
    ExprP v = expr(a);
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
    if (sm_.getFileID(sm_.getExpansionLoc(r->getLocation())) == sm_.getMainFileID()) {
      if (!r->isEmpty() || isa<ClassTemplateSpecializationDecl>(r) ||
          !r->getDeclContext()->getRedeclContext()->isFileContext())
        return false;
      std::string decl = fmt::format("struct {};", r->getNameAsString());
      for (const DeclContext* dc = r->getDeclContext(); dc; dc = dc->getParent())
        if (const auto* ns = dyn_cast<NamespaceDecl>(dc))
          decl = fmt::format("namespace {} {{ {} }}", ns->getNameAsString(), decl);
      if (std::find(k_.declarations.begin(), k_.declarations.end(), decl) ==
          k_.declarations.end())
        k_.declarations.push_back(decl);
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
  for (int n = 1; local_names_.count(name) || k_.names.count(name); ++n)
    name = fmt::format("dpgen_object_{}", n);
  auto l = std::make_shared<LocalVar>();
  l->name = name;
  l->type_name = "auto";
  l->def = param(fmt::format("{}({})", spelled(e->getType()), *args), Type::Int);
  l->id = next_local_id_++;
  l->kernel_level = true;
  l->opaque = true;
  local_names_.insert(name);
  k_.kernel_locals.push_back(l);
  return name;
}

const Binding* Lowerer::bound(const clang::Expr* e) const {
  e = e->IgnoreParenImpCasts();
  if (const auto* r = dyn_cast<DeclRefExpr>(e)) {
    const auto* v = dyn_cast<VarDecl>(r->getDecl());
    if (!v)
      return nullptr;
    if (poisoned_.count(v))
      throw Rejected{};
    auto it = env_.find(v);
    return it == env_.end() ? nullptr : &it->second;
  }
  const auto* m = dyn_cast<MemberExpr>(e);
  const auto* f = m ? dyn_cast<FieldDecl>(m->getMemberDecl()) : nullptr;
  if (!f || !isa<CXXThisExpr>(m->getBase()->IgnoreParenImpCasts()))
    return nullptr;
  if (poisoned_.count(f))
    throw Rejected{};
  auto it = fields_.find(f);
  return it == fields_.end() ? nullptr : &it->second;
}

std::set<const FieldDecl*> Lowerer::used_fields() const {
  std::set<const FieldDecl*> out;
  std::set<const FunctionDecl*> seen;
  std::function<void(const Stmt*)> walk = [&](const Stmt* s) {
    if (!s)
      return;
    if (const auto* mc = dyn_cast<CXXMemberCallExpr>(s)) // a method on this: its body too
      if (const CXXMethodDecl* md = mc->getMethodDecl();
          md && md->getParent() == self_class_ && md->hasBody() &&
          isa<CXXThisExpr>(mc->getImplicitObjectArgument()->IgnoreParenImpCasts()) &&
          seen.insert(md).second)
        walk(md->getBody());
    if (const auto* m = dyn_cast<MemberExpr>(s))
      if (const auto* f = dyn_cast<FieldDecl>(m->getMemberDecl());
          f && f->getParent() == self_class_ &&
          isa<CXXThisExpr>(m->getBase()->IgnoreParenImpCasts()))
        out.insert(f);
    if (const auto* le = dyn_cast<LambdaExpr>(s))
      walk(le->getBody());
    for (const Stmt* c : s->children())
      walk(c);
  };
  walk(fn_->getBody());
  // the class's call operators (a functor run by a parallel-for on *this)
  for (const CXXMethodDecl* m : self_class_->methods())
    if (m->isOverloadedOperator() && m->getOverloadedOperator() == OO_Call && m->hasBody())
      walk(m->getBody());
  return out;
}

bool Lowerer::is_functor_class(const CXXRecordDecl* rd) const {
  if (!rd || rd->isLambda() || !rd->hasDefinition() || rd->isInStdNamespace())
    return false;
  for (const NamedDecl* d : call_operators(rd, ctx_)) {
    const FunctionDecl* f = d->getAsFunction();
    if (f && f->getReturnType()->isVoidType())
      return true;
  }
  return false;
}

Binding Lowerer::functor_binding(const clang::Expr* init, const CXXRecordDecl* rd) {
  const clang::Expr* e = made_object(init);
  Binding b;
  b.kind = Binding::Lambda;
  b.functor = true;
  b.closure = rd;
  if (const auto* u = dyn_cast<UnaryOperator>(e);
      u && u->getOpcode() == UO_Deref && isa<CXXThisExpr>(u->getSubExpr()->IgnoreParenImpCasts())) {
    if (rd != self_class_)
      fail(init->getBeginLoc(), "'*this' of a class other than the member kernel's");
    return b; // the member kernel's own object: its members are fields_
  }
  const auto* il = dyn_cast<InitListExpr>(e);
  if (!il)
    fail(init->getBeginLoc(), fmt::format("functor '{}' must be made here from the kernel's "
                                          "views, arrays and values ({}{{...}}, members in "
                                          "order), or be '*this' of a member kernel",
                                          rd->getNameAsString(), rd->getNameAsString()),
         "dpgen-lambda");
  b.fields = std::make_shared<std::map<const FieldDecl*, Binding>>();
  unsigned i = 0;
  for (const FieldDecl* f : rd->fields()) {
    if (i >= il->getNumInits())
      fail(il->getBeginLoc(), fmt::format("functor '{}': member '{}' has no value here",
                                          rd->getNameAsString(), f->getNameAsString()),
           "dpgen-lambda");
    const clang::Expr* v = il->getInit(i++);
    QualType t = f->getType();
    const CXXRecordDecl* frd = t->getAsCXXRecordDecl();
    if (t->isPointerType() || (frd && is_view_class(frd))) {
      // (a view member is copied, or converted to const elements, from the kernel's)
      const clang::Expr* src = v->IgnoreImplicit()->IgnoreParenImpCasts();
      if (const auto* cc = dyn_cast<CXXConstructExpr>(src); cc && cc->getNumArgs() == 1)
        src = cc->getArg(0);
      const Binding* a = bound(src);
      if (!a || a->kind != Binding::ArrayParam)
        fail(v->getBeginLoc(), fmt::format("member '{}' of functor '{}' must be made from an "
                                           "array or view parameter of the kernel",
                                           f->getNameAsString(), rd->getNameAsString()),
             "dpgen-lambda");
      (*b.fields)[f] = *a;
      continue;
    }
    auto st = scalar_type(t);
    if (!st)
      fail(v->getBeginLoc(), fmt::format("member '{}' of functor '{}' has type '{}', outside the "
                                         "kernel subset (views, arrays and numbers)",
                                         f->getNameAsString(), rd->getNameAsString(),
                                         t.getAsString()),
           "dpgen-lambda");
    Binding value;
    value.kind = Binding::Value;
    value.value = cast(expr(v), *st);
    (*b.fields)[f] = value;
  }
  return b;
}

} // namespace dpgen::lowering
