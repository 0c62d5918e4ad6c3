// Lowering, `while` loops that count (lower_while.cpp): read as the `for` loop they are.
// Included by the lowering's files that meet a `while` (lower_stmt.cpp, lower_buffer.cpp).
#pragma once

#include <clang/Basic/SourceLocation.h>

#include <functional>
#include <string>

namespace clang {
class ASTContext;
class BinaryOperator;
class Expr;
class ForStmt;
class VarDecl;
class WhileStmt;
} // namespace clang

namespace dpgen::lowering {

/// `i = i + s`, `i = s + i`, `i = i - s`: the amount `s`, with `i` in `var` and whether it
/// adds in `adds`; null for any other expression. (A step as C codes spell it out.)
const clang::Expr* self_step(const clang::BinaryOperator* a, const clang::VarDecl*& var,
                             bool& adds);

/// A `while` loop's counter where the loop counts: stepped by the body's last statement
/// (`while (i < n) { ...; ++i; }`) or counted down by the condition (`while (i-- > lo)`);
/// null for any other `while`.
const clang::VarDecl* while_counter(const clang::WhileStmt* w);

/// Reports a `while` loop outside the subset (the lowering's fail, which does not return).
using WhileFail = std::function<void(clang::SourceLocation, const std::string&)>;

/// The `for` statement that loop is, `for (i = i; cond; step) body` (the body without the
/// step), built from its parts in `ctx`; `fail` for any other `while`.
const clang::ForStmt* while_as_for(clang::ASTContext& ctx, const clang::WhileStmt* w,
                                   const WhileFail& fail);

} // namespace dpgen::lowering
