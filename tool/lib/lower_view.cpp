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

namespace {


// `t` with const dropped at every level (`const double* const*` -> `double**`).
QualType without_const(QualType t, ASTContext& ctx) {
  t = t.getCanonicalType();
  if (t->isPointerType())
    return ctx.getPointerType(without_const(t->getPointeeType(), ctx));
  return t.getUnqualifiedType();
}

} // namespace

bool Views::is_view_class(const CXXRecordDecl* rd) const {
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
  for (const NamedDecl* d : call_operators(rd, L.ctx_)) {
    const FunctionDecl* f = d->getAsFunction();
    if (f && !f->getReturnType()->isVoidType())
      return true;
  }
  return false;
}

std::string Views::include_for(const TagDecl* rd, SourceLocation use, const std::string& what) {
  const Decl* d = rd;
  if (const auto* s = dyn_cast<ClassTemplateSpecializationDecl>(rd))
    d = s->getSpecializedTemplate();
  const char* kind = isa<EnumDecl>(rd) ? "an enum" : "a class";
  FileID fid = L.sm_.getFileID(L.sm_.getExpansionLoc(d->getLocation()));
  const FileID main = L.sm_.getMainFileID();
  if (fid == main)
    L.fail(use,
           fmt::format("{} has {} defined in the kernel file ('{}'): the generated "
                       "files must see its definition, so move it to a header the kernel "
                       "file includes",
                       what, kind, rd->getQualifiedNameAsString()),
           "dpgen-signature");
  SourceLocation inc;
  for (int depth = 0; depth < 256; ++depth) {
    inc = L.sm_.getIncludeLoc(fid);
    if (inc.isInvalid())
      break;
    FileID parent = L.sm_.getFileID(L.sm_.getExpansionLoc(inc));
    if (parent == main)
      break;
    fid = parent;
  }
  if (inc.isInvalid() || L.sm_.getFileID(L.sm_.getExpansionLoc(inc)) != main)
    L.fail(use,
           fmt::format("{}: dpgen cannot find the #include of the kernel file that declares "
                       "'{}'",
                       what, rd->getQualifiedNameAsString()),
           "dpgen-signature");
  // The whole line of the directive, as written.
  auto [file, offset] = L.sm_.getDecomposedLoc(L.sm_.getExpansionLoc(inc));
  llvm::StringRef buffer = L.sm_.getBufferData(file);
  size_t begin = buffer.rfind('\n', offset);
  begin = begin == llvm::StringRef::npos ? 0 : begin + 1;
  size_t end = buffer.find('\n', offset);
  std::string line = buffer.slice(begin, end).trim().str();
  if (line.empty() || line[0] != '#')
    L.fail(use,
           fmt::format("{}: the directive that includes '{}' is not a plain #include "
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
std::string Views::without_element_const(QualType t, bool& changed) const {
  t = t.getCanonicalType();
  QualType m = without_const(t, L.ctx_);
  if (m != t)
    changed = true;
  const auto* spec = dyn_cast_or_null<ClassTemplateSpecializationDecl>(m->getAsCXXRecordDecl());
  if (!spec)
    return Lowerer::spelled(m);
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
    return Lowerer::with_unsigned_suffix(os.str());
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

void Views::mutable_view_type(const DeclaratorDecl* p, Param& out) const {
  QualType q = p->getType();
  bool ref = q->isReferenceType();
  QualType cls = q.getNonReferenceType();
  bool changed = false;
  out.view_reference = ref;
  out.view_class = without_element_const(cls.getUnqualifiedType(), changed);
  out.view_pass = Param::ViewPass::Value;
  if (!ref)
    return;
  // Taken by const reference where the view is shallow (its const operator()
  // returns a non-const element: Array4<double>, View<double**>) or its
  // elements' constness was in its template arguments; else (a deep-const
  // class, AthenaArray) by non-const reference.
  bool shallow = changed;
  for (const NamedDecl* d : call_operators(cls->getAsCXXRecordDecl(), L.ctx_)) {
    const auto* m = dyn_cast_or_null<CXXMethodDecl>(d->getAsFunction());
    if (m && m->isConst() && m->getReturnType()->isLValueReferenceType() &&
        !m->getReturnType().getNonReferenceType().isConstQualified())
      shallow = true;
  }
  out.view_pass = shallow ? Param::ViewPass::ConstRef : Param::ViewPass::Ref;
}

void Views::view_param(const DeclaratorDecl* p, const std::string& ann, Param& out) {
  const CXXRecordDecl* rd = p->getType().getNonReferenceType()->getAsCXXRecordDecl();
  if (ann == "dpgen.inout")
    L.fail(p->getLocation(), fmt::format("DPGEN_INOUT view '{}': pass its old values and its new "
                                       "ones as two views (DPGEN_IN and DPGEN_OUT)",
                                       out.name),
         "dpgen-signature");
  if (p->getType()->isReferenceType() && !p->getType().getNonReferenceType().isConstQualified() &&
      ann.empty())
    L.fail(p->getLocation(), fmt::format("unmarked view '{}' is a non-const reference: mark it "
                                       "DPGEN_OUT, or make it const",
                                       out.name),
         "dpgen-signature");
  // The element type: what operator() returns, without reference and const.
  std::optional<Type> et;
  std::string elem_name;
  for (const NamedDecl* d : call_operators(rd, L.ctx_)) {
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
    et = L.scalar_type(r);
    elem_name = Lowerer::spelled(r);
    if (et)
      break;
  }
  if (!et || *et == Type::Bool)
    L.fail(p->getLocation(), fmt::format("view '{}' of class '{}': its operator() must return "
                                       "float, double or an integer type (by value or by "
                                       "reference)",
                                       out.name, rd->getQualifiedNameAsString()),
         "dpgen-signature");
  if ((ann == "dpgen.in" || ann == "dpgen.out") && !is_real(*et))
    L.fail(p->getLocation(), fmt::format("{} view '{}' must hold float or double",
                                       ann == "dpgen.in" ? "DPGEN_IN" : "DPGEN_OUT", out.name),
         "dpgen-signature");
  out.elem = *et;
  out.elem_name = elem_name;
  out.kind = ann == "dpgen.in"    ? ParamKind::In
             : ann == "dpgen.out" ? ParamKind::Out
                                  : ParamKind::ConstArray;
  out.view = true;
  out.view_rank = 0; // from its first element access (view_element)
  out.view_type = Lowerer::spelled(p->getType(), /*keep_const=*/true);
  mutable_view_type(p, out);
  out.tag_declaration = include_for(rd, p->getLocation(), fmt::format("view '{}'", out.name));
}


ExprP Views::level_symbol(const Param& p, int level) {
  auto& table = level == 1 ? L.row_lengths_ : level == 2 ? L.plane_lengths_ : L.cube_lengths_;
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
  ExprP s = L.opaque_symbol(name, value);
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
void Views::check_layout(const FunctionDecl* op, const Param& p, SourceLocation use) {
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
    L.fail(use, fmt::format("view '{}': the body of {}::operator() is not 'return ptr[index];' "
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
      e->printPretty(os, nullptr, PrintingPolicy(L.ctx_.getLangOpts()));
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
    L.fail(use, fmt::format("view '{}': {}::operator() does not map distinct indices to distinct "
                          "elements as a layout does: {}",
                          p.name, rd ? rd->getQualifiedNameAsString() : "?", why),
         "dpgen-signature");
  }
  layouts_ok_.insert(op);
}

auto Views::view_element(const CXXOperatorCallExpr* oc) -> std::optional<Access> {
  if (oc->getOperator() != OO_Call && oc->getOperator() != OO_Subscript)
    return std::nullopt;
  const Binding* b = L.bound(oc->getArg(0)); // (throws for a poisoned one)
  if (!b || b->kind != Binding::ArrayParam || !b->param->view)
    return std::nullopt;
  const Param* p = b->param;
  const FunctionDecl* op = oc->getDirectCallee();
  if (!op)
    L.fail(oc->getBeginLoc(), fmt::format("view '{}': dpgen cannot see which operator() this is",
                                        p->name));
  const unsigned rank = oc->getNumArgs() - 1;
  if (oc->getOperator() == OO_Subscript)
    L.fail(oc->getBeginLoc(), fmt::format("view '{}' is indexed with []: index it with its "
                                        "operator(), {}(i)",
                                        p->name, p->name));
  if (rank < 1 || rank > 4)
    L.fail(oc->getBeginLoc(), fmt::format("view '{}' is indexed with {} indices: dpgen takes "
                                        "views of rank 1 to 4",
                                        p->name, rank));
  if (p->view_rank != 0 && p->view_rank != static_cast<int>(rank))
    L.fail(oc->getBeginLoc(), fmt::format("view '{}' is indexed with {} indices here and {} "
                                        "elsewhere: use one operator() per view",
                                        p->name, rank, p->view_rank));
  check_layout(op, *p, oc->getBeginLoc());
  if (p->view_rank == 0) // L.k_.params owns it: the rank is known from here on
    const_cast<Param*>(p)->view_rank = static_cast<int>(rank);
  std::vector<ExprP> idx;
  bool piecewise = false;
  for (unsigned d = 1; d <= rank; ++d) {
    ExprP x = L.exprs_.expr(oc->getArg(d));
    if (x->type != Type::Int)
      L.fail(oc->getArg(d)->getBeginLoc(), "array index must be an integer");
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
        L.fail(oc->getArg(d)->getBeginLoc(),
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
ExprP Views::view_flat(const Param& p, const std::vector<ExprP>& idx) {
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
ExprP Views::piecewise_read(const Access& a, size_t d, std::vector<ExprP> idx, SourcePos at,
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


} // namespace dpgen::lowering
