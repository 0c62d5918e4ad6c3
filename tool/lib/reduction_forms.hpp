// Lowering, the forms of reductions (reduction_forms.cpp): which statements
// of a loop body update an accumulator (`s += e`, `s = s + e`) or a min/max
// reduction (`m = std::max(m, e)`, `fmin`, a `?:` of m and e, `if (e > m) m =
// e;`), and of what. Pure syntax over Clang's AST, no state of the lowering;
// the Reductions part (lower_reduce.hpp) lowers what it finds. Included by
// lower_impl.hpp only.
#pragma once

#include <clang/AST/Type.h>

#include <optional>
#include <set>
#include <utility>
#include <vector>

namespace clang {
class ASTContext;
class CallExpr;
class Expr;
class FunctionDecl;
class IfStmt;
class SourceManager;
class Stmt;
class ValueDecl;
class VarDecl;
} // namespace clang

namespace dpgen::lowering {

// What a min/max reduction updates: a local `v`, or an output element
// (`*err`, `err[0]`, `rowmax[j]`: `element`, of array `decl`) at the same
// index in every iteration of the reducing loop.
struct ReductionTarget {
  const clang::ValueDecl* decl = nullptr;
  const clang::Expr* element = nullptr;
};

class ReductionForms {
public:
  ReductionForms(clang::ASTContext& ctx, clang::SourceManager& sm) : ctx_(ctx), sm_(sm) {}

  // The terms of `v = v + e`, `v = v - e`, `v = e + v` and of a chain `v = v + e - f`
  // (v the leftmost operand), each with its sign (negate) in the order C++ adds them, none
  // mentioning v; empty for any other form.
  static std::vector<std::pair<const clang::Expr*, bool>>
  accumulated_terms(const clang::Expr* rhs, const clang::VarDecl* v);
  // The terms of `x = x + e`, `x = x - e`, `x = e + x` and of a chain `x = x + e - f + ...`
  // (x the leftmost operand), each with its sign (negate), in the order C++ adds them; false
  // for any other form, for an `x` that may change something as it is evaluated
  // (`out[k++]`), and for a chain whose terms mention x's variable (they would see x as it
  // was before the statement, not as the sum so far).
  bool self_update_terms(const clang::Expr* lhs, const clang::Expr* rhs,
                         std::vector<std::pair<const clang::Expr*, bool>>& terms) const;
  // The elements of call `c`'s one argument where it is an initializer list (`std::max({a, b,
  // c})`: a, b, c); empty for any other call.
  static std::vector<const clang::Expr*> list_elements(const clang::CallExpr* c);
  // `s` mentions `v`.
  static bool mentions(const clang::Stmt* s, const clang::ValueDecl* v);
  // Every mention of `v` in `body` is the target of `v += e`, `v -= e` or
  // `v = v + e` (`v = v + e - f`: accumulated_terms; and its `v`), with `e`
  // free of v, and there is at least one.
  static bool is_accumulator(const clang::Stmt* body, const clang::VarDecl* v);

  // The same expression, up to parentheses and implicit conversions.
  bool same_expr(const clang::Expr* a, const clang::Expr* b) const;
  bool is_target(const clang::Expr* e, const ReductionTarget& t) const;
  // The target of assignment `lhs`: a variable, or an element of an array
  // parameter (`*p`, `p[...]`); decl null for anything else.
  static ReductionTarget target_of(const clang::Expr* lhs);
  // The term `e` of a min/max update of `t` (`v = std::max(v, e)`, `v =
  // fmin(e, v)`, `v = v > e ? v : e`, ...), with `extremum` +1 for max and
  // -1 for min; null for any other form.
  // `v = std::max({v, e1, e2})`: e1, its further terms (e2) in `more` where given.
  const clang::Expr* extremum_term(const clang::Expr* rhs, const ReductionTarget& t, int& extremum,
                                   std::vector<const clang::Expr*>* more = nullptr) const;
  // `if (e > v) v = e;` (no else; the body the one assignment): its `e`,
  // target and kind; null for any other if.
  // `extra`: where the if's condition is `<comparison> && rest` (`if (e > m
  // && i > 0)`), `rest`, the condition the update runs under (null for a
  // plain comparison); with no `extra`, such an if is no update.
  const clang::Expr* extremum_if(const clang::IfStmt* s, ReductionTarget& t, int& extremum,
                                 const clang::Expr** extra = nullptr) const;
  // +1 or -1 if every mention of `t.decl` in `body` is in a min/max update of
  // `t` of one kind, and there is at least one; 0 otherwise.
  int extremum_kind(const clang::Stmt* body, const ReductionTarget& t) const;
  // (`open`: the lambda and helper bodies being visited)
  int extremum_kind(const clang::Stmt* body, const ReductionTarget& t,
                    std::set<const clang::Stmt*>& open) const;

private:
  // `*p` (element 0) or `p[c]` of a parameter p at an integer constant c.
  std::optional<std::pair<const clang::ValueDecl*, long long>>
  constant_element(const clang::Expr* e) const;
  bool same_type(clang::QualType e, const ReductionTarget& t) const;
  // +1 / -1 if helper `f` is a max / min of its two parameters, else 0.
  int helper_extremum(const clang::FunctionDecl* f) const;
  // Two elements of one parameter at different constant indices.
  bool apart(const clang::Expr* a, const clang::Expr* b) const;

  clang::ASTContext& ctx_;
  clang::SourceManager& sm_;
  mutable int helper_depth_ = 0; // (helper_extremum of nested helpers)
};

} // namespace dpgen::lowering
