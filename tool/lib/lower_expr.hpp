// Lowering, expressions (lower_expr.cpp): a part of the lowering. A Clang
// expression becomes an IR expression: arithmetic, conversions, variables
// (their bindings), calls of math functions and inlined helpers, and array
// elements (an input's read, an output's visible store, a work array's
// read). Everything else it needs it reaches through `L`. Included by
// lower_impl.hpp only.
#pragma once

#include "lower_common.hpp"

#include <optional>

namespace clang {
class BinaryOperator;
class CallExpr;
class CastExpr;
class DeclRefExpr;
class Expr;
} // namespace clang

namespace dpgen::lowering {

class Lowerer;

class Expressions {
public:
  explicit Expressions(Lowerer& lowerer) : L(lowerer) {}

  ExprP expr(const clang::Expr* e);

  // `e` as a condition: compared with zero unless it is a bool.
  ExprP cond(const clang::Expr* e);

  // The array element `e` names (`a[i]`, `a[j][i]`, `v(i, j)`, `*p`), if it
  // names one.
  std::optional<Access> element(const clang::Expr* e);
  // u[j][i] of a `std::vector<std::vector<T>>&` parameter (`oc` the column's
  // operator[], `row` the row's).
  Access nested_element(const clang::CXXOperatorCallExpr* oc,
                        const clang::CXXOperatorCallExpr* row);

  const Param* array_base(const clang::Expr* base, ExprP* offset = nullptr);

private:
  Lowerer& L;

  ExprP cast_expr(const clang::CastExpr* c, const clang::Expr* sub);

  ExprP decl_ref(const clang::DeclRefExpr* r);

  ExprP binary_expr(const clang::BinaryOperator* b);

  ExprP call_expr(const clang::CallExpr* c);
};

} // namespace dpgen::lowering
