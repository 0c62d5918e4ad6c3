// Lowering, guards (lower_guard.cpp): a part of the lowering. Values are
// made under the conditions of the path (an arm, a helper's branch, an
// operand C++ evaluates only under a condition), but the generated code may
// compute them where those conditions fail: merged past an arm into a select,
// or as the operand of a select it evaluates whole. Guards gives such values
// copies that are safe to evaluate anywhere. Included by lower_impl.hpp only.
#pragma once

#include "lower_common.hpp"

#include <functional>
#include <map>
#include <optional>
#include <utility>

namespace clang {
class Expr;
} // namespace clang

namespace dpgen::lowering {

class Lowerer;

class Guards {
public:
  explicit Guards(Lowerer& lowerer) : L(lowerer) {}

  // `lower()` of an operand C++ evaluates only under a condition (a `?:` arm,
  // the right side of `&&` / `||`), on Lowerer::cond_operands_ while it runs,
  // with `holds` (if any) on the path.
  ExprP conditional(const clang::Expr* operand, std::optional<PathCond> holds,
                    const std::function<ExprP()>& lower);

  // `e`, a value made in an arm, for use past the arm where the path has
  // only its first `depth` conditions (merged into a select on the others:
  // `b[i] = 0; if (i > 0) { double d = a[i - 1]; b[i] = d * d; }`): the locals
  // made under more conditions replaced by copies guarded by those
  // conditions, so nothing of the arm reads out of bounds where it does not
  // run. (A helper's return values past its ifs alike.)
  ExprP guarded(const ExprP& e, size_t depth);

private:
  Lowerer& L;
  std::map<std::pair<int, size_t>, ExprP> guarded_; // by local id and depth

  // guarded(v, depth) where a local made since `first_local` may fault: the
  // value of a conditional operand.
  ExprP guarded_operand(const ExprP& v, size_t depth, int first_local);
};

} // namespace dpgen::lowering
