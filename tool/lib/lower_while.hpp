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

/// A condition that tests a counter and steps it down by one: `i-- > lo`, `lo < i--`,
/// `i-- >= lo`, `i-- != lo`, `i--` alone; for a signed counter also `--i >= lo`, `--i > lo`,
/// `--i != lo`. The body sees i from its start - 1 down to `bound` + `offset` (`bound` null:
/// 0); `test` is the comparison (null for `i--` alone). A start below that (where `!=` and the
/// truth test would run until the counter wraps) is outside what a kernel may do. `var` is
/// null for any other condition.
struct CountDown {
  const clang::VarDecl* var = nullptr;
  const clang::Expr* bound = nullptr;
  int offset = 0;
  const clang::BinaryOperator* test = nullptr;
  bool post = true; // tested before the step; else the last value tested is the lowest - 1
};
CountDown count_down(const clang::Expr* cond);

/// `--k` of an unsigned local in a condition (`--k > 0`, `0 < --k`, `--k`), else null; and the
/// message that refuses it (at 0 it wraps instead of ending the loop).
const clang::VarDecl* unsigned_pre_decrement(const clang::Expr* cond);
std::string pre_decrement_message(const clang::VarDecl* u);

/// A `while` loop's counter where the loop counts: stepped by the body's last statement
/// (`while (i < n) { ...; ++i; }`) or counted down by the condition (`while (i-- > lo)`,
/// count_down); null for any other `while`.
const clang::VarDecl* while_counter(const clang::WhileStmt* w);

/// Reports a `while` loop outside the subset (the lowering's fail, which does not return).
using WhileFail = std::function<void(clang::SourceLocation, const std::string&)>;

/// The `for` statement that loop is, `for (i = i; cond; step) body` (the body without the
/// step), built from its parts in `ctx`; `fail` for any other `while`.
const clang::ForStmt* while_as_for(clang::ASTContext& ctx, const clang::WhileStmt* w,
                                   const WhileFail& fail);

} // namespace dpgen::lowering
