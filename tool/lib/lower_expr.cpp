// Lowering, expressions: values, helper calls inlined, array elements,
// casts, names, operators and math calls (lower_expr.hpp).
#include "lower_impl.hpp"

#include <cmath>

namespace dpgen::lowering {

namespace {
// A conversion of a real to an integer type of `bits` bits: to a 64-bit one
// (`static_cast<long>(std::floor(x))`) as spelled, since an int would wrap for values
// past 2^31 that the kernel keeps.
ExprP spelled_cast(const ExprP& e, uint64_t bits, const std::string& spelling) {
  if (e->op != Op::Cast || e->type != Type::Int || bits < 64)
    return e;
  auto w = std::make_shared<dpgen::Expr>(*e);
  w->cast_type = spelling;
  return w;
}

// What a node that only wraps an expression wraps: a temporary, a constant, a template's
// argument (Dir of template <int Dir>), a default argument; null for any other node.
const clang::Expr* wrapped(const clang::Expr* e) {
  if (const auto* m = dyn_cast<MaterializeTemporaryExpr>(e))
    return m->getSubExpr();
  if (const auto* w = dyn_cast<ExprWithCleanups>(e))
    return w->getSubExpr();
  if (const auto* c = dyn_cast<ConstantExpr>(e))
    return c->getSubExpr();
  if (const auto* t = dyn_cast<SubstNonTypeTemplateParmExpr>(e))
    return t->getReplacement();
  if (const auto* d = dyn_cast<CXXDefaultArgExpr>(e)) // an argument left to its default
    return d->getExpr();
  return nullptr;
}

// An integer explicitly widened to 64 bits, `(long)(e)`, kept as spelled; to an unsigned
// type (`std::size_t(n)`, whose value check_unsigned_result kept >= 0) as std::ptrdiff_t, the
// generated code's integers, which it then compares with without a sign warning.
ExprP widened(const ExprP& e, std::string spelling, bool to_unsigned) {
  auto w = std::make_shared<dpgen::Expr>();
  w->op = Op::Cast;
  w->type = Type::Int;
  w->ops = {e};
  w->cast_type = to_unsigned ? "std::ptrdiff_t" : std::move(spelling);
  return w;
}

// The operands of a call: its arguments, or for `std::min({a, b, c})` and `std::max({...})`
// the elements of its one initializer list (`list` set).
std::vector<const clang::Expr*> operands(const CallExpr* c, const std::string& fn, bool& list) {
  std::vector<const clang::Expr*> elements;
  if (fn == "min" || fn == "max")
    elements = ReductionForms::list_elements(c);
  list = !elements.empty();
  if (list)
    return elements;
  return {c->arg_begin(), c->arg_end()};
}

// The comparator of `std::max(a, b, comp)`, `std::min({...}, comp)` or `std::clamp(v, lo, hi,
// comp)` (a function object, a lambda or a function); null for none.
const clang::Expr* comparator(const CallExpr* c, const FunctionDecl* f) {
  const std::string fn = f->getNameAsString();
  const unsigned plain = fn == "clamp" ? 3 : (fn == "min" || fn == "max") ? 1 : 0;
  if (!f->isInStdNamespace() || plain == 0 || c->getNumArgs() <= plain)
    return nullptr;
  const clang::Expr* last = c->getArg(c->getNumArgs() - 1);
  const QualType t = last->getType();
  return t->isRecordType() || t->isFunctionPointerType() || t->isFunctionType() ? last : nullptr;
}

// `w.size()` of a DPGEN_OUT container.
std::string output_size_message(const std::string& w) {
  return fmt::format("the size of output '{}' is outside the kernel subset: its adjoint receives "
                     "only the seed '{}_adj', whose size it cannot check against '{}'; take the "
                     "size from an input (u.size()) or a parameter",
                     w, w, w);
}

std::string comparator_message(const FunctionDecl* f) {
  return fmt::format("'{}' with a comparator is outside the kernel subset: dpgen differentiates "
                     "std::{} by the order of its values; write the choice out as a conditional "
                     "on what the comparator compares",
                     f->getQualifiedNameAsString(), f->getNameAsString());
}
// A member call outside the subset: `u[j].size()` of a row (row_size), or any other.
std::string member_call_message(bool row_size) {
  return row_size ? "the length of a row (u[j].size()) is outside the kernel subset: dpgen "
                    "assumes each row holds the columns the kernel touches; pass the number of "
                    "columns as a parameter"
                  : "member call is outside the kernel subset (of a std::vector parameter or "
                    "local work array, the kernel may call size())";
}

} // namespace

ExprP Expressions::cond(const clang::Expr* e) {
  ExprP c = expr(e);
  if (c->type != Type::Bool)
    c = binary(Op::Ne, c, c->type == Type::Int ? int_const(0) : real_const(0, c->type, ""));
  return c;
}

// u[j][i] of a `std::vector<std::vector<T>>&` parameter (`oc` the column's
// operator[], `row` the row's): the flat j * R + i of row pointers.
auto Expressions::nested_element(const CXXOperatorCallExpr* oc, const CXXOperatorCallExpr* row)
    -> Access {
  const clang::Expr* base = row->getArg(0)->IgnoreParenImpCasts();
  const Param* p = isa<DeclRefExpr>(base) ? array_base(base) : nullptr;
  if (!p || !p->nested)
    L.fail(base->getBeginLoc(), "operator[] must index a std::vector parameter of the kernel "
                                "(u[i], or u[j][i] of a std::vector<std::vector<T>>)");
  ExprP j = expr(row->getArg(1)), i = expr(oc->getArg(1));
  if (j->type != Type::Int || i->type != Type::Int)
    L.fail(oc->getBeginLoc(), "array index must be an integer");
  if (!to_poly(j) || !to_poly(i))
    L.fail(oc->getBeginLoc(), fmt::format("'{}' is indexed at a data-dependent row or column; "
                                          "dpgen needs both indices of {}[j][i] affine in the "
                                          "loop counters and sizes (pass a flat array for "
                                          "interpolation)",
                                          p->name, p->name));
  return Access{p, binary(Op::Add, binary(Op::Mul, j, L.row_lengths_.at(p->name)), i)};
}

auto Expressions::element(const clang::Expr* e) -> std::optional<Access> {
  e = e->IgnoreParens();
  if (const auto* oc = dyn_cast<CXXOperatorCallExpr>(e)) // v(k, j, i) of a view, U(i, j) of an
    if (auto a = L.views_.view_element(oc); a || (a = L.inl_.accessor_element(oc))) // accessor
      return a;
  if (const Param* p = L.scalar_ref_param(e)) // `mass` of `DPGEN_OUT double& mass`: mass[0]
    return Access{p, int_const(0)};
  if (const auto* u = dyn_cast<UnaryOperator>(e); u && u->getOpcode() == UO_Deref) {
    const clang::Expr* base = u->getSubExpr()->IgnoreParenImpCasts();
    if (auto moved = L.ptrs_.pointer_into(base); moved && moved->offset) // *row, *(row + 1)
      return Access{moved->param, *moved->offset};                       // (lower_pointer.hpp)
    if (isa<DeclRefExpr>(base)) {
      const Param* p = array_base(base);
      if (p->row_pointers)
        L.fail(u->getOperatorLoc(), fmt::format("'*{}' of row-pointer array '{}' is a row; index "
                                                "its elements as {}[j][i]",
                                                p->name, p->name, p->name));
      if (L.bufs_.is_buffer(p->name))
        return Access{p, L.bufs_.buffer_index(p, int_const(0), e)};
      return Access{p, int_const(0)};
    }
    L.fail(u->getOperatorLoc(), "pointer arithmetic is outside the kernel subset; index the "
                                "parameter directly: a[i + 1]");
  }
  if (const auto* oc = dyn_cast<CXXOperatorCallExpr>(e);
      oc && oc->getOperator() == OO_Subscript && oc->getNumArgs() == 2 &&
      !L.inl_.made_accessor(oc)) { // (an accessor's operator[] returning a value: a call)
    // v[i] of a std::vector parameter
    const clang::Expr* base = oc->getArg(0)->IgnoreParenImpCasts();
    if (const auto* row = dyn_cast<CXXOperatorCallExpr>(base);
        row && row->getOperator() == OO_Subscript && row->getNumArgs() == 2)
      return nested_element(oc, row);
    if (!isa<DeclRefExpr>(base))
      L.fail(base->getBeginLoc(), "operator[] must index a std::vector parameter of the kernel");
    ExprP offset; // (of a row `const auto& up = u[j - 1];`: up[i])
    const Param* p = array_base(base, &offset);
    ExprP idx = expr(oc->getArg(1));
    if (idx->type != Type::Int)
      L.fail(oc->getArg(1)->getBeginLoc(), "array index must be an integer");
    if (offset)
      return L.ptrs_.row_element(p, offset, idx, e);
    if (L.bufs_.is_buffer(p->name)) // t[i] of a std::array line buffer
      return Access{p, L.bufs_.buffer_index(p, idx, e)};
    return Access{p, idx};
  }
  const auto* sub = dyn_cast<ArraySubscriptExpr>(e);
  if (!sub)
    return std::nullopt;
  ExprP idx = expr(sub->getIdx());
  if (idx->type != Type::Int)
    L.fail(sub->getIdx()->getBeginLoc(), "array index must be an integer");
  const clang::Expr* base = sub->getBase()->IgnoreParenImpCasts();
  if (const auto* row = dyn_cast<ArraySubscriptExpr>(base);
      row && row->getType().getCanonicalType()->isPointerType()) {
    // a[j][i] of row pointers `double** a`: the flat j * R + i (R the row
    // symbol); a[k][j][i] of `double*** a`: k * P + j * R + i. The indices
    // must be affine: the printer writes them back as [k][j][i].
    std::vector<const clang::Expr*> outer = {row->getIdx()}; // j, then k
    const clang::Expr* rb = row->getBase()->IgnoreParenImpCasts();
    if (const auto* plane = dyn_cast<ArraySubscriptExpr>(rb);
        plane && plane->getType().getCanonicalType()->isPointerType()) {
      outer.push_back(plane->getIdx());
      rb = plane->getBase()->IgnoreParenImpCasts();
    }
    const Param* p = isa<DeclRefExpr>(rb) ? array_base(rb) : nullptr;
    if (!p || !p->row_pointers)
      L.fail(base->getBeginLoc(), "rows reached through a pointer must come straight from a "
                                  "'double**' or 'double***' kernel parameter: a[j][i], "
                                  "a[k][j][i]");
    if (outer.size() != (p->plane_pointers ? 2u : 1u))
      L.fail(sub->getBeginLoc(),
             fmt::format("'{}' is indexed with {} subscripts; index its elements as {}", p->name,
                         outer.size() + 1, p->plane_pointers ? "a[k][j][i]" : "a[j][i]"));
    ExprP flat = idx;
    std::vector<ExprP> symbols = {L.row_lengths_.at(p->name)};
    if (p->plane_pointers)
      symbols.push_back(L.plane_lengths_.at(p->name));
    bool affine = to_poly(idx).has_value();
    for (size_t d = 0; d < outer.size(); ++d) {
      ExprP x = expr(outer[d]);
      if (x->type != Type::Int)
        L.fail(outer[d]->getBeginLoc(), "array index must be an integer");
      affine = affine && to_poly(x).has_value();
      flat = binary(Op::Add, binary(Op::Mul, x, symbols[d]), flat);
    }
    if (!affine)
      L.fail(sub->getBeginLoc(), fmt::format("row-pointer array '{}' is indexed at a "
                                             "data-dependent row or column; dpgen needs every "
                                             "index of a[j][i] affine in the loop counters "
                                             "and sizes for row pointers (pass a flat array for "
                                             "interpolation)",
                                             p->name));
    return Access{p, flat};
  }
  if (const auto* row = dyn_cast<ArraySubscriptExpr>(base)) {
    // a[j][i]: row j of an array of rows, each `extent` elements long.
    QualType rt = row->getType().getCanonicalType();
    const clang::ArrayType* at = L.ctx_.getAsArrayType(rt);
    if (!at)
      L.fail(base->getBeginLoc(),
             "rows reached through a pointer ('double** a', a[j][i]) are outside the kernel "
             "subset: dpgen cannot prove rows do not overlap; pass the array as 'double (*a)[N]', "
             "'double a[][N]' or a flat pointer with a[j * N + i]");
    ExprP extent;
    if (const auto* c = dyn_cast<ConstantArrayType>(at))
      extent = int_const(static_cast<long long>(c->getSize().getZExtValue()));
    else if (const auto* v = dyn_cast<VariableArrayType>(at)) {
      // (a pointer's extents as evaluated at its declaration, lower_buffer.cpp)
      extent = L.bufs_.vla_size(v->getSizeExpr());
      if (!extent)
        extent = expr(v->getSizeExpr());
    } else
      L.fail(base->getBeginLoc(), "this array type is outside the kernel subset");
    auto inner = element(row);
    ExprP flat = binary(Op::Add, binary(Op::Mul, inner->index, extent), idx);
    // (the flat index of a[j][i] is computed by the compiler in 64 bits)
    return Access{inner->param, flat};
  }
  ExprP offset;
  const Param* p = array_base(base, &offset);
  if (offset) // row[i] of a pointer local: the parameter's element offset + i
    return Access{p, binary(Op::Add, offset, idx)}; // (an offset 0 folds away)
  if (p->row_pointers)
    L.fail(sub->getBeginLoc(), fmt::format("row '{}[...]' of row-pointer array '{}' is used as a "
                                           "value; index its elements as {}[j][i]",
                                           p->name, p->name, p->name));
  if (L.bufs_.is_buffer(p->name)) // tmp[i] of a line buffer (lower_buffer.cpp)
    return Access{p, L.bufs_.buffer_index(p, idx, e)};
  L.ints_.check_index_width(sub->getIdx(), idx, p->name);
  return Access{p, idx};
}

const Param* Expressions::array_base(const clang::Expr* base, ExprP* offset) {
  // (`offset`: where given, a pointer local's element offset; lower_pointer.hpp)
  const auto param_of = [&](const Binding& b) { return L.ptrs_.param_of(b, base, offset); };
  if (isa<MemberExpr>(base->IgnoreParenImpCasts())) // `u_[i]` of a member kernel's array
    if (const Binding* b = L.bound(base); b && b->kind == Binding::ArrayParam)
      return param_of(*b);
  const auto* ref = dyn_cast<DeclRefExpr>(base);
  if (!ref) {
    if (isa<BinaryOperator>(base) || isa<UnaryOperator>(base))
      L.fail(base->getBeginLoc(), isa<UnaryOperator>(base) // (`(*a)[j]`, `(&x)[0]`)
                                      ? "pointer arithmetic is outside the kernel subset; index "
                                        "the parameter directly: a[i + 1]"
                                      : "pointer arithmetic is outside the kernel subset; index "
                                        "the array (a[i + 1]) or a pointer named first (p = a + "
                                        "1; p[i])");
    L.fail(base->getBeginLoc(), "array access must index a pointer parameter of the kernel");
  }
  L.ptrs_.check_usable(dyn_cast<VarDecl>(ref->getDecl()), base->getBeginLoc());
  auto it = L.env_.find(dyn_cast<VarDecl>(ref->getDecl()));
  if (it == L.env_.end() || it->second.kind != Binding::ArrayParam) {
    if (const auto* v = dyn_cast<VarDecl>(ref->getDecl()); v && v->hasGlobalStorage())
      L.fail(base->getBeginLoc(),
             fmt::format("'{}' is global state, outside the kernel subset", v->getNameAsString()));
    L.fail(base->getBeginLoc(), "array access must index a pointer parameter of the kernel");
  }
  return param_of(it->second);
}

ExprP Expressions::expr(const clang::Expr* e) {
  e = e->IgnoreParens();
  if (isa<MemberExpr>(e->IgnoreParenImpCasts())) { // `nu_` of a member kernel or a functor
    const Binding* b = L.bound(e);
    if (b && b->kind == Binding::ScalarParam && !b->param->object)
      return L.scalar_param(b->param->name, b->param->elem);
    if (b && b->kind == Binding::Value && b->value)
      return *b->value;
  }
  if (auto v = L.objects_.object_value(e)) // bx.smallEnd(0), u.extent(1), lo.x
    return *v;
  if (const auto* c = dyn_cast<ImplicitCastExpr>(e))
    return cast_expr(c, c->getSubExpr());
  if (const auto* c = dyn_cast<ExplicitCastExpr>(e))
    return cast_expr(c, c->getSubExpr());
  if (const clang::Expr* inner = wrapped(e))
    return expr(inner);
  clang::Expr::EvalResult n; // 3000000000u (positive), sizeof(w) / sizeof(w[0]): the value
  if (isa<IntegerLiteral, UnaryExprOrTypeTraitExpr>(e) && e->EvaluateAsInt(n, L.ctx_))
    return int_const(L.ints_.constant(n.Val.getInt(), e->getBeginLoc()));
  if (const auto* l = dyn_cast<FloatingLiteral>(e)) {
    Type t = L.type_of(e);
    // The literal as written; from a macro (`#define C 0.5` in a header the
    // generated code does not include), its spelling in the definition.
    SourceLocation at = l->getLocation();
    std::string spelled_as =
        at.isMacroID()
            ? Lexer::getSourceText(CharSourceRange::getTokenRange(L.sm_.getSpellingLoc(at)), L.sm_,
                                   L.ctx_.getLangOpts())
                  .str()
            : L.text(l);
    return real_const(l->getValueAsApproximateDouble(), t, spelled_as);
  }
  if (const auto* l = dyn_cast<CXXBoolLiteralExpr>(e))
    return binary(Op::Eq, int_const(l->getValue() ? 1 : 0), int_const(1));
  if (const auto* r = dyn_cast<DeclRefExpr>(e); r && !L.scalar_ref_param(r))
    return decl_ref(r);
  if (const VarDecl* v = L.stores_.deref_local(e)) {
    const Binding& b = L.env_[v];
    if (!b.value)
      L.fail(e->getBeginLoc(), L.unset_message(v, "may be used before it has a value"));
    return *b.value;
  }
  if (auto le = L.stmts_.local_element(e)) {
    const std::optional<ExprP>& v = L.env_[le->first].elems[le->second];
    if (!v)
      L.fail(e->getBeginLoc(), L.unset_message(le->first, "may be used before it has a value"));
    return *v;
  }
  if (auto acc = element(e)) {
    const Param* p = acc->param;
    if (!acc->dims.empty()) { // a view at a periodic wrap
      if (p->kind == ParamKind::Out)
        L.fail(e->getBeginLoc(), fmt::format("output view '{}' is read back at a choice of "
                                             "positions (a periodic wrap); read the input it "
                                             "came from",
                                             p->name));
      return L.views_.piecewise_read(*acc, 0, acc->dims, L.pos(e->getBeginLoc()), L.text(e));
    }
    if (p->kind == ParamKind::Out) {
      const auto from = L.bufs_.is_buffer(p->name) ? L.bufs_.check_buffer_read(p, acc->index, e)
                                                   : LineBuffers::BufferRead{}; // (its rules)
      if (from.value && !from.in) // a std::vector's value: no store of the row wrote there
        return from.value;
      // An output read back in the iteration that stored it: that value.
      L.order_after_later_stores(p->name);
      auto nit = L.nest_index_.find(L.cur_key());
      Store* st = nit == L.nest_index_.end()
                      ? nullptr
                      : L.stores_.visible_store(L.k_.nests[nit->second], p->name, acc->index);
      // An output an earlier loop nest wrote (a work array: fluxes, then
      // the update from them): an intermediate, read like an input; the
      // adjoint recomputes it and runs the nests backwards.
      if (!st && L.stores_.written_by_other_nest(p->name)) {
        if (L.loops_.empty() && !L.path_reads_ok_)
          L.acc_.kernel_level_work_reads.push_back({p->name, L.pos(e->getBeginLoc())});
        ExprP r = read(p->name, acc->index, p->elem, L.pos(e->getBeginLoc()), shape_of(*p));
        std::const_pointer_cast<Expr>(r)->source = L.text(e);
        L.k_.intermediates.insert(p->name);
        L.acc_.work_reads.push_back({p->name, L.cur_key(), L.next_store_seq_, acc->index, L.path_,
                                     L.pos(e->getBeginLoc())});
        return from.value ? select(from.in, r, from.value) : r;
      }
      if (!st || st->accumulate)
        L.fail(e->getBeginLoc(),
               fmt::format("reads output '{}'{}: the adjoint has only the output's seed, not its "
                           "values; read the input it came from, or store it earlier in the same "
                           "iteration and read it back at the same index",
                           p->name, st ? " after '+=' (its previous contents)" : ""));
      return L.stores_.shared_value(*st, p->name);
    }
    if (p->inout)
      return L.stores_.inout_value(p, acc->index, e->getBeginLoc(), e);
    // an element of a constant integer table (`constexpr int cx[9] = {...}`)
    // at a constant index (an unrolled counter): its value
    if (p->global && p->kind == ParamKind::ConstArray && p->elem == Type::Int &&
        L.global_decls_.count(p->name))
      if (auto i = int_value(acc->index))
        if (const APValue* val = L.global_decls_.at(p->name)->evaluateValue();
            val && val->isArray() && *i >= 0 && *i < (long long)val->getArraySize()) {
          const APValue& el = *i < (long long)val->getArrayInitializedElts()
                                  ? val->getArrayInitializedElt(unsigned(*i))
                                  : val->getArrayFiller();
          if (el.isInt())
            return int_const(L.ints_.constant(el.getInt(), e->getBeginLoc()));
        }
    ExprP r = read(p->name, acc->index, p->elem, L.pos(e->getBeginLoc()), shape_of(*p));
    std::const_pointer_cast<Expr>(r)->source = L.text(e); // as written, for remarks
    return r;
  }
  if (const auto* u = dyn_cast<UnaryOperator>(e)) {
    switch (u->getOpcode()) {
    case UO_Minus: {
      ExprP x = expr(u->getSubExpr());
      if (u->getType()->isUnsignedIntegerType())
        L.ints_.check_unsigned_result(unary(Op::Neg, x), u->getOperatorLoc(),
                                      fmt::format("unsigned negation '{}'", L.text(u)), u);
      return unary(Op::Neg, x);
    }
    case UO_Plus:
      return expr(u->getSubExpr());
    case UO_LNot:
      return unary(Op::Not, cond(u->getSubExpr()));
    case UO_Not:
      return unary(Op::BitNot, expr(u->getSubExpr()));
    case UO_Deref: // `*p` of a parameter is an element access (handled above)
    case UO_AddrOf:
      L.fail(u->getOperatorLoc(), "pointer arithmetic is outside the kernel subset; index "
                                  "parameters directly");
    default:
      if (L.for_loops_.running_.inline_steps_.count(u)) // its statement steps it
        return expr(u->getSubExpr());
      L.fail(u->getOperatorLoc(), "increment/decrement inside an expression is outside the "
                                  "kernel subset");
    }
  }
  if (const auto* b = dyn_cast<BinaryOperator>(e))
    return binary_expr(b);
  if (const auto* c = dyn_cast<ConditionalOperator>(e)) {
    ExprP cc = cond(c->getCond());
    Type t = L.type_of(c);
    // (the false arm first: the order in which GCC evaluated the arguments of the select this
    // was before, so that locals keep their names)
    ExprP no = L.guards_.conditional(c->getFalseExpr(), PathCond{cc, false},
                                     [&] { return cast(expr(c->getFalseExpr()), t); });
    ExprP yes = L.guards_.conditional(c->getTrueExpr(), PathCond{cc, true},
                                      [&] { return cast(expr(c->getTrueExpr()), t); });
    return select(cc, yes, no);
  }
  if (const auto* m = dyn_cast<CXXMemberCallExpr>(e)) {
    const auto* obj = dyn_cast<DeclRefExpr>(m->getImplicitObjectArgument()->IgnoreParenImpCasts());
    auto it = obj ? L.env_.find(dyn_cast<VarDecl>(obj->getDecl())) : L.env_.end();
    const CXXMethodDecl* md = m->getMethodDecl();
    if (it != L.env_.end() && it->second.kind == Binding::ArrayParam && !it->second.offset &&
        (!it->second.param->container.empty() || L.bufs_.length_of(it->second.param)) && md &&
        md->getName() == "size" && m->getNumArgs() == 0) {
      if (ExprP length = L.bufs_.length_of(it->second.param)) // a std::vector line buffer's
        return length;
      if (it->second.param->kind == ParamKind::Out) // (its seed's size would stand in for it)
        L.fail(m->getBeginLoc(), output_size_message(it->second.param->name));
      return L.scalar_param(it->second.param->name + "_size", Type::Int);
    }
    // a method of the member kernel's (or the running functor's) object, on the same object:
    // inlined like a helper, reading the same members
    if (L.this_call(m) && md && md->hasBody() && !md->isVirtual())
      return L.inl_.inline_call(m, md);
    const auto* row =
        dyn_cast<CXXOperatorCallExpr>(m->getImplicitObjectArgument()->IgnoreParenImpCasts());
    const bool row_size =
        md && md->getName() == "size" &&
        ((row && row->getOperator() == OO_Subscript) || (it != L.env_.end() && it->second.offset));
    L.fail(e->getExprLoc(), member_call_message(row_size));
  }
  if (const auto* c = dyn_cast<CallExpr>(e))
    return call_expr(c);
  L.fail(e->getExprLoc(), fmt::format("expression '{}' ({}) is outside the kernel subset",
                                      L.text(e), e->getStmtClassName()));
}

ExprP Expressions::cast_expr(const CastExpr* c, const clang::Expr* sub) {
  switch (c->getCastKind()) {
  case CK_LValueToRValue:
  case CK_NoOp:
    return expr(sub);
  case CK_IntegralCast: {
    // An explicit cast that widens to 64 bits is kept, so index arithmetic
    // stays as wide in the adjoint as in the kernel; implicit promotions
    // happen again by themselves around it.
    ExprP inner = expr(sub);
    QualType to = c->getType().getCanonicalType(), from = sub->getType().getCanonicalType();
    if (to->isUnsignedIntegerType() && from->isSignedIntegerType())
      L.ints_.check_unsigned_result(
          inner, c->getExprLoc(),
          fmt::format("'{}', converted to unsigned '{}',", L.text(sub), to.getAsString()), c);
    if (!to->isBooleanType() && L.ctx_.getTypeSize(to) < 32 &&
        L.ctx_.getTypeSize(to) < L.ctx_.getTypeSize(from) && !L.in_loop_bounds_) {
      auto pv = to_poly(inner);
      if (!pv || !pv->is_constant())
        L.fail(c->getExprLoc(), fmt::format("conversion of '{}' to '{}' may truncate it; dpgen "
                                            "computes integers in 64 bits: use int or a wider "
                                            "type",
                                            L.text(sub), to.getAsString()));
    }
    const auto* implicit = dyn_cast<ImplicitCastExpr>(c);
    bool explicit_cast = isa<ExplicitCastExpr>(c) || (implicit && implicit->isPartOfExplicitCast());
    if (!explicit_cast || L.ctx_.getTypeSize(c->getType()) < 64 ||
        L.ctx_.getTypeSize(sub->getType()) >= 64 || inner->type != Type::Int)
      return inner;
    return widened(inner, L.spelled(c->getType()), to->isUnsignedIntegerType());
  }
  case CK_FloatingToIntegral:
    return spelled_cast(cast(expr(sub), L.type_of(c)), L.ctx_.getTypeSize(c->getType()),
                        L.spelled(c->getType()));
  case CK_IntegralToFloating:
  case CK_FloatingCast:
    return cast(expr(sub), L.type_of(c));
  case CK_IntegralToBoolean:
  case CK_FloatingToBoolean:
    return cond(sub);
  case CK_BooleanToSignedIntegral:
  case CK_ToVoid:
  default:
    if (c->getType()->isPointerType() || sub->getType()->isPointerType())
      L.fail(c->getExprLoc(), "pointer arithmetic is outside the kernel subset");
    L.fail(c->getExprLoc(),
           fmt::format("conversion '{}' is outside the kernel subset", c->getCastKindName()));
  }
}

ExprP Expressions::decl_ref(const DeclRefExpr* r) {
  if (const auto* ec = dyn_cast<EnumConstantDecl>(r->getDecl()))
    return int_const(L.ints_.constant(ec->getInitVal(), r->getLocation()));
  const auto* v = dyn_cast<VarDecl>(r->getDecl());
  if (!v)
    L.fail(r->getLocation(),
           fmt::format("'{}' is outside the kernel subset", r->getDecl()->getNameAsString()));
  L.ptrs_.check_usable(v, r->getLocation());
  auto it = L.env_.find(v);
  if (it == L.env_.end()) {
    // A global constant with a known value is a constant.
    if (v->hasGlobalStorage() && v->getType().isConstQualified()) {
      if (const clang::Expr* init = v->getAnyInitializer()) {
        clang::Expr::EvalResult res;
        if (init->EvaluateAsRValue(res, L.ctx_) && res.Val.isFloat())
          return real_const(res.Val.getFloat().convertToDouble(), L.type_of(r));
        if (init->EvaluateAsRValue(res, L.ctx_) && res.Val.isInt())
          return int_const(L.ints_.constant(res.Val.getInt(), r->getLocation()));
      }
    }
    L.fail(r->getLocation(), fmt::format("'{}' is global state, outside the kernel subset; "
                                         "pass it as a parameter",
                                         v->getNameAsString()));
  }
  const Binding& b = it->second;
  switch (b.kind) {
  case Binding::ScalarParam:
    return L.scalar_param(b.param->name, b.param->elem);
  case Binding::ArrayParam:
    L.fail(r->getLocation(), fmt::format("{} '{}' used as a value; only its elements can be "
                                         "read",
                                         b.offset ? "pointer" : "array",
                                         b.offset ? v->getNameAsString() : b.param->name));
  case Binding::LoopVar:
    return *b.value;
  case Binding::LocalArray:
    L.fail(r->getLocation(), fmt::format("local array '{}' used as a value; only its elements "
                                         "can be read",
                                         v->getNameAsString()));
  case Binding::Lambda:
    L.fail(r->getLocation(), fmt::format("lambda '{}' is used other than called; a kernel calls "
                                         "its lambdas, which dpgen inlines",
                                         v->getNameAsString()));
  case Binding::Value:
    if (b.deref_only)
      L.fail(r->getLocation(), fmt::format("pointer '{}' to a local is used without '*': only "
                                           "'*{}' is in the kernel subset",
                                           v->getNameAsString(), v->getNameAsString()));
    if (!b.value)
      L.fail(r->getLocation(), L.unset_message(v, "may be used before it has a value"));
    return *b.value;
  }
  throw std::logic_error("internal error: lower: a binding of no known kind");
}

ExprP Expressions::binary_expr(const BinaryOperator* b) {
  if (b->isAssignmentOp())
    L.fail(b->getOperatorLoc(), "assignment inside an expression is outside the kernel subset");
  if (b->getOpcode() == BO_Comma)
    L.fail(b->getOperatorLoc(), "comma operator is outside the kernel subset");
  if (b->getOpcode() == BO_LAnd || b->getOpcode() == BO_LOr) {
    ExprP l = cond(b->getLHS()); // (first: what it assigns, the right side sees)
    ExprP r = L.guards_.conditional(b->getRHS(), PathCond{l, b->getOpcode() == BO_LAnd},
                                    [&] { return cond(b->getRHS()); });
    return binary(b->getOpcode() == BO_LAnd ? Op::And : Op::Or, l, r);
  }
  ExprP l = expr(b->getLHS()), r = expr(b->getRHS());
  // Arithmetic, comparisons and integer bit logic (index and branch
  // conditions; never on reals in C++): the op table's row of the symbol.
  const OpInfo* row = binary_op(b->getOpcodeStr().str());
  if (!row)
    L.fail(b->getOperatorLoc(),
           fmt::format("operator '{}' is outside the kernel subset", b->getOpcodeStr().str()));
  if (row->op == Op::Sub && b->getType()->isUnsignedIntegerType())
    L.ints_.check_unsigned_result(binary(Op::Sub, l, r), b->getOperatorLoc(),
                                  fmt::format("unsigned difference '{}'", L.text(b)), b);
  if (b->getType()->isUnsignedIntegerType())
    L.ints_.check_unsigned_constant(b->getOpcode(), b->getOperatorLoc(), L.text(b), l, r);
  if (row->op == Op::Rem) {
    // a periodic wrap `(x + 1 + nx) % nx` as the choice it is (prove.hpp)
    std::vector<Loop> around;
    for (const auto& lp : L.loops_)
      around.push_back(*lp);
    if (auto c = remainder_as_choice(l, r, around, L.path_))
      return *c;
  }
  return binary(row->op, l, r);
}

ExprP Expressions::call_expr(const CallExpr* c) {
  const FunctionDecl* f = c->getDirectCallee();
  if (!f)
    L.fail(c->getBeginLoc(), "indirect call is outside the kernel subset", "dpgen-call");
  if (f->getCanonicalDecl() == L.fn_->getCanonicalDecl())
    L.fail(c->getBeginLoc(),
           fmt::format("recursive call to '{}' is outside the kernel subset", f->getNameAsString()),
           "dpgen-call");
  // (a member function named like one, std::numeric_limits<T>::max, is not)
  const MathFn* math = isa<CXXMethodDecl>(f) ? nullptr : find_math_function(f->getNameAsString());
  bool from_library =
      L.sm_.isInSystemHeader(L.sm_.getExpansionLoc(f->getLocation())) || f->getBuiltinID() != 0;
  if (!from_library && f->hasBody())
    return L.inl_.inline_call(c, f);
  if (!from_library)
    L.fail(c->getBeginLoc(),
           fmt::format("call to '{}', whose body dpgen cannot see: helper functions are inlined, "
                       "so define '{}' in the kernel's file or a header it includes",
                       f->getQualifiedNameAsString(), f->getNameAsString()),
           "dpgen-call");
  if (!math) {
    // A constant the library computes: std::numeric_limits<double>::lowest(),
    // HUGE_VAL (__builtin_huge_val()), a constexpr function of constants.
    clang::Expr::EvalResult r;
    if (c->EvaluateAsRValue(r, L.ctx_) && !r.HasSideEffects) {
      Type t = L.type_of(c);
      if (r.Val.isInt() && t == Type::Int)
        return int_const(L.ints_.constant(r.Val.getInt(), c->getBeginLoc()));
      if (r.Val.isFloat() && is_real(t)) {
        const llvm::APFloat& v = r.Val.getFloat();
        if (v.isInfinity()) // (printed as <cmath> spells it)
          return real_const(v.isNegative() ? -HUGE_VAL : HUGE_VAL, t,
                            std::string(v.isNegative() ? "-" : "") +
                                (t == Type::Float ? "HUGE_VALF" : "HUGE_VAL"));
        if (!v.isNaN())
          return real_const(v.convertToDouble(), t);
      }
    }
  }
  if (const clang::Expr* comp = comparator(c, f)) // std::max(a, b, comp)
    L.fail(comp->getBeginLoc(), comparator_message(f), "dpgen-call");
  if (!math && f->isInStdNamespace() && f->getName() == "clamp" && c->getNumArgs() == 3) {
    // std::clamp(v, lo, hi) is v < lo ? lo : hi < v ? hi : v, which for lo <= hi (its precondition)
    // is min(max(v, lo), hi) with their ties: the same value, the same derivatives.
    Type t = L.type_of(c);
    auto arg = [&](unsigned i) { return cast(expr(c->getArg(i)), t); };
    ExprP v = arg(0), lo = arg(1), hi = arg(2);
    return call("min", {call("max", {v, lo}, t), hi}, t);
  }
  if (!math)
    L.fail(c->getBeginLoc(),
           fmt::format("call to '{}', which dpgen cannot differentiate; the kernel subset calls "
                       "only {}",
                       f->getQualifiedNameAsString(), supported_calls()),
           "dpgen-call");
  Type t = L.type_of(c);
  bool list = false;
  std::vector<ExprP> args;
  for (const clang::Expr* a : operands(c, math->name, list))
    args.push_back(cast(expr(a), t == Type::Int ? L.type_of(a) : t));
  std::string fnname = math->name;
  for (; list && args.size() > 2;
       args.erase(args.begin() + 1)) // the first least: min(min(a, b), c)
    args[0] = call(fnname, {args[0], args[1]}, t);
  if (list && args.size() == 1) // std::min({a})
    return args[0];
  if (args.size() != math->arity)
    L.fail(c->getBeginLoc(),
           fmt::format("'{}' takes {} argument(s) in the kernel subset", fnname, math->arity),
           "dpgen-call");
  return call(fnname, args, t);
}

} // namespace dpgen::lowering
