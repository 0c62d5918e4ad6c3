// Lowering, pointer locals (lower_pointer.hpp): `const double* row = a + j *
// nx;` bound as array `a` at element offset j * nx. The pointer is fixed at
// its declaration (an assignment to it, `++row`, `row += nx`, is refused where
// assignments are lowered), so the offset is the value its initialiser has
// there, counters and locals included; `row[i]` is then `a[j * nx + i]`, as if
// the kernel had written that. A pointer into anything but a flat array
// parameter (a line buffer, a view, row pointers, a std::vector, a scalar by
// reference, a local) is refused.
#include "lower_impl.hpp"

namespace dpgen::lowering {

bool PointerLocals::declare(const VarDecl* v) {
  const QualType t = v->getType();
  if (t->isReferenceType() && L.scalar_type(t.getNonReferenceType()))
    return declare_reference(v);
  if (!t->isPointerType() || !L.scalar_type(t->getPointeeType()))
    return false;
  std::optional<Binding> b = v->getInit() ? pointer_into(v->getInit()) : std::nullopt;
  if (!b)
    L.fail(v->getLocation(),
           fmt::format("pointer '{}' must be initialised where it is declared with a pointer "
                       "into an array parameter of the kernel ('const double* {} = a + j * nx;', "
                       "'&a[k]'), and is not changed after (declare another for another row)",
                       v->getNameAsString(), v->getNameAsString()),
           "dpgen-pointer");
  check_flat(*b, v->getInit());
  if (!b->offset) // (`row = a`: a pointer local all the same, fixed)
    b->offset = int_const(0);
  L.env_[v] = *b;
  return true;
}

// `const double& x = u[i];` (also through a pointer local, `const auto& x = row[i];`): an
// element of an array the kernel never writes (an input, a constant array), so the
// reference reads what a copy made here reads: a local of that value. A reference to
// anything else (an output's element, which later stores change; a local; a non-const
// reference, through which the kernel would write) is refused.
bool PointerLocals::declare_reference(const VarDecl* v) {
  const QualType t = v->getType().getNonReferenceType();
  const clang::Expr* init = v->getInit() ? v->getInit()->IgnoreParenImpCasts() : nullptr;
  std::optional<Access> at = init && t.isConstQualified() ? L.exprs_.element(init) : std::nullopt;
  if (!at || (at->param->kind != ParamKind::In && at->param->kind != ParamKind::ConstArray) ||
      L.bufs_.is_buffer(at->param->name) || L.is_hidden(at->param->name))
    L.fail(v->getLocation(),
           fmt::format("reference '{}' is outside the kernel subset but for a const reference to "
                       "an element of an input ('const double& {} = u[i];'); copy the value "
                       "('const double {} = ...;') or index the array where it is used",
                       v->getNameAsString(), v->getNameAsString(), v->getNameAsString()),
           "dpgen-pointer");
  Binding b;
  b.kind = Binding::Value;
  b.kernel_level = L.loops_.empty();
  b.value = L.stmts_.make_local(v->getNameAsString(), v,
                                cast(L.exprs_.expr(v->getInit()), *L.scalar_type(t)));
  L.env_[v] = b;
  return true;
}

// A pointer into anything but a flat array parameter (or a table of namespace scope) is
// refused: a line buffer's elements, a view's, rows of pointers or a std::vector's are not
// the flat elements `offset + i` of one array.
void PointerLocals::check_flat(const Binding& b, const clang::Expr* at) {
  const Param* p = b.param;
  if (p->row_pointers || p->view || p->object || !p->container.empty() || p->nested ||
      p->scalar_ref || !p->rows.empty() || L.bufs_.is_buffer(p->name))
    L.fail(at->getBeginLoc(),
           fmt::format("a pointer into '{}' is outside the kernel subset: dpgen follows "
                       "pointers into flat array parameters ('const double* row = a + j * nx;'); "
                       "index '{}' itself",
                       p->name, p->name),
           "dpgen-pointer");
}

std::optional<Binding> PointerLocals::pointer_into(const clang::Expr* e) {
  e = e->IgnoreParenImpCasts(); // (an array's decay, a const added)
  // (a cast that keeps the element type: `(const double*)(a + k)`, `const_cast<double*>(p)`)
  while (const auto* c = dyn_cast<ExplicitCastExpr>(e)) {
    const QualType from = c->getSubExpr()->getType(), to = c->getType();
    if (!from->isPointerType() || !to->isPointerType() ||
        !L.ctx_.hasSameUnqualifiedType(from->getPointeeType(), to->getPointeeType()))
      break;
    e = c->getSubExpr()->IgnoreParenImpCasts();
  }
  if (const auto* r = dyn_cast<DeclRefExpr>(e)) {
    const auto* v = dyn_cast<VarDecl>(r->getDecl());
    auto it = v ? L.env_.find(v) : L.env_.end();
    if (it == L.env_.end() || it->second.kind != Binding::ArrayParam)
      return std::nullopt;
    return it->second;
  }
  const clang::Expr* base = nullptr; // the pointer moved
  const clang::Expr* amount = nullptr;
  bool back = false; // p - k
  if (const auto* b = dyn_cast<BinaryOperator>(e);
      b && (b->getOpcode() == BO_Add || b->getOpcode() == BO_Sub)) {
    const bool left = b->getLHS()->getType()->isPointerType();
    base = left ? b->getLHS() : b->getRHS();
    amount = left ? b->getRHS() : b->getLHS();
    back = b->getOpcode() == BO_Sub;
    if (!base->getType()->isPointerType() || amount->getType()->isPointerType())
      return std::nullopt; // (p - q is a distance, not a pointer)
  } else if (const auto* u = dyn_cast<UnaryOperator>(e); u && u->getOpcode() == UO_AddrOf) {
    const auto* s = dyn_cast<ArraySubscriptExpr>(u->getSubExpr()->IgnoreParens());
    if (!s || !s->getBase()->getType()->isPointerType())
      return std::nullopt;
    base = s->getBase();
    amount = s->getIdx();
  } else {
    return std::nullopt;
  }
  std::optional<Binding> b = pointer_into(base);
  if (!b)
    return std::nullopt;
  check_flat(*b, e);
  ExprP k = L.exprs_.expr(amount);
  if (k->type != Type::Int)
    L.fail(amount->getBeginLoc(), "a pointer moves by an integer", "dpgen-pointer");
  if (back)
    k = unary(Op::Neg, k);
  b->offset = b->offset ? binary(Op::Add, *b->offset, k) : k; // (an offset 0 folds away)
  return b;
}

const Param* PointerLocals::param_of(const Binding& b, const clang::Expr* base, ExprP* offset) {
  if (b.offset && !offset)
    L.fail(base->getBeginLoc(),
           fmt::format("pointer '{}' into '{}' is used where dpgen takes an array parameter of "
                       "the kernel itself; index '{}' there",
                       L.text(base), b.param->name, b.param->name),
           "dpgen-pointer");
  if (offset)
    *offset = b.offset ? *b.offset : nullptr;
  return b.param;
}

} // namespace dpgen::lowering
