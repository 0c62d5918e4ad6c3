// Lowering, integer arithmetic as the kernel computes it (lower_int.cpp): a
// part of the lowering. Integer arithmetic in the generated code is signed
// and 64 bits wide; the kernel's own may wrap (unsigned below zero, a
// negative value converted to unsigned) or truncate (to short or char).
// Where the two could differ the kernel is rejected, unless the value
// provably stays in range (loop bounds are exempt: where they differ the
// forward loop itself runs ~2^64 times). Included by lower_impl.hpp only.
#pragma once

#include "lower_common.hpp"

#include <string>
#include <vector>

namespace clang {
class Expr;
} // namespace clang

namespace dpgen::lowering {

class Lowerer;

class IntegerChecks {
public:
  explicit IntegerChecks(Lowerer& lowerer) : L(lowerer) {}

  // `value`, the result of `node` (`what` in messages) in the kernel's
  // unsigned arithmetic, does not go below zero here: an error unless it
  // provably does not, or only feeds an index (where a wrap would make the
  // kernel itself read out of bounds), or is a loop bound.
  void check_unsigned_result(const ExprP& value, clang::SourceLocation loc,
                             const std::string& what, const clang::Expr* node);
  // An index that multiplies three or more sizes and counters (a 3D
  // `(l*ny + j)*nx + i`) passes 2^31 on grids of 1290^3 cells: computed in a
  // 32-bit type it overflows, in the forward kernel and in its adjoint alike
  // (a warning, once per kernel).
  void check_index_width(const clang::Expr* e, const ExprP& idx, const std::string& array);
  // The value of integer constant `v` (unsigned ones are not negative); one
  // outside the range of long long is refused (at `loc`).
  long long constant(const llvm::APSInt& v, clang::SourceLocation loc);
  // Unsigned `+`, `-`, `*` or `<<` (operands lowered to `l`, `r`) with
  // a constant of 2^31 or more: it may wrap past the type's maximum, which
  // dpgen's signed 64-bit arithmetic does not; refused.
  // (`op` may be a compound assignment, `h *= c`; `text` the operation as written)
  void check_unsigned_constant(clang::BinaryOperatorKind op, clang::SourceLocation loc,
                               const std::string& text, const ExprP& l, const ExprP& r);

private:
  Lowerer& L;

  // The value of `e` only goes into an array index (through + - * and
  // conversions): if it wraps, the kernel itself reads out of bounds.
  bool feeds_index_only(const clang::Expr* e);
  // The conditions of the ternaries `e` is an arm of (`i == 0 ? n - 1 : i - 1`).
  std::vector<PathCond> arm_conditions(const clang::Expr* e);
  bool warned_width_ = false;
};

} // namespace dpgen::lowering
