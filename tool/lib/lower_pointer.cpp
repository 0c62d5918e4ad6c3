// Lowering, pointer locals (lower_pointer.hpp): `const double* row = a + j *
// nx;` bound as array `a` at element offset j * nx. The pointer is fixed at
// its declaration (an assignment to it, `++row`, `row += nx`, is refused), or,
// declared with no value (C89), at each assignment at the top of a loop's body
// before its uses; the offset is the value its initialiser has there, counters
// and locals included; `row[i]` is then `a[j * nx + i]`, as if the kernel had
// written that. A pointer into anything but a flat array
// parameter (a line buffer, a view, row pointers, a std::vector, a scalar by
// reference, a local) is refused.
#include "lower_impl.hpp"

namespace dpgen::lowering {

bool PointerLocals::declare(const VarDecl* v) {
  const QualType t = v->getType();
  if (t->isReferenceType() && L.scalar_type(t.getNonReferenceType()))
    return declare_reference(v);
  if (t->isReferenceType() && declare_row(v))
    return true;
  if (!t->isPointerType() || !L.scalar_type(t->getPointeeType()))
    return false;
  const clang::Expr* init = v->getInit();
  if (!init || init->IgnoreParenImpCasts()->isNullPointerConstant(
                   L.ctx_, clang::Expr::NPC_ValueDependentIsNotNull) != clang::Expr::NPCK_NotNull) {
    deferred_.insert(v); // (`double* row;`, `= NULL`: assigned before it is used, or refused)
    L.env_.erase(v);     // (a helper's, inlined again: what the last call left is gone)
    return true;
  }
  std::optional<Binding> b = pointer_into(init);
  if (!b)
    L.fail(v->getLocation(),
           fmt::format("pointer '{}' must be initialised where it is declared with a pointer "
                       "into an array parameter of the kernel ('const double* {} = a + j * nx;', "
                       "'&a[k]') and not changed after, or declared with no value and assigned "
                       "in each iteration before it is used ('row = a + j * nx;')",
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

// `const auto& up = u[j - 1];`, `auto& row = v[j];` of a std::vector<std::vector<T>>
// parameter: a reference is bound once, so the row is the one its index names here (a
// counter changed later does not move it), and `up[i]` is u[j - 1][i] (row_element).
bool PointerLocals::declare_row(const VarDecl* v) {
  const auto* oc =
      v->getInit() ? dyn_cast<CXXOperatorCallExpr>(v->getInit()->IgnoreParenImpCasts()) : nullptr;
  if (!oc || oc->getOperator() != OO_Subscript || oc->getNumArgs() != 2)
    return false;
  const auto* base = dyn_cast<DeclRefExpr>(oc->getArg(0)->IgnoreParenImpCasts());
  const auto* bv = base ? dyn_cast<VarDecl>(base->getDecl()) : nullptr;
  auto it = bv ? L.env_.find(bv) : L.env_.end();
  if (it == L.env_.end() || it->second.kind != Binding::ArrayParam || it->second.offset ||
      !it->second.param->nested)
    return false;
  const Param* p = it->second.param;
  ExprP row = L.exprs_.expr(oc->getArg(1));
  if (row->type != Type::Int || !to_poly(row))
    L.fail(oc->getArg(1)->getBeginLoc(),
           fmt::format("row '{}' of '{}' is taken at a data-dependent index; dpgen needs both "
                       "indices of {}[j][i] affine in the loop counters and sizes",
                       v->getNameAsString(), p->name, p->name),
           "dpgen-pointer");
  Binding b;
  b.kind = Binding::ArrayParam;
  b.param = p;
  b.offset = binary(Op::Mul, row, L.row_lengths_.at(p->name));
  L.env_[v] = b;
  return true;
}

Access PointerLocals::row_element(const Param* p, const ExprP& offset, const ExprP& idx,
                                  const clang::Expr* at) {
  if (!p->nested)
    L.fail(at->getBeginLoc(), "operator[] must index a std::vector parameter of the kernel");
  if (!to_poly(idx))
    L.fail(at->getBeginLoc(), fmt::format("'{}' is indexed at a data-dependent column; dpgen "
                                          "needs both indices of {}[j][i] affine in the loop "
                                          "counters and sizes (pass a flat array for "
                                          "interpolation)",
                                          L.text(at), p->name));
  return Access{p, binary(Op::Add, offset, idx)};
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

bool PointerLocals::assign(const clang::BinaryOperator* b) {
  const auto* ref = dyn_cast<DeclRefExpr>(b->getLHS()->IgnoreParenImpCasts());
  const auto* v = ref ? dyn_cast<VarDecl>(ref->getDecl()) : nullptr;
  if (!v || !v->getType()->isPointerType() || !L.scalar_type(v->getType()->getPointeeType()))
    return false;
  const std::string name = v->getNameAsString();
  auto refuse = [&](const std::string& why) {
    L.poisoned_.insert(v); // (its uses are not reported again)
    L.fail(b->getOperatorLoc(),
           fmt::format("pointer '{}' is changed here{}; dpgen follows a pointer fixed where it "
                       "is declared ('const double* {} = a + j * nx;'), or one declared with no "
                       "value and assigned at the top of each iteration of a loop, before it is "
                       "used ('{} = a + j * nx;')",
                       name, why, name, name),
           "dpgen-pointer");
  };
  if (!deferred_.count(v))
    return false; // (refused as a change of a fixed pointer: Stores::assign)
  if (L.poisoned_.count(v))
    throw Rejected{}; // (refused once)
  if (b->getOpcode() != BO_Assign)
    refuse(fmt::format(" by '{}' (its value carries from one iteration to the next)",
                       b->getOpcodeStr().str()));
  // A statement of a loop's body or of the function's: not in an arm of a condition.
  const clang::Stmt* stmt = b;
  auto ps = L.ctx_.getParents(*stmt);
  if (!ps.empty())
    if (const auto* w = ps[0].get<clang::ExprWithCleanups>()) {
      stmt = w;
      ps = L.ctx_.getParents(*stmt);
    }
  bool top = false;
  if (!ps.empty()) {
    const clang::Stmt* parent = ps[0].get<clang::Stmt>();
    const auto is_loop = [](const clang::Stmt* s) {
      return s &&
             (isa<ForStmt>(s) || isa<WhileStmt>(s) || isa<DoStmt>(s) || isa<CXXForRangeStmt>(s));
    };
    if (parent && isa<CompoundStmt>(parent)) {
      auto pp = L.ctx_.getParents(*parent);
      top = !pp.empty() && (is_loop(pp[0].get<clang::Stmt>()) ||
                            pp[0].get<clang::FunctionDecl>() == v->getDeclContext());
    } else {
      top = is_loop(parent);
    }
  }
  if (!top)
    refuse(" in an arm of a condition, a block of its own or a lambda (what it points at "
           "after it would depend on the path taken, or on the calls)");
  // The value it holds here must be one this iteration gave it (or none).
  if (L.env_.count(v)) {
    auto it = assigned_in_.find(v);
    if (it == assigned_in_.end() || it->second != L.loop_ids_)
      refuse(" in a loop, holding a value from before the loop's iteration (in the next "
             "iteration it would point where this one left it)");
  }
  std::optional<Binding> bound = pointer_into(b->getRHS());
  if (!bound) {
    L.poisoned_.insert(v);
    if (const auto* from = dyn_cast<DeclRefExpr>(b->getRHS()->IgnoreParenImpCasts());
        from && L.poisoned_.count(from->getDecl()))
      throw Rejected{}; // (`row = plane;`, plane's error reported already)
    if (const auto* sum = dyn_cast<BinaryOperator>(b->getRHS()->IgnoreParenImpCasts()))
      for (const clang::Expr* side : {sum->getLHS(), sum->getRHS()})
        if (const auto* from = dyn_cast<DeclRefExpr>(side->IgnoreParenImpCasts());
            from && L.poisoned_.count(from->getDecl()))
          throw Rejected{}; // (`row = plane + j * nx;`)
    L.fail(b->getRHS()->getBeginLoc(),
           fmt::format("pointer '{}' must be assigned a pointer into an array parameter of the "
                       "kernel ('{} = a + j * nx;', '&a[k]')",
                       name, name),
           "dpgen-pointer");
  }
  check_flat(*bound, b->getRHS());
  if (!bound->offset)
    bound->offset = int_const(0);
  L.env_[v] = *bound;
  assigned_in_[v] = L.loop_ids_;
  return true;
}

void PointerLocals::check_not_stepped(const clang::UnaryOperator* u) {
  const auto* ref = dyn_cast<DeclRefExpr>(u->getSubExpr()->IgnoreParenImpCasts());
  const auto* v = ref ? dyn_cast<VarDecl>(ref->getDecl()) : nullptr;
  if (!v || !deferred_.count(v))
    return;
  L.poisoned_.insert(v);
  L.fail(u->getOperatorLoc(),
         fmt::format("pointer '{}' is stepped by '{}' (its value carries from one iteration to "
                     "the next); name the row it points at in each iteration ('{} = a + j * "
                     "nx;')",
                     v->getNameAsString(), clang::UnaryOperator::getOpcodeStr(u->getOpcode()).str(),
                     v->getNameAsString()),
         "dpgen-pointer");
}

void PointerLocals::check_usable(const VarDecl* v, clang::SourceLocation at) {
  if (v && L.poisoned_.count(v))
    throw Rejected{}; // its declaration's (assignment's) error is reported already
  if (v && deferred_.count(v) && !L.env_.count(v))
    L.fail(at,
           fmt::format("pointer '{}' is used before it is assigned (in this iteration: a value "
                       "from an earlier one, or from before the loop, is not followed); assign "
                       "it ('{} = a + j * nx;') before its uses, in the same loop body",
                       v->getNameAsString(), v->getNameAsString()),
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
