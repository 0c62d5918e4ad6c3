// Lowering, integer arithmetic as the kernel computes it (lower_int.hpp):
// where the kernel's own integers may wrap (unsigned below zero, a negative
// value converted to unsigned) or truncate, and the generated code's signed
// 64-bit arithmetic would differ, the kernel is rejected unless the value
// provably stays in range; a 32-bit index of three sizes is a warning.
#include "lower_impl.hpp"

namespace dpgen::lowering {

// The value of `e` only goes into an array index (through + - * and
// conversions): if it wraps, the kernel itself reads out of bounds.
bool IntegerChecks::feeds_index_only(const clang::Expr* e) {
  const clang::Stmt* child = e;
  for (int depth = 0; depth < 32; ++depth) {
    auto parents = L.ctx_.getParents(*child);
    if (parents.size() != 1)
      return false;
    const clang::Stmt* up = parents[0].get<clang::Stmt>();
    if (!up)
      return false;
    if (const auto* sub = dyn_cast<ArraySubscriptExpr>(up))
      return sub->getIdx()->IgnoreParenImpCasts() == child ||
             sub->getIdx() == child;
    if (const auto* oc = dyn_cast<CXXOperatorCallExpr>(up))
      return oc->getOperator() == OO_Subscript && oc->getNumArgs() == 2 &&
             oc->getArg(1)->IgnoreParenImpCasts() ==
                 static_cast<const clang::Expr*>(child)->IgnoreParenImpCasts();
    if (const auto* b = dyn_cast<BinaryOperator>(up)) {
      if (b->getOpcode() != BO_Add && b->getOpcode() != BO_Sub && b->getOpcode() != BO_Mul)
        return false;
    } else if (const auto* c = dyn_cast<ConditionalOperator>(up)) {
      // an arm (`i == 0 ? n - 1 : i - 1`): taken only where it is the index
      if (c->getCond() == child || c->getCond()->IgnoreParenImpCasts() == child)
        return false;
    } else if (!isa<ParenExpr>(up) && !isa<ImplicitCastExpr>(up)) {
      return false;
    }
    child = up;
  }
  return false;
}

// The conditions of the ternaries `e` is an arm of (`i == 0 ? n - 1 : i - 1`).
std::vector<PathCond> IntegerChecks::arm_conditions(const clang::Expr* e) {
  std::vector<PathCond> out;
  const clang::Stmt* child = e;
  for (int depth = 0; depth < 32; ++depth) {
    auto parents = L.ctx_.getParents(*child);
    if (parents.size() != 1)
      break;
    const clang::Stmt* up = parents[0].get<clang::Stmt>();
    if (!up || !isa<clang::Expr>(up))
      break;
    if (const auto* c = dyn_cast<ConditionalOperator>(up)) {
      bool in_true = c->getTrueExpr() == child, in_false = c->getFalseExpr() == child;
      if (in_true || in_false)
        out.push_back({L.exprs_.cond(c->getCond()), in_true});
    }
    child = up;
  }
  return out;
}

void IntegerChecks::check_unsigned_result(const ExprP& value, SourceLocation loc, const std::string& what, const clang::Expr* node) {
  if (L.in_loop_bounds_ || feeds_index_only(node) || L.provably_nonneg(value) ||
      L.provably_nonneg(value, arm_conditions(node)))
    return;
  L.fail(loc, fmt::format("{} may go below zero here, where the kernel's unsigned arithmetic "
                        "wraps around but dpgen's index arithmetic (signed, 64 bits) does not: "
                        "compute it in a signed type, or guard it so that it stays >= 0 (dpgen "
                        "proves that from the loop bounds and the conditions around it)",
                        what));
}

// The value of integer constant `v` (unsigned ones are not negative: a
// 32-bit 3000000000u is 3000000000); one past the range of long long, which
// dpgen's integers are, is refused.
long long IntegerChecks::constant(const llvm::APSInt& v, SourceLocation loc) {
  if (v.isUnsigned() ? v.getActiveBits() > 63 : v.getSignificantBits() > 64)
    L.fail(loc, fmt::format("this integer constant ({} bits) is outside the range of long long, "
                            "in which dpgen computes integers",
                            v.getActiveBits()));
  return v.isUnsigned() ? static_cast<long long>(v.getZExtValue()) : v.getSExtValue();
}

// Unsigned arithmetic with a constant of 2^31 or more (`i * 2654435761u`, a
// hash; `i + 4294967295u`, i - 1 modulo 2^32): it wraps past the type's
// maximum where dpgen's signed 64-bit arithmetic does not.
void IntegerChecks::check_unsigned_constant(BinaryOperatorKind op, SourceLocation loc,
                                            const std::string& text, const ExprP& l,
                                            const ExprP& r) {
  if (BinaryOperator::isCompoundAssignmentOp(op)) // (`h *= 2654435761u` as `h * ...`)
    op = BinaryOperator::getOpForCompoundAssignment(op);
  if (op != BO_Add && op != BO_Mul && op != BO_Shl && op != BO_Sub)
    return;
  for (const ExprP& x : {l, r})
    if (auto c = int_value(x); c && *c >= (1LL << 31)) // (also through a local: `K`)
      L.fail(loc, fmt::format("unsigned arithmetic '{}' with the constant {} may wrap around past "
                              "the type's largest value (a hash, or a subtraction written as an "
                              "addition), where dpgen's index arithmetic (signed, 64 bits) does "
                              "not; outside the kernel subset",
                              text, *int_value(x)));
}

// An index that multiplies three or more sizes and counters (a 3D
// `(l*ny + j)*nx + i`) passes 2^31 on grids of 1290^3 cells: computed in a
// 32-bit type it overflows, in the forward kernel and in its adjoint alike.
void IntegerChecks::check_index_width(const clang::Expr* e, const ExprP& idx, const std::string& array) {
  QualType t = e->IgnoreImpCasts()->getType();
  if (L.ctx_.getTypeSize(t) >= 64)
    return;
  auto p = to_poly(idx);
  if (!p || p->degree() < 3)
    return;
  // The forward kernel has the same limit; the adjoint computes its indices
  // in 64 bits, so this is a warning about the user's code, not an error.
  if (warned_width_)
    return; // once per kernel
  warned_width_ = true;
  auto& d = L.ctx_.getDiagnostics();
  unsigned id = d.getCustomDiagID(DiagnosticsEngine::Warning, "%0");
  d.Report(e->getBeginLoc(), id)
      << fmt::format("index of '{}' is computed in the {}-bit type '{}' but multiplies {} sizes "
                     "and counters ('{}'): past 2^31 elements it overflows in this kernel (the "
                     "generated adjoint computes it in 64 bits); compute it in std::ptrdiff_t "
                     "or long [dpgen-index-width]",
                     array, L.ctx_.getTypeSize(t), t.getAsString(), p->degree(), p->str());
}

} // namespace dpgen::lowering
