// Lowering, `while` loops that count (lower_loop.hpp): a `while` whose body ends by stepping
// one integer counter, or whose condition counts it down (`i-- > lo`, `i--`, `--i >= 0`:
// count_down), is the `for` loop C would run:
//
//   int i = lo;                              for (i = i; i < hi; ++i) {
//   while (i < hi) { body; ++i; }      <=>     body;
//                                            }
//   size_t i = n;
//   while (i-- > lo) { body; }         <=>   for (i = i; i-- > lo;) { body; }
//
// (the counter keeps the value it has when the loop starts, which `i = i` reads). dpgen
// builds that `for` statement out of the `while`'s own parts and lowers it as any other, so
// every rule of a `for` loop applies: a counter the body assigns, a bound the body changes,
// a counter read after the loop are refused there. What only a `while` can do is refused
// here: a `continue` (it skips the step at the end of the body, which a `for` would run).
#include "lower_while.hpp"

#include "lower_impl.hpp"

namespace dpgen::lowering {

namespace {

// The local that `e` steps by a constant or a size: `++i`, `i++`, `--i`, `i--`, `i += s`,
// `i -= s`, `i = i + s` (the for header checks the step itself); null for anything else.
const VarDecl* stepped(const Stmt* s) {
  // (`(++i);`, and a macro's `((i) += 1)`)
  const Stmt* e = isa<clang::Expr>(s) ? llvm::cast<clang::Expr>(s)->IgnoreParens() : s;
  const clang::Expr* target = nullptr;
  if (const auto* u = dyn_cast<UnaryOperator>(e); u && u->isIncrementDecrementOp())
    target = u->getSubExpr();
  else if (const auto* c = dyn_cast<CompoundAssignOperator>(e);
           c && (c->getOpcode() == BO_AddAssign || c->getOpcode() == BO_SubAssign))
    target = c->getLHS();
  const VarDecl* assigned = nullptr; // `i = i + 1`
  bool adds = true;
  if (const auto* a = dyn_cast<BinaryOperator>(e); a && self_step(a, assigned, adds))
    target = a->getLHS();
  const auto* r = target ? dyn_cast<DeclRefExpr>(target->IgnoreParenImpCasts()) : nullptr;
  const auto* v = r ? dyn_cast<VarDecl>(r->getDecl()) : nullptr;
  return v && v->getType()->isIntegerType() && !v->getType()->isBooleanType() ? v : nullptr;
}

} // namespace

// `--k` of an unsigned local in a condition (`--k > 0`, `0 < --k`, `--k`), else null.
const VarDecl* unsigned_pre_decrement(const clang::Expr* cond) {
  const clang::Expr* e = cond ? cond->IgnoreParenImpCasts() : nullptr;
  const auto* c = e ? dyn_cast<BinaryOperator>(e) : nullptr;
  const clang::Expr* sides[] = {e, c ? c->getLHS() : nullptr, c ? c->getRHS() : nullptr};
  for (const clang::Expr* side : sides) {
    const auto* u = side ? dyn_cast<UnaryOperator>(side->IgnoreParenImpCasts()) : nullptr;
    const VarDecl* v = u && u->getOpcode() == UO_PreDec ? stepped(u) : nullptr;
    if (v && v->getType()->isUnsignedIntegerType())
      return v;
  }
  return nullptr;
}

std::string pre_decrement_message(const VarDecl* u) {
  return fmt::format("the unsigned counter '{}' is stepped down before it is tested ('--{}'): at 0 "
                     "it wraps around instead of ending the loop; test it before the step ('{}-- "
                     "> lo' runs the body down to {} = lo), or make it signed",
                     u->getNameAsString(), u->getNameAsString(), u->getNameAsString(),
                     u->getNameAsString());
}

namespace {

// The counter a condition counts down (count_down), else null.
const VarDecl* counted_down(const clang::Expr* cond) { return count_down(cond).var; }

// A `continue` of the loop whose body is `s` (not one of a loop inside it, nor a lambda's).
const ContinueStmt* own_continue(const Stmt* s) {
  if (!s || isa<ForStmt>(s) || isa<WhileStmt>(s) || isa<DoStmt>(s) || isa<CXXForRangeStmt>(s) ||
      isa<LambdaExpr>(s))
    return nullptr;
  if (const auto* c = dyn_cast<ContinueStmt>(s))
    return c;
  for (const Stmt* child : s->children())
    if (const ContinueStmt* c = own_continue(child))
      return c;
  return nullptr;
}

const char* const kForm = "a while loop is in the kernel subset as the for loop it is: one "
                          "integer counter, stepped by the body's last statement "
                          "(`while (i < n) { ...; ++i; }`) or counted down by the condition "
                          "(`while (i-- > 0) { ... }`)";

} // namespace

CountDown count_down(const clang::Expr* cond) {
  if (!cond)
    return {};
  // `i--` or `--i` of an integer local: the counter, and whether it is tested before the step
  const auto decrement = [](const clang::Expr* e, bool& post) -> const VarDecl* {
    const auto* u = dyn_cast<UnaryOperator>(e->IgnoreParenImpCasts());
    if (!u || (u->getOpcode() != UO_PostDec && u->getOpcode() != UO_PreDec))
      return nullptr;
    post = u->getOpcode() == UO_PostDec;
    return stepped(u);
  };
  bool post = false;
  if (const VarDecl* v = decrement(cond, post)) // `i--`, `--i`: the test is != 0
    return !post && v->getType()->isUnsignedIntegerType() ? CountDown{}
                                                          : CountDown{v, nullptr, post ? 0 : 1};
  const auto* c = dyn_cast<BinaryOperator>(cond->IgnoreParenImpCasts());
  if (!c)
    return {};
  BinaryOperatorKind op = c->getOpcode();
  const clang::Expr* counter_side = c->getLHS();
  const clang::Expr* bound = c->getRHS();
  if (op == BO_LT || op == BO_LE) // `lo < i--`: as `i-- > lo`
    std::swap(counter_side, bound), op = op == BO_LT ? BO_GT : BO_GE;
  if (op == BO_NE && !decrement(counter_side, post)) // `lo != i--`
    std::swap(counter_side, bound);
  const VarDecl* v = decrement(counter_side, post);
  if (!v || (op != BO_GT && op != BO_GE && op != BO_NE) ||
      (!post && v->getType()->isUnsignedIntegerType()))
    return {};
  // the lowest value the body sees: the last tested value (post) or the stepped one (pre)
  const int offset = post ? (op == BO_GE ? -1 : 0) : (op == BO_GE ? 0 : 1);
  return {v, bound, offset, c, post};
}

const clang::Expr* self_step(const BinaryOperator* a, const VarDecl*& var, bool& adds) {
  const auto* lhs = dyn_cast<DeclRefExpr>(a->getLHS()->IgnoreParenImpCasts());
  const auto* b = dyn_cast<BinaryOperator>(a->getRHS()->IgnoreParenImpCasts());
  if (a->getOpcode() != BO_Assign || !lhs || !isa<VarDecl>(lhs->getDecl()) || !b ||
      (b->getOpcode() != BO_Add && b->getOpcode() != BO_Sub))
    return nullptr;
  const auto same = [&](const clang::Expr* x) {
    const auto* r = dyn_cast<DeclRefExpr>(x->IgnoreParenImpCasts());
    return r && r->getDecl() == lhs->getDecl();
  };
  const clang::Expr* amount = same(b->getLHS())                               ? b->getRHS()
                              : b->getOpcode() == BO_Add && same(b->getRHS()) ? b->getLHS()
                                                                              : nullptr;
  var = llvm::cast<VarDecl>(lhs->getDecl());
  adds = b->getOpcode() == BO_Add;
  return amount;
}

// Which statement of the body steps the counter: the last one, or, in a run of steps that
// ends the body (`++i; ++j;`), the one that steps a counter of the condition, where the steps
// after it neither read that counter nor are read by its step (so it may run last). -1: none.
static int step_statement(const WhileStmt* w) {
  const auto* body = dyn_cast_or_null<CompoundStmt>(w->getBody());
  if (!body || body->body_empty())
    return -1;
  const std::vector<const Stmt*> stmts(body->body_begin(), body->body_end());
  const int last = static_cast<int>(stmts.size()) - 1;
  for (int k = last; k >= 0 && stepped(stmts[k]); --k) {
    const VarDecl* v = stepped(stmts[k]);
    if (!LoopHeaders::mentions(w->getCond(), v))
      continue;
    bool commutes = true;
    for (int later = k + 1; later <= last; ++later)
      commutes = commutes && !LoopHeaders::mentions(stmts[later], v) &&
                 !LoopHeaders::mentions(stmts[k], stepped(stmts[later]));
    return commutes ? k : last;
  }
  return stepped(stmts[last]) ? last : -1;
}

const VarDecl* while_counter(const WhileStmt* w) {
  if (const VarDecl* v = counted_down(w->getCond()))
    return v;
  const int k = step_statement(w);
  return k < 0 ? nullptr : stepped(*(llvm::cast<CompoundStmt>(w->getBody())->body_begin() + k));
}

const ForStmt* while_as_for(ASTContext& ctx, const WhileStmt* w, const WhileFail& fail) {
  const auto refuse = [&](SourceLocation at, const std::string& msg) {
    fail(at, msg);
    throw Rejected{}; // (fail does not return)
  };
  if (w->getConditionVariable())
    refuse(w->getBeginLoc(),
           fmt::format("{}; not one that declares a variable in its condition", kForm));
  const VarDecl* v = while_counter(w);
  if (!v) {
    // A counter of the condition stepped by another statement than the last: say which.
    if (const auto* c = dyn_cast_or_null<CompoundStmt>(w->getBody()))
      for (const Stmt* s : c->body())
        if (const VarDecl* u = stepped(s); u && LoopHeaders::mentions(w->getCond(), u))
          refuse(s->getBeginLoc(),
                 fmt::format("{}; this statement steps the counter '{}' before the end of the "
                             "body: move the step to the end (adjusting the start and the uses "
                             "of '{}'), or write the loop as a for loop",
                             kForm, u->getNameAsString(), u->getNameAsString()));
    if (const VarDecl* u = unsigned_pre_decrement(w->getCond()))
      refuse(w->getCond()->getBeginLoc(), pre_decrement_message(u));
    refuse(w->getBeginLoc(), kForm);
  }
  if (isa<ParmVarDecl>(v))
    refuse(w->getBeginLoc(),
           fmt::format("the counter '{}' of this while loop is a parameter of the kernel, which "
                       "the loop would change: count a local copy (`int i = {}; while (i-- > "
                       "0) ...`)",
                       v->getNameAsString(), v->getNameAsString()));
  // The body without its last statement, which becomes the for loop's increment; or, counted
  // down by the condition, the body as it is (a `continue` there runs the same in both).
  Stmt* body = const_cast<Stmt*>(w->getBody());
  Stmt* step = nullptr;
  if (counted_down(w->getCond()) != v) {
    // (a compound statement: while_counter found the step in it)
    const auto* c = llvm::cast<CompoundStmt>(w->getBody());
    std::vector<Stmt*> stmts;
    for (const Stmt* s : c->body())
      stmts.push_back(const_cast<Stmt*>(s));
    const int step_at = step_statement(w);
    step = stmts[static_cast<std::size_t>(step_at)];
    stmts.erase(stmts.begin() + step_at);
    for (Stmt* s : stmts)
      if (const ContinueStmt* k = own_continue(s))
        refuse(k->getBeginLoc(),
               fmt::format("'continue' in a while loop skips the step of its counter '{}' at "
                           "the end of the body (a for loop would still run it): write the loop "
                           "as a for loop, or the skipped part as an if/else",
                           v->getNameAsString()));
    body =
        CompoundStmt::Create(ctx, stmts, FPOptionsOverride(), c->getLBracLoc(), c->getRBracLoc());
  }
  const SourceLocation at = w->getBeginLoc();
  QualType type = v->getType().getNonReferenceType();
  auto* lhs = DeclRefExpr::Create(ctx, NestedNameSpecifierLoc(), SourceLocation(),
                                  const_cast<VarDecl*>(v), false, at, type, VK_LValue);
  auto* rhs = ImplicitCastExpr::Create(
      ctx, type.getUnqualifiedType(), CK_LValueToRValue,
      DeclRefExpr::Create(ctx, NestedNameSpecifierLoc(), SourceLocation(), const_cast<VarDecl*>(v),
                          false, at, type, VK_LValue),
      nullptr, VK_PRValue, FPOptionsOverride());
  auto* init = BinaryOperator::Create(ctx, lhs, rhs, BO_Assign, type, VK_LValue, OK_Ordinary, at,
                                      FPOptionsOverride());
  return new (ctx) ForStmt(ctx, init, const_cast<clang::Expr*>(w->getCond()), nullptr,
                           step ? llvm::cast<clang::Expr>(step)->IgnoreParens() : nullptr, body,
                           w->getWhileLoc(), w->getLParenLoc(), w->getRParenLoc());
}

} // namespace dpgen::lowering
