// Lowering, statements and stores (lower_stmt.cpp, lower_store.cpp): two
// parts of the lowering. Statements lowers blocks, branches, returns and
// declarations (locals, local arrays, lambdas) and hands each expression
// statement's assignment to Stores, which makes it a store of the current
// nest (an output element, or an in-place array's) or a local's new value,
// and answers what a later statement of the iteration sees at an element.
// The state they change (environment, path, nests) is the Lowerer's,
// reached through `L`. Included by lower_impl.hpp only.
#pragma once

#include "lower_common.hpp"

#include <clang/AST/OperationKinds.h>
#include <clang/Basic/SourceLocation.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace clang {
class ConstantArrayType;
class Decl;
class Expr;
class IfStmt;
class Stmt;
class VarDecl;
} // namespace clang

namespace dpgen::lowering {

class Lowerer;
enum class Escape;

class Statements {
public:
  explicit Statements(Lowerer& lowerer) : L(lowerer) {}

  // The kernel's body (a kernel whose body comes from a macro is refused).
  void body(const clang::Stmt* s);

  Escape lower(const clang::Stmt* s);

  // A new SSA local of value `def`, named after `base` (renamed where the
  // name is taken), for `decl` if it is a variable's.
  ExprP make_local(const std::string& base, const clang::VarDecl* decl, ExprP def);

  // `a[k]` of a local array: its binding and element, if that is what `e` is.
  std::optional<std::pair<const clang::VarDecl*, size_t>> local_element(const clang::Expr* e);

private:
  Lowerer& L;

  // `if (c) A else B`; a branch ending in continue/return puts the negated
  // condition on the path of everything that follows.
  Escape if_stmt(const clang::IfStmt* s);
  // `if (c) then_arm() else else_arm()`: each arm lowered on its side of the
  // path, the values either assigns merged into selects after it.
  Escape branch(const ExprP& c, const std::function<Escape()>& then_arm,
                const std::function<Escape()>& else_arm);
  // The statements of a block (or of a switch's case), in order.
  Escape sequence(const std::vector<const clang::Stmt*>& body);
  // `switch (x) { case 1: case 2: A; break; default: B; }`: if/else arms.
  Escape switch_stmt(const clang::SwitchStmt* s);

  void declare(const clang::Decl* d);

  // A small local array (`double w[3] = {...}`, a line buffer `double v[5]`):
  // each element is a local value, indexed by constants (counters of small
  // constant loops count as constants: those loops are unrolled).
  void declare_array(const clang::VarDecl* v, const clang::ConstantArrayType* at);

  // The element of a local array that `idx` names: it must be a constant.
  size_t local_index(const clang::Expr* idx_expr, const clang::VarDecl* v, size_t n);

  // An expression statement: an assignment to an output element or a local.
  void expr_stmt(const clang::Expr* e);
};

class Stores {
public:
  explicit Stores(Lowerer& lowerer) : L(lowerer) {}

  void assign(const clang::Expr* lhs, clang::BinaryOperatorKind op, const clang::Expr* rhs,
              clang::SourceLocation loc);

  // `*p` of a helper's pointer parameter bound to a caller's local (`&f`).
  const clang::VarDecl* deref_local(const clang::Expr* e);

  // An assignment to `var` at `loc`: refused inside a call in an operand
  // evaluated under a condition where `var` is declared outside it.
  void check_caller_write(const clang::VarDecl* var, clang::SourceLocation loc);
  // The frames [first, end) to which `var` is a caller's (or the kernel's)
  // variable: those that run inside the function that declares it.
  size_t first_outer_frame(const clang::VarDecl* var) const;

public:
  // The store of this iteration that a later statement on the current path
  // sees at `array[idx]`: the last one to that element whose path is still
  // open. nullptr when there is none.
  Store* visible_store(Nest& nest, const std::string& array, const ExprP& idx);

  Nest& current_nest();

  // `extremum` (with accumulate): a min/max scan's store (Store::extremum).
  void add_store(const std::string& array, ExprP idx, ExprP value, bool accumulate, SourcePos p,
                 clang::SourceLocation loc, int extremum = 0) {
    put(array, std::move(idx), std::move(value), accumulate, p, loc, extremum, nullptr);
  }
  // `x += t` (`x = x + t1 - t2`, `s += t` of an accumulator): the terms, signed and as the
  // kernel computes them, before their conversion to `elem`, the element's type. The adjoint
  // sees `x += (elem)(t1 + t2)`; the forward forms get the element's new value as C++ computes
  // it (Store::chain) where that rounds otherwise: a float element plus a double term is
  // rounded once, as a double sum, and a chain's terms are added one by one.
  void add_sum(const std::string& array, ExprP idx, const std::vector<ExprP>& terms, Type elem,
               SourcePos p, clang::SourceLocation loc);
  // add_sum of the kernel's terms (each with its sign: true, subtracted), lowered in order.
  void add_sum(const std::string& array, ExprP idx,
               const std::vector<std::pair<const clang::Expr*, bool>>& terms, Type elem,
               SourcePos p, clang::SourceLocation loc);

  // The value u[k] of an in-place array has here: what this iteration stored
  // at k, or the value before the call (a read of the input).
  ExprP inout_value(const Param* p, const ExprP& idx, clang::SourceLocation loc,
                    const clang::Expr* e);

  // The value `st` stores, for a read back of it: a local made where the
  // store is (`b_1 = ...`), which becomes the store's value, so a value read
  // back twice, or kept and updated under a condition, is printed once
  // (`b[i] = b[i] * b[i] + b[i];` four times over is no tree of 3^4 copies).
  // A leaf or a local is returned as it is, as is a store outside every loop.
  ExprP shared_value(Store& st, const std::string& name);
  // `v` as such a local (for a value of `st` the forward forms print twice).
  ExprP local_at(const Store& st, const std::string& name, const ExprP& v);
  // The name such locals start from: the array's (an in-place array's, not its twin's).
  std::string local_base(const std::string& array) const;

  bool written_by_other_nest(const std::string& array) const;

  // `std::swap(a, b)` of two scalar locals (a sorting network: `if (a > b) std::swap(a, b);`)
  // is `t = a; a = b; b = t;`; any other std::swap is refused. False for any other statement.
  bool swap(const clang::Expr* e);

  // `prefix` holds wherever `path` holds: its conditions open `path`.
  static bool is_prefix(const std::vector<PathCond>& prefix, const std::vector<PathCond>& path);

private:
  Lowerer& L;

  // add_store, and add_sum with its `terms`.
  void put(const std::string& array, ExprP idx, ExprP value, bool accumulate, SourcePos p,
           clang::SourceLocation loc, int extremum, const std::vector<ExprP>* terms);

  // var = rhs, var += rhs, ... for a scalar local (or what a helper's `*p`
  // stands for).
  void assign_value(const clang::VarDecl* var, Type t, const clang::Expr* lhs,
                    clang::BinaryOperatorKind op, const clang::Expr* rhs,
                    clang::SourceLocation loc);
};

} // namespace dpgen::lowering
