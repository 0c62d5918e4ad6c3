// Lowering, loops (lower_loop.cpp, lower_loop_header.cpp): two parts of the
// lowering. LoopHeaders reads a `for` statement's header (its counter, range,
// step, the triangle or stride that makes it rectangular) and does the index
// algebra over the enclosing loops (hulls, lower bounds); ForLoops lowers the
// loop itself: unrolled when small, else a Loop of the nest with its
// accumulators and the variables it assigns. Everything else they need (the
// environment, the path, statements and expressions) they reach through `L`.
// Included by lower_impl.hpp only.
#pragma once

#include "affine.hpp"
#include "lower_common.hpp"

#include <clang/AST/OperationKinds.h>

#include <optional>
#include <set>
#include <utility>
#include <vector>

namespace clang {
class BinaryOperator;
class CXXRecordDecl;
class Expr;
class ForStmt;
class Stmt;
class VarDecl;
} // namespace clang

namespace dpgen::lowering {

class Lowerer;

// A `for` statement's header: the counter, its range [lo, hi) and step; for
// a triangular nest the original bounds (made conditions on the body's path:
// (bound, is the upper one)); for a strided loop whose start moves with outer
// counters, that start and the step (the body runs where counter >= start
// and (counter - start) % step == 0).
struct ForHeader {
  const clang::VarDecl* var = nullptr;
  ExprP lo, hi;
  int step = 1;
  std::vector<std::pair<ExprP, bool>> triangle;
  ExprP parity_start;
  int parity_step = 0;
};

class LoopHeaders {
public:
  explicit LoopHeaders(Lowerer& lowerer) : L(lowerer) {}

  ForHeader for_header(const clang::ForStmt* f);

  // An integer expression for a polynomial over parameters and kernel-level
  // locals (symbols resolve to what they name).
  ExprP poly_expr(const Poly& p);
  ExprP symbol_expr(const Sym& sym);

  // The extreme (the largest if `upper`, else the smallest) of loop bound `e`
  // (`p` as a polynomial) over the enclosing loops' ranges: each outer counter
  // replaced by its first or last value, by the sign of its coefficient. Null
  // where a coefficient is not a constant.
  std::optional<ExprP> hull(const ExprP& e, const Poly& p, bool upper) const;

  // A lower bound of integer `e` over the enclosing loops that depends on the
  // sizes only: `e` itself where it mentions no counter, the hull of an
  // affine part, 0 for `x % m` with a constant m > 0 and x >= 0 (C's
  // remainder of a non-negative value), sums of those. Null otherwise.
  std::optional<ExprP> smallest(const ExprP& e) const;

  // The `i = lo` of a C89-style loop, if that is its init statement.
  static const clang::BinaryOperator* init_assignment(const clang::ForStmt* f);

private:
  Lowerer& L;

  // The bound of a loop condition as `counter op bound` (op returned in `op`):
  // `i < n`, `i + 1 < n` (i < n - 1), `n > i` (i < n). Null when the sides do
  // not differ by exactly +-counter plus something free of the counter.
  ExprP loop_bound(const clang::BinaryOperator* c, const clang::VarDecl* var,
                   clang::BinaryOperatorKind& op);

  int loop_step(const clang::Expr* inc, const clang::VarDecl* var);
};

class ForLoops {
public:
  explicit ForLoops(Lowerer& lowerer) : L(lowerer) {}

  void for_loop(const clang::ForStmt* f);

  // Every local variable assigned (=, op=, ++, --) somewhere in `s`.
  void assigned_vars(const clang::Stmt* s, std::set<const clang::VarDecl*>& out);

  // A counter the loop body assigns is refused.
  void check_not_assigned(const clang::Stmt* s, const clang::VarDecl* var);

private:
  Lowerer& L;

  // A loop with constant bounds and at most 16 iterations that touches a
  // local array or assigns a variable declared outside it (`s += w[m] *
  // a[i + m]`) is unrolled: its counter is a constant in each copy.
  bool should_unroll(const clang::ForStmt* f, long long lo, long long hi);
  bool unroll(const clang::ForStmt* f, const ForHeader& h);

  // A local (or local array) assigned in a loop has no single value after
  // it: forgets it. False if `v` is no such variable.
  bool forget_value(const clang::VarDecl* v);

  std::set<const clang::CXXRecordDecl*> lambdas_seen_; // (assigned_vars: no endless recursion)
};

} // namespace dpgen::lowering
