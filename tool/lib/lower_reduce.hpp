// Lowering, reductions: the scalar accumulators and min/max reductions of
// the loops being lowered. A part of the lowering with its own state (the
// reductions open in the enclosing loops) and a narrow interface: the loop
// lowering opens and closes a loop's reductions (begin_loop / end_loop), the
// statement lowering offers it each assignment and if that may update one
// (if_update, element_update, local_update: false where it is none). Everything else it needs from the lowering
// (expressions, stores, the loops and path around a statement) it reads
// through `L`. Included by lower_impl.hpp only.
#pragma once

#include "ir.hpp"
#include "reduction_forms.hpp"

#include <clang/AST/OperationKinds.h>
#include <clang/Basic/SourceLocation.h>

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace clang {
class Expr;
class ForStmt;
class IfStmt;
class Stmt;
class ValueDecl;
class VarDecl;
} // namespace clang

namespace dpgen::lowering {

class Lowerer;

// ---- scalar accumulators ------------------------------------------------
//
// `double s = 0; for (...) s += f(a[i]); out[0] = g(s);` and per-row sums:
// `s` becomes a hidden work array H (Kernel::hidden) with one element per
// iteration of the loops around the accumulating loop: `H[c] = <s before
// the loop>` there, `H[c] += f(...)` in the loop, and `s` after the loop is
// the work-array read H[c]. The output rules, the staged adjoint (which
// recomputes H) and the tangent then treat it like any work array.
//
// A min/max reduction (`m = std::max(m, e)`, fmax, a `?:` of m and e, or
// `if (e > m) m = e;` in a loop, `m` read after it) is exact in value, and
// its derivative goes to the elements equal to the extremum, split equally
// among ties (as torch.amax does; independent of the loop's order). Four
// hidden arrays per reduction, element c as for a sum:
//   S[c] = <m before the loop>                        start (differentiable)
//   M[c] = ng(S[c]);  in the loop M[c] max= ng(e)     the scan (constant)
//   T[c] = [S == M] + sum over the loop of [e == M]   the ties (constant)
//   R[c] = M + [S == M](S - M)/T + sum of [e == M](e - M)/T
// where ng() is dpgen_nograd and M, T are read through it: R equals M
// exactly (each added term is 0), and dR/de = [e == M]/T. The sums over
// the loop are loop nests lowering adds after the user's loop, one per
// update, with the update's loops and path (finish_accumulator); `m` after
// the loop is R[c].
class Reductions {
public:
  explicit Reductions(Lowerer& lowerer);

  // The reductions of one loop, opened before its body is lowered.
  struct LoopScope {
    std::vector<const clang::VarDecl*> accumulating; // locals that reduce in it
    size_t element_reductions_before = 0;
    bool accumulates(const clang::VarDecl* v) const;
  };
  // Opens the reductions of loop `f` (counter `counter`) whose body assigns
  // the locals `assigned`: every local it only adds to or takes the min/max
  // of, and every output element it reduces into. `open` is false where
  // the loop cannot hold reductions (unrolled, a helper's own loop).
  LoopScope begin_loop(const clang::ForStmt* f, const clang::VarDecl* counter,
                       const std::set<const clang::VarDecl*>& assigned, bool open);
  // After the loop: the results, and each reducing local is its result.
  void end_loop(const LoopScope& scope, const clang::ForStmt* f);
  // Why a local reducing in the loop being lowered has no value inside it;
  // nullopt if it does not reduce.
  std::optional<std::string> why_unset_inside(const clang::VarDecl* v) const;

  // The updates of open reductions; false (and nothing done) where the
  // statement is no such update. `if (e > m) m = e;` (also with `&& cond`):
  bool if_update(const clang::IfStmt* s);
  // `*err = fmax(*err, e)` of an output element reduction:
  bool element_update(const clang::Expr* lhs, clang::BinaryOperatorKind op,
                      const clang::Expr* rhs, clang::SourceLocation loc);
  // `s += e`, `m = std::max(m, e)`, ... of a reducing local:
  bool local_update(const clang::VarDecl* var, Type t, const clang::Expr* lhs,
                    clang::BinaryOperatorKind op, const clang::Expr* rhs,
                    clang::SourceLocation loc);
  // A helper's out-parameter (`double& acc`, `double* acc`) bound to local `v` for one call
  // (lower_inline.cpp): where `v` reduces, the helper's updates of `acc` are v's
  // (ReductionForms::is_accumulator found that they are all it does with `acc`).
  void bind_param(const clang::VarDecl* param, const clang::VarDecl* v) { params_[param] = v; }
  void unbind_param(const clang::VarDecl* param) { params_.erase(param); }
  const ReductionForms& forms() const { return forms_; }

private:
  Lowerer& L;
  ReductionForms forms_; // which statements are updates

  struct ExtremumUpdate {
    ExprP term;                 // e, lowered in the user's loop
    std::vector<PathCond> path; // where the update runs
    std::vector<Loop> loops;    // from the reducing loop in
    SourcePos pos;
  };
  struct Accumulator {
    std::string array; // the hidden array (a min/max reduction's: its scan M)
    ExprP index;       // its element: the outer loops' iteration, mixed radix
    int extremum = 0;  // +1 a max reduction, -1 a min, 0 a sum
    std::string start, ties, result; // a min/max reduction's S, T, R
    size_t depth = 0;                // loops_.size() outside the reducing loop
    std::vector<ExtremumUpdate> updates;
    // A sum's first update: its loop nest and line (updates in two nests would be added
    // nest by nest, not in the kernel's order: refused).
    std::optional<std::pair<std::vector<int>, unsigned>> first_update;
  };
  std::map<const clang::VarDecl*, Accumulator> accumulators_;
  std::map<const clang::VarDecl*, const clang::VarDecl*> params_; // (bind_param)
  // The local whose reduction `v` updates: `v`, or what the parameter is bound to, down the
  // calls, up to the first that reduces (a helper's own loop may sum into its parameter).
  const clang::VarDecl* bound(const clang::VarDecl* v) const {
    for (auto it = params_.find(v); !accumulators_.count(v) && it != params_.end();
         it = params_.find(v))
      v = it->second;
    return v;
  }

  // Min/max reductions into output elements of the loop being lowered
  // (`*err = fmax(*err, ...)`): the element's store before the loop becomes
  // the reduction's start, and after the loop the element is stored its
  // result.
  struct ElementReduction {
    ReductionTarget target;
    std::string array; // the output
    ExprP index;       // the element
    Accumulator acc;
  };
  std::vector<ElementReduction> element_reductions_;
  // Starts the element reductions of loop `f` (before its body is lowered).
  void start_element_reductions(const clang::ForStmt* f, const clang::VarDecl* counter,
                                const std::set<const clang::VarDecl*>& assigned);
  void finish_element_reductions(size_t from, clang::SourceLocation loc);
  // The update `v = max(v, e)` here: the scan's store, and the update kept
  // for the sums after the loop.
  void extremum_update(Accumulator& a, const clang::Expr* term, Type t,
                       clang::SourceLocation loc);
  // After the reducing loop: the ties and the result (the comment above).
  void finish_extremum(const Accumulator& a, clang::SourceLocation loc);
  // Fails where `var`'s update sits in a void helper's own loop (a parallel-for).
  void check_serial(const clang::VarDecl* var, clang::SourceLocation loc);
  // A read of hidden work array `array` at `idx` by a later nest.
  ExprP hidden_read(const std::string& array, const ExprP& idx, clang::SourceLocation loc);

  // Makes `v` (a real scalar with a value here) an accumulator of the loop
  // about to be lowered; false (and nothing done) where it cannot be one.
  bool start_accumulator(const clang::VarDecl* v, clang::SourceLocation loc, int extremum = 0);
  std::optional<Accumulator> make_accumulator(const std::string& name,
                                              const std::string& spelling, ExprP init,
                                              int extremum, clang::SourceLocation loc,
                                              Store* start);
  // After the accumulating loop: `v` is the sum, a read of its element.
  void finish_accumulator(const clang::VarDecl* v, clang::SourceLocation loc);
};

} // namespace dpgen::lowering
