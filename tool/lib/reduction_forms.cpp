// Lowering, the forms of reductions (reduction_forms.hpp): which statements
// of a loop body are updates of an accumulator or of a min/max reduction.
// Pure syntax over Clang's AST; the Reductions part lowers what it finds.
#include "lower_impl.hpp"

namespace dpgen::lowering {

namespace {

// The terms of `x = x + e`, `x = x - e`, `x = e + x` and of a chain `x = x + e - f + ...` or
// `x = e + x - f + ...` (x, which `is_x` recognises, the leftmost operand or the right one of
// the innermost +, whose left operand e is then one term: e + x is x + e, bit for bit), each
// with its sign (true: subtracted), in the order C++ adds them; empty for any other form. A
// cast of the whole chain to the type it is assigned to, `x = (double)(x + e)`, is the
// assignment's own conversion. (What the terms may mention is the caller's to check.)
template <typename IsX>
std::vector<std::pair<const clang::Expr*, bool>> chain_terms(const clang::Expr* rhs, IsX is_x) {
  std::vector<std::pair<const clang::Expr*, bool>> terms;
  const clang::Expr* e = rhs->IgnoreParenImpCasts();
  if (const auto* c = dyn_cast<ExplicitCastExpr>(e);
      c && rhs->getType()->isRealFloatingType() &&
      c->getType().getCanonicalType().getUnqualifiedType() ==
          rhs->getType().getCanonicalType().getUnqualifiedType())
    e = c->getSubExpr()->IgnoreParenImpCasts();
  while (const auto* b = dyn_cast<BinaryOperator>(e)) {
    if (b->getOpcode() != BO_Add && b->getOpcode() != BO_Sub)
      break;
    const bool start = is_x(b->getLHS()); // x + e, x - e: the chain's start
    if (start || (b->getOpcode() == BO_Add && is_x(b->getRHS()))) { // or e + x
      terms.push_back({start ? b->getRHS() : b->getLHS(), b->getOpcode() == BO_Sub});
      std::reverse(terms.begin(), terms.end());
      return terms;
    }
    terms.push_back({b->getRHS(), b->getOpcode() == BO_Sub});
    e = b->getLHS()->IgnoreParenImpCasts();
  }
  return {};
}

} // namespace

// The chain's terms where none mentions v (it would see v as it was, not the sum so far).
std::vector<std::pair<const clang::Expr*, bool>>
ReductionForms::accumulated_terms(const clang::Expr* rhs, const VarDecl* v) {
  auto terms = chain_terms(rhs, [&](const clang::Expr* e) {
    const auto* r = dyn_cast<DeclRefExpr>(e->IgnoreParenImpCasts());
    return r && r->getDecl() == v;
  });
  for (const auto& term : terms)
    if (mentions(term.first, v))
      return {};
  return terms;
}

std::vector<const clang::Expr*> ReductionForms::list_elements(const CallExpr* c) {
  const auto* l = c->getNumArgs() == 1
                      ? dyn_cast<CXXStdInitializerListExpr>(c->getArg(0)->IgnoreImplicit())
                      : nullptr;
  const auto* init = l ? dyn_cast<InitListExpr>(l->getSubExpr()->IgnoreImplicit()) : nullptr;
  if (!init)
    return {};
  return {init->inits().begin(), init->inits().end()};
}

bool ReductionForms::mentions(const Stmt* s, const ValueDecl* v) {
  if (!s)
    return false;
  if (const auto* r = dyn_cast<DeclRefExpr>(s); r && r->getDecl() == v)
    return true;
  for (const Stmt* c : s->children())
    if (mentions(c, v))
      return true;
  return false;
}

// The body of the lambda that `s` writes (a lambda expression) or names (a variable of its
// closure type, as at each call), where the lambda captures `v` by reference (its mentions of
// `v` are the caller's) or captures other lambdas and not `v`. Null for anything else (a
// capture by copy names the lambda's copy).
static const Stmt* lambda_body_of(const Stmt* s, const ValueDecl* v) {
  const CXXRecordDecl* closure = nullptr;
  if (const auto* le = dyn_cast<LambdaExpr>(s))
    closure = le->getLambdaClass();
  else if (const auto* r = dyn_cast<DeclRefExpr>(s))
    closure = r->getType().getNonReferenceType()->getAsCXXRecordDecl();
  if (!closure || !closure->isLambda())
    return nullptr;
  // by reference, or not at all but a lambda that may (`[&] { add(x); add(y); }`)
  bool by_ref = false, by_copy = false, lambdas = false;
  for (const LambdaCapture& lc : closure->captures()) {
    if (!lc.capturesVariable())
      continue;
    const ValueDecl* cv = lc.getCapturedVar();
    by_ref = by_ref || (cv == v && lc.getCaptureKind() == LCK_ByRef);
    by_copy = by_copy || (cv == v && lc.getCaptureKind() != LCK_ByRef);
    const auto* rd = cv->getType().getNonReferenceType()->getAsCXXRecordDecl();
    lambdas = lambdas || (rd && rd->isLambda());
  }
  const CXXMethodDecl* call = closure->getLambdaCallOperator();
  return call && (by_ref || (lambdas && !by_copy)) ? call->getBody() : nullptr;
}

// Visits the lambda bodies `s` leads to (lambda_body_of) with `visit`, once per path (a
// lambda calling a lambda is followed; `open` keeps a body from being entered inside
// itself). True where `s` is a lambda expression or names a closure: the caller visits
// nothing more of it (a lambda's capture list is no use of `v`).
static bool visit_lambda(const Stmt* s, const ValueDecl* v, std::set<const Stmt*>& open,
                         const std::function<void(const Stmt*)>& visit) {
  const Stmt* body = lambda_body_of(s, v);
  if (body && open.insert(body).second) {
    visit(body);
    open.erase(body);
  }
  return isa<LambdaExpr>(s) || (isa<DeclRefExpr>(s) && body != nullptr);
}

// The parameter through which call `c` lets its callee update `v`: a non-const reference
// bound to `v` (`add(s, x)` for `double& acc`), or a pointer given `&v` (`add(&s, x)` for
// `double* acc`; `pointer` set), or a pointer `v` passed on (`v` itself a pointer; `pointer`
// set). Null where `c` passes `v` no such way or its callee has no body here. `arg`: the
// argument.
static const ParmVarDecl* updated_param(const CallExpr* c, const ValueDecl* v,
                                        const clang::Expr*& arg, bool& pointer) {
  const FunctionDecl* f = c->getDirectCallee();
  if (!f || !f->hasBody(f)) // (the definition: its parameters are the ones its body names)
    return nullptr;
  // (a lambda's or functor's call, `add(s, x)`: argument 0 is the object)
  const unsigned shift = isa<CXXOperatorCallExpr>(c) && isa<CXXMethodDecl>(f) ? 1 : 0;
  for (unsigned i = shift; i < c->getNumArgs() && i - shift < f->getNumParams(); ++i) {
    const clang::Expr* a = c->getArg(i)->IgnoreParenImpCasts();
    bool by_address = false;
    if (const auto* u = dyn_cast<UnaryOperator>(a); u && u->getOpcode() == UO_AddrOf) {
      a = u->getSubExpr()->IgnoreParenImpCasts();
      by_address = true;
    }
    const auto* r = dyn_cast<DeclRefExpr>(a);
    if (!r || r->getDecl() != v)
      continue;
    const ParmVarDecl* p = f->getParamDecl(i - shift);
    const QualType pt = p->getType();
    const bool passed_on = !by_address && v->getType()->isPointerType();
    pointer = by_address || passed_on;
    const bool writable =
        pointer ? pt->isPointerType() && !pt->getPointeeType().isConstQualified()
                : pt->isReferenceType() && !pt.getNonReferenceType().isConstQualified();
    if (writable) {
      arg = c->getArg(i);
      return p;
    }
  }
  return nullptr;
}

// A call `s` that lets its callee update `v` (updated_param): `callee_kind(body, p, pointer)`
// says what the callee's body does to its parameter `p` (0: not the form asked for); where
// not 0, the call's other arguments are visited. None where `s` is no such call. (`open`:
// the bodies being visited; one is not entered inside itself.)
static std::optional<int>
through_call(const Stmt* s, const ValueDecl* v, std::set<const Stmt*>& open,
             const std::function<int(const Stmt*, const ParmVarDecl*, bool)>& callee_kind,
             const std::function<void(const Stmt*)>& visit) {
  const auto* c = dyn_cast<CallExpr>(s);
  const clang::Expr* arg = nullptr;
  bool pointer = false;
  const ParmVarDecl* p = c ? updated_param(c, v, arg, pointer) : nullptr;
  if (!p)
    return std::nullopt;
  const Stmt* callee = c->getDirectCallee()->getBody();
  int k = 0;
  if (open.insert(callee).second) {
    k = callee_kind(callee, p, pointer);
    open.erase(callee);
  }
  if (k != 0)
    for (const Stmt* ch : c->children())
      if (ch != arg)
        visit(ch);
  return k;
}

// `e` names `v` (`deref`: is `*v`).
static bool names(const clang::Expr* e, const ValueDecl* v, bool deref) {
  e = e->IgnoreParenImpCasts();
  if (deref) {
    const auto* u = dyn_cast<UnaryOperator>(e);
    if (!u || u->getOpcode() != UO_Deref)
      return false;
    e = u->getSubExpr()->IgnoreParenImpCasts();
  }
  const auto* r = dyn_cast<DeclRefExpr>(e);
  return r && r->getDecl() == v;
}

// is_accumulator for `v`, or with `deref` for `*v` (a helper's pointer parameter: its
// updates are `*v += e` and `*v -= e`). `open`: the bodies being visited.
static bool accumulates(const Stmt* body, const VarDecl* v, bool deref,
                        std::set<const Stmt*>& open) {
  int updates = 0;
  bool other = false;
  std::function<void(const Stmt*)> visit = [&](const Stmt* s) {
    if (!s || other)
      return;
    if (visit_lambda(s, v, open, visit))
      return;
    if (std::optional<int> k = through_call(
            s, v, open,
            [&](const Stmt* callee, const ParmVarDecl* p, bool pointer) {
              return accumulates(callee, p, pointer, open) ? 1 : 0;
            },
            visit)) {
      other = other || *k == 0;
      ++updates; // (each of the callee's updates is one of `v`)
      return;
    }
    if (const auto* b = dyn_cast<BinaryOperator>(s); b && b->isAssignmentOp()) {
      if (names(b->getLHS(), v, deref)) {
        bool ok = b->getOpcode() == BO_AddAssign || b->getOpcode() == BO_SubAssign
                      ? !ReductionForms::mentions(b->getRHS(), v)
                      : !deref && b->getOpcode() == BO_Assign &&
                            !ReductionForms::accumulated_terms(b->getRHS(), v).empty();
        if (!ok)
          other = true;
        ++updates;
        return;
      }
    }
    if (const auto* r = dyn_cast<DeclRefExpr>(s); r && r->getDecl() == v) {
      other = true;
      return;
    }
    for (const Stmt* c : s->children())
      visit(c);
  };
  visit(body);
  return updates > 0 && !other;
}

// Every mention of `v` in `body` is the target of `v += e`, `v -= e` or
// `v = v + e` (and its `v`), with `e` free of v, and there is at least one.
// Lambdas that capture `v` by reference count as part of `body` where it
// names them (`auto add = [&](double x) { s += x * x; };` ... `add(a[i]);`),
// and so do helpers given `v` to add to (`add(s, x)` for `double& acc`,
// `add(&s, x)` for `double* acc`), where they only add to it.
bool ReductionForms::is_accumulator(const Stmt* body, const VarDecl* v) {
  std::set<const Stmt*> open; // (a pointer: a helper's out-parameter, summed into as `*v`)
  return accumulates(body, v, v->getType()->isPointerType(), open);
}

bool ReductionForms::same_expr(const clang::Expr* a, const clang::Expr* b) const {
  llvm::FoldingSetNodeID x, y;
  a->IgnoreParenImpCasts()->Profile(x, ctx_, true);
  b->IgnoreParenImpCasts()->Profile(y, ctx_, true);
  return x == y;
}

namespace {

// `s` may change something as it is evaluated: `++`, `--`, an assignment, or a call of a
// function that takes a non-const reference or pointer, or of a non-const member function
// other than an element accessor (`v(j, i)`, `v[i]`).
bool may_mutate(const Stmt* s) {
  if (!s)
    return false;
  if (const auto* u = dyn_cast<UnaryOperator>(s); u && u->isIncrementDecrementOp())
    return true;
  if (const auto* b = dyn_cast<BinaryOperator>(s); b && b->isAssignmentOp())
    return true;
  if (const auto* c = dyn_cast<CallExpr>(s)) {
    const FunctionDecl* f = c->getDirectCallee();
    if (!f)
      return true;
    const auto* oc = dyn_cast<CXXOperatorCallExpr>(c);
    const bool accessor = oc && (oc->getOperator() == OO_Call || oc->getOperator() == OO_Subscript);
    if (oc && !accessor)
      return true;
    if (const auto* m = dyn_cast<CXXMethodDecl>(f); m && !m->isConst() && !accessor)
      return true;
    for (const ParmVarDecl* p : f->parameters()) {
      const QualType t = p->getType();
      if ((t->isReferenceType() || t->isPointerType()) && !t->getPointeeType().isConstQualified())
        return true;
    }
  }
  for (const Stmt* c : s->children())
    if (may_mutate(c))
      return true;
  return false;
}

} // namespace

bool ReductionForms::self_update_terms(
    const clang::Expr* lhs, const clang::Expr* rhs,
    std::vector<std::pair<const clang::Expr*, bool>>& terms) const {
  terms.clear();
  if (may_mutate(lhs))
    return false;
  terms = chain_terms(rhs, [&](const clang::Expr* e) { return same_expr(e, lhs); });
  // (a target through an accessor or a view, R(i, j): a term that reads the output is refused
  // where it reads it, as any read of an output summed into)
  const ReductionTarget t = target_of(lhs);
  if (terms.size() > 1 && t.decl)
    for (const auto& term : terms)
      if (mentions(term.first, t.decl))
        terms.clear();
  return !terms.empty();
}

bool ReductionForms::is_target(const clang::Expr* e, const ReductionTarget& t) const {
  if (t.element)
    return same_expr(e, t.element);
  const auto* r = dyn_cast<DeclRefExpr>(e->IgnoreParenImpCasts());
  return r && r->getDecl() == t.decl;
}

ReductionTarget ReductionForms::target_of(const clang::Expr* lhs) {
  lhs = lhs->IgnoreParenImpCasts();
  if (const auto* r = dyn_cast<DeclRefExpr>(lhs))
    return {dyn_cast<VarDecl>(r->getDecl()), nullptr};
  const clang::Expr* base = nullptr;
  if (const auto* u = dyn_cast<UnaryOperator>(lhs); u && u->getOpcode() == UO_Deref)
    base = u->getSubExpr();
  else if (const auto* sub = dyn_cast<ArraySubscriptExpr>(lhs))
    base = sub->getBase();
  while (base) { // p[j][i]: p
    base = base->IgnoreParenImpCasts();
    if (const auto* sub = dyn_cast<ArraySubscriptExpr>(base)) {
      base = sub->getBase();
      continue;
    }
    if (const auto* r = dyn_cast<DeclRefExpr>(base))
      if (isa<ParmVarDecl>(r->getDecl()))
        return {r->getDecl(), lhs};
    break;
  }
  return {};
}

// The term `e` of a min/max update of `t` (lower_impl.hpp).
// The type of expression `e` is that of the target `t` (canonical, unqualified).
bool ReductionForms::same_type(QualType e, const ReductionTarget& t) const {
  QualType target = t.element ? t.element->getType() : t.decl->getType().getNonReferenceType();
  return e.getCanonicalType().getUnqualifiedType() ==
         target.getCanonicalType().getUnqualifiedType();
}

// A user's helper that is a max or a min of its two parameters: its body the
// one statement `return a > b ? a : b;` (or `b < a ? a : b`, `std::max(a,
// b)`, `fmax(b, a)`, ...: any form extremum_term knows, the target one
// parameter and the term the other), both parameters real values. +1 a max,
// -1 a min, 0 anything else (a helper that does more is no update).
int ReductionForms::helper_extremum(const FunctionDecl* f) const {
  const FunctionDecl* def = nullptr;
  if (!f->hasBody(def) || def->getNumParams() != 2 || isa<CXXMethodDecl>(def) ||
      def->isVariadic())
    return 0;
  const ParmVarDecl *a = def->getParamDecl(0), *b = def->getParamDecl(1);
  // (one real type throughout: a float helper on doubles would round)
  QualType rt = def->getReturnType().getCanonicalType().getUnqualifiedType();
  for (const ParmVarDecl* p : {a, b}) {
    QualType q = p->getType().getNonReferenceType();
    if (q.getCanonicalType().getUnqualifiedType() != rt ||
        (p->getType()->isReferenceType() && !q.isConstQualified()))
      return 0;
  }
  if (!rt->isRealFloatingType())
    return 0;
  const auto* body = dyn_cast_or_null<CompoundStmt>(def->getBody());
  const auto* ret = body && body->size() == 1 ? dyn_cast<ReturnStmt>(body->body_front()) : nullptr;
  if (!ret || !ret->getRetValue())
    return 0;
  if (helper_depth_ >= 4) // (a helper of a helper ...; a recursive one)
    return 0;
  int kind = 0;
  ++helper_depth_;
  const clang::Expr* term = extremum_term(ret->getRetValue(), {a, nullptr}, kind);
  --helper_depth_;
  const auto* r = term ? dyn_cast<DeclRefExpr>(term->IgnoreParenImpCasts()) : nullptr;
  return r && r->getDecl() == b ? kind : 0;
}

const clang::Expr* ReductionForms::extremum_term(const clang::Expr* rhs, const ReductionTarget& t,
                                                 int& extremum,
                                                 std::vector<const clang::Expr*>* more) const {
  auto is_t = [&](const clang::Expr* e) { return is_target(e, t); };
  rhs = rhs->IgnoreParenImpCasts();
  // std::max(v, e), fmax(e, v), fminf(v, e), ...; std::max({v, e1, e2}) (its terms e1, e2)
  if (const auto* c = dyn_cast<CallExpr>(rhs)) {
    std::vector<const clang::Expr*> args = list_elements(c);
    const bool list = !args.empty();
    if (!list)
      args.assign(c->arg_begin(), c->arg_end());
    if (args.size() != 2 && !list)
      return nullptr;
    const FunctionDecl* f = c->getDirectCallee();
    const MathFn* m =
        f && !isa<CXXMethodDecl>(f) ? find_math_function(f->getNameAsString()) : nullptr;
    bool from_library = f && (sm_.isInSystemHeader(sm_.getExpansionLoc(f->getLocation())) ||
                              f->getBuiltinID() != 0);
    int kind = 0;
    if (m && from_library &&
        (m->name == "max" || m->name == "min" || m->name == "fmax" || m->name == "fmin"))
      kind = m->name == "max" || m->name == "fmax" ? 1 : -1;
    else if (f && !from_library && !list && same_type(c->getType(), t))
      kind = helper_extremum(f); // the user's own `dmax(a, b)`, in the target's type
    if (kind == 0)
      return nullptr;
    // v once among the operands; the terms the others, none of which mentions v
    std::vector<const clang::Expr*> terms;
    for (const clang::Expr* a : args)
      if (!is_t(a))
        terms.push_back(a);
    if (terms.size() + 1 != args.size() || terms.empty())
      return nullptr;
    for (const clang::Expr* term : terms)
      if (mentions(term, t.decl))
        return nullptr;
    extremum = kind;
    if (more)
      more->assign(terms.begin() + 1, terms.end());
    return terms[0];
  }
  // v > e ? v : e, e < v ? v : e, v < e ? v : e (min), ... (a MAX macro)
  const auto* co = dyn_cast<ConditionalOperator>(rhs);
  if (!co)
    return nullptr;
  const auto* cmp = dyn_cast<BinaryOperator>(co->getCond()->IgnoreParenImpCasts());
  if (!cmp || !cmp->isRelationalOp())
    return nullptr;
  const clang::Expr *yes = co->getTrueExpr(), *no = co->getFalseExpr();
  const clang::Expr* term = is_t(yes) ? no : is_t(no) ? yes : nullptr;
  if (!term || mentions(term, t.decl))
    return nullptr;
  // The comparison's sides are the target and the same e as the other arm.
  const clang::Expr *l = cmp->getLHS(), *r = cmp->getRHS();
  bool t_left = is_t(l) && same_expr(r, term), t_right = is_t(r) && same_expr(l, term);
  if (!t_left && !t_right)
    return nullptr;
  // `l > r ? l : r` is a max, `l > r ? r : l` a min; `<` the other way.
  bool greater = cmp->getOpcode() == BO_GT || cmp->getOpcode() == BO_GE;
  bool picks_left = t_left ? is_t(yes) : !is_t(yes);
  extremum = greater == picks_left ? 1 : -1;
  return term;
}

// `if (e > v) v = e;` (lower_impl.hpp).
const clang::Expr* ReductionForms::extremum_if(const IfStmt* s, ReductionTarget& t, int& extremum,
                                        const clang::Expr** extra) const {
  if (s->getElse() || s->getInit() || s->getConditionVariable() || s->isConstexpr())
    return nullptr;
  const Stmt* body = s->getThen();
  if (const auto* cs = dyn_cast<CompoundStmt>(body)) {
    if (cs->size() != 1)
      return nullptr;
    body = cs->body_front();
  }
  const auto* as = dyn_cast<BinaryOperator>(body);
  if (!as || as->getOpcode() != BO_Assign)
    return nullptr;
  t = target_of(as->getLHS());
  if (!t.decl)
    return nullptr;
  const auto* cmp = dyn_cast<BinaryOperator>(s->getCond()->IgnoreParenImpCasts());
  // `if (e > m && i > 0) m = e;`: the update where the other conjunct holds.
  const clang::Expr* rest = nullptr;
  if (cmp && cmp->getOpcode() == BO_LAnd) {
    for (const clang::Expr* side : {cmp->getLHS(), cmp->getRHS()}) {
      const auto* b = dyn_cast<BinaryOperator>(side->IgnoreParenImpCasts());
      if (b && b->isRelationalOp() && mentions(b, t.decl)) {
        rest = side == cmp->getLHS() ? cmp->getRHS() : cmp->getLHS();
        cmp = b;
        break;
      }
    }
    if (!rest || mentions(rest, t.decl) || !extra)
      return nullptr;
  }
  if (!cmp || !cmp->isRelationalOp())
    return nullptr;
  if (extra)
    *extra = rest;
  const clang::Expr* term = as->getRHS();
  if (mentions(term, t.decl))
    return nullptr;
  bool t_left = is_target(cmp->getLHS(), t) && same_expr(cmp->getRHS(), term);
  bool t_right = is_target(cmp->getRHS(), t) && same_expr(cmp->getLHS(), term);
  if (!t_left && !t_right)
    return nullptr;
  // `if (e > v) v = e` keeps the larger: a max; `if (v > e) v = e` a min.
  bool greater = cmp->getOpcode() == BO_GT || cmp->getOpcode() == BO_GE;
  extremum = greater == t_right ? 1 : -1;
  return term;
}

// +1 or -1 if every mention of `t.decl` in `body` is in a min/max update of
// `t` of one kind (lower_impl.hpp).
// `*p` (element 0) or `p[c]` of a parameter, c an integer constant: p and c.
std::optional<std::pair<const ValueDecl*, long long>>
ReductionForms::constant_element(const clang::Expr* e) const {
  e = e->IgnoreParenImpCasts();
  const clang::Expr* base = nullptr;
  long long index = 0;
  if (const auto* u = dyn_cast<UnaryOperator>(e); u && u->getOpcode() == UO_Deref) {
    base = u->getSubExpr();
  } else if (const auto* sub = dyn_cast<ArraySubscriptExpr>(e)) {
    clang::Expr::EvalResult r;
    if (sub->getIdx()->isValueDependent() || !sub->getIdx()->EvaluateAsInt(r, ctx_))
      return std::nullopt;
    base = sub->getBase();
    index = r.Val.getInt().getExtValue();
  }
  const auto* ref = base ? dyn_cast<DeclRefExpr>(base->IgnoreParenImpCasts()) : nullptr;
  if (!ref || !isa<ParmVarDecl>(ref->getDecl()))
    return std::nullopt;
  return std::pair{ref->getDecl(), index};
}

bool ReductionForms::apart(const clang::Expr* a, const clang::Expr* b) const {
  auto x = constant_element(a), y = constant_element(b);
  return x && y && x->first == y->first && x->second != y->second;
}

int ReductionForms::extremum_kind(const Stmt* body, const ReductionTarget& t) const {
  std::set<const Stmt*> open;
  return extremum_kind(body, t, open);
}

int ReductionForms::extremum_kind(const Stmt* body, const ReductionTarget& t,
                                  std::set<const Stmt*>& open) const {
  int kind = 0, updates = 0;
  bool other = false;
  std::function<void(const Stmt*)> visit = [&](const Stmt* s) {
    if (!s || other)
      return;
    // (a local's updates inside lambdas and helpers, as is_accumulator; a helper's
    // `double& m` only: a pointer's `*m = std::max(*m, e)` is no form here)
    if (!t.element && visit_lambda(s, t.decl, open, visit))
      return;
    int k = 0;
    if (std::optional<int> called =
            t.element ? std::nullopt
                      : through_call(
                            s, t.decl, open,
                            [&](const Stmt* callee, const ParmVarDecl* p, bool pointer) {
                              return pointer ? 0 : extremum_kind(callee, {p, nullptr}, open);
                            },
                            visit)) {
      other = other || *called == 0 || (kind != 0 && *called != kind);
      kind = *called;
      ++updates;
      return;
    }
    if (const auto* i = dyn_cast<IfStmt>(s)) {
      ReductionTarget u;
      const clang::Expr* rest = nullptr;
      bool same = extremum_if(i, u, k, &rest) && u.decl == t.decl &&
                  (t.element ? u.element && same_expr(u.element, t.element) : !u.element);
      if (same) {
        other = other || (kind != 0 && k != kind);
        kind = k;
        ++updates;
        return;
      }
    }
    if (const auto* b = dyn_cast<BinaryOperator>(s); b && b->isAssignmentOp()) {
      if (is_target(b->getLHS(), t)) {
        if (b->getOpcode() != BO_Assign || !extremum_term(b->getRHS(), t, k) ||
            (kind != 0 && k != kind)) {
          other = true;
          return;
        }
        kind = k;
        ++updates;
        return;
      }
    }
    // Another element of the target's array at a constant index (`err[1]`
    // beside the reduction into `err[0]`): a different element, no mention.
    if (const auto* e = dyn_cast<clang::Expr>(s); e && t.element && apart(e, t.element))
      return;
    if (const auto* r = dyn_cast<DeclRefExpr>(s); r && r->getDecl() == t.decl) {
      other = true;
      return;
    }
    for (const Stmt* c : s->children())
      visit(c);
  };
  visit(body);
  return updates > 0 && !other ? kind : 0;
}

} // namespace dpgen::lowering
