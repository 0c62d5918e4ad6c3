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

#include <memory>
#include <optional>
#include <set>
#include <utility>
#include <vector>

namespace clang {
class BinaryOperator;
class CXXRecordDecl;
class Expr;
class ForStmt;
class UnaryOperator;
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
  // A strided loop whose start moves with outer counters, run as a unit-step
  // loop over the starts' hull: its start, its step (negative counting down)
  ExprP parity_start;
  int parity_step = 0;
  // Companion counters (`for (i = 0, j = n - 1; i < n; ++i, --j)`): in the
  // body, init + step * (the iteration's number, from 0)
  struct Companion {
    const clang::VarDecl* var = nullptr;
    ExprP init;
    int step = 0;
    bool is_unsigned = false; // (must provably stay >= 0 in the body)
    const clang::Expr* inc = nullptr;
  };
  std::vector<Companion> companions;
  ExprP first; // the counter's first value, as the body may name it
  // The variables the body assigns (ForLoops::assigned_vars: helpers' references and lambdas
  // capturing by reference included), found once for the condition's check and the body.
  std::set<const clang::VarDecl*> assigned;
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

  // A lower (`upper`: an upper) bound of integer `e` over the enclosing
  // loops that depends on the sizes only: `e` itself where it mentions no
  // counter, the hull of an affine part, 0 (m - 1) for `x % m` with a
  // constant m > 0 and x >= 0 (C's remainder of a non-negative value), sums
  // and differences of those. Null otherwise.
  std::optional<ExprP> extreme(const ExprP& e, bool upper) const;

  // Whether `s` names variable `v`.
  static bool mentions(const clang::Stmt* s, const clang::VarDecl* v);

private:
  Lowerer& L;

  // The bound of a loop condition as `counter op bound` (op returned in `op`):
  // `i < n`, `i + 1 < n` (i < n - 1), `n > i` (i < n). Null when the sides do
  // not differ by exactly +-counter plus something free of the counter.
  ExprP loop_bound(const clang::BinaryOperator* c, const clang::VarDecl* var,
                   clang::BinaryOperatorKind& op);

  int loop_step(const clang::Expr* inc, const clang::VarDecl* var);
  const clang::VarDecl* stepped_local(const clang::Expr* e) const;
};

// Running indices (lower_induction.cpp): an integer local declared before a
// loop and stepped in its body (`b[idx] = ...; idx++;`), in closed form in
// each iteration: its value before the loop plus the iteration's number times
// its step per iteration (a kernel-level local, `<v>_per_<counter>`).
class RunningIndices {
public:
  explicit RunningIndices(Lowerer& lowerer) : L(lowerer) {}

  struct Induction {
    const clang::VarDecl* var = nullptr;
    ExprP entry, start;            // its value before the loop, at an iteration's start
    std::shared_ptr<LocalVar> per; // its step per iteration (defined by end_body)
    bool is_unsigned = false;
    bool enclosed = false; // an enclosing loop steps it too
  };
  // Before loop `f`'s body (`trip`: the iteration's number from 0): the
  // running indices among `assigned` (which loses them) get their closed form.
  std::vector<Induction> begin(const clang::ForStmt* f, const ForHeader& h, const Loop& loop,
                               const ExprP& trip, std::set<const clang::VarDecl*>& assigned);
  // After the body: each one's step per iteration, from its value there.
  void end_body(const clang::ForStmt* f, std::vector<Induction>& inductions);
  // After the loop: each one's value past it, where that is a value.
  void end(const std::vector<Induction>& inductions, const Loop& loop);

  // Expression statement `e` with steps inside it (`b[idx++] = x`), lowered;
  // false where it has none. The steps the expression being lowered reads
  // as their variable's value:
  bool lower_inner_steps(const clang::Expr* e);
  std::set<const clang::UnaryOperator*> inline_steps_;

private:
  Lowerer& L;
  bool steps_only(const clang::Stmt* body, const clang::VarDecl* v, bool& read, bool& up);
  std::set<const clang::VarDecl*> active_; // stepped by a loop being lowered
  // stepped by an inner loop that may not have run (end: no value after the nest)
  std::set<const clang::VarDecl*> unproved_;
};

class ForLoops {
public:
  explicit ForLoops(Lowerer& lowerer) : L(lowerer) {}

  void for_loop(const clang::ForStmt* f);
  // `for (double w : weights)` over a local array (a C array or std::array,
  // whose elements dpgen keeps as values): unrolled, the variable bound to
  // each element in turn.
  void range_for(const clang::CXXForRangeStmt* f);

  // Every local variable assigned (=, op=, ++, --) somewhere in `s`.
  void assigned_vars(const clang::Stmt* s, std::set<const clang::VarDecl*>& out);

  // A counter the loop body assigns is refused.
  void check_not_assigned(const clang::Stmt* s, const clang::VarDecl* var);

private:
  Lowerer& L;

  // A loop with constant bounds and at most 16 iterations that touches a
  // local array or assigns a variable declared outside it (`s += w[m] *
  // a[i + m]`) is unrolled: its counter is a constant in each copy.
  bool should_unroll(const clang::ForStmt* f, const ForHeader& h, long long lo, long long hi);
  bool unroll(const clang::ForStmt* f, const ForHeader& h);
  // One copy of an unrolled loop's body (the path back at `depth` after it).
  void lower_copy(const clang::Stmt* body, size_t depth);
  // After loop `h` (`before`: the bindings before it): its counters declared
  // in its header are gone; one declared before it (C89) is no value.
  void counters_after(const ForHeader& h, const std::map<const clang::VarDecl*, Binding>& before);
  // An unsigned companion counting down must provably stay >= 0 in the body
  // (`value` there); refused otherwise.
  void check_stays_nonneg(const ForHeader::Companion& c, const ExprP& value,
                          const clang::VarDecl* counter);

  // A local (or local array) assigned in a loop has no single value after
  // it: forgets it. False if `v` is no such variable.
  bool forget_value(const clang::VarDecl* v);

  std::set<const clang::CXXRecordDecl*> lambdas_seen_; // (assigned_vars: no endless recursion)

public:
  RunningIndices running_{L};
};

} // namespace dpgen::lowering
