// Lowering, pointer locals (lower_pointer.cpp): a pointer into a flat array
// parameter of the kernel, made once and indexed after (`const double* row =
// a + j * nx;`, `double* out = &b[k];`, a helper called with `a + j * nx`).
// Its binding is the parameter's with the element offset it points at, and
// every element read or written through it is the parameter's element at the
// offset plus the index: the generated code names the parameter only.
// Included by lower_impl.hpp only.
#pragma once

#include "lower_common.hpp"

#include <map>
#include <optional>
#include <set>
#include <vector>

namespace clang {
class BinaryOperator;
class Expr;
class SourceLocation;
class UnaryOperator;
class VarDecl;
} // namespace clang

namespace dpgen::lowering {

class Lowerer;

class PointerLocals {
public:
  explicit PointerLocals(Lowerer& lowerer) : L(lowerer) {}

  // Binds `v` if it is a pointer to numbers initialised with a pointer into a
  // flat array parameter (pointer_into), or a const reference to an input's
  // element (a local of its value); refuses a pointer or reference to numbers
  // made any other way; or a reference to a row of a std::vector<std::vector<T>>
  // parameter (declare_row). False if `v` is none of these.
  bool declare(const clang::VarDecl* v);

  // What pointer expression `e` points at, as a binding: `a` (the binding of
  // a parameter, a pointer local or a helper's pointer parameter as it is),
  // `p + k`, `k + p`, `p - k`, `&p[k]` for such a `p` (its offset plus k).
  // None if `e` is none of these.
  std::optional<Binding> pointer_into(const clang::Expr* e);

  // The parameter that binding `b` (of array `base`) indexes, with its element
  // offset in `offset` where the caller takes one (null for the parameter
  // itself). A pointer local where the caller takes the parameter only is
  // refused, never read at the wrong elements.
  const Param* param_of(const Binding& b, const clang::Expr* base, ExprP* offset);

  // `row = a + j * nx;` of a pointer declared with no value (C89: `const double* row;` or
  // `= NULL` before the loops): bound as a declaration there would bind it, where the
  // assignment is a statement of a loop's body or of its function's body (no arm of a
  // condition) and the pointer holds no value from an earlier iteration of that loop (it
  // would carry one iteration's row into the next). True if `b` assigns a pointer local
  // (refused otherwise: a pointer declared with its value stays fixed).
  bool assign(const clang::BinaryOperator* b);
  // Before a use of `v` at `at`: throws Rejected where `v`'s error is reported already
  // (Lowerer::poisoned_), fails where it is a pointer declared with no value and not
  // assigned here; returns otherwise.
  void check_usable(const clang::VarDecl* v, clang::SourceLocation at);
  // Fails where `u` steps (`++row`, `row--`) a pointer declared with no value.
  void check_not_stepped(const clang::UnaryOperator* u);
  // `up[i]` of a row reference (`const auto& up = u[j - 1];` of a std::vector<std::vector<T>>
  // parameter `p`, bound with the row's first element at `offset`): u[j - 1][i], its column
  // affine as in u[j][i].
  Access row_element(const Param* p, const ExprP& offset, const ExprP& idx, const clang::Expr* at);

private:
  Lowerer& L;
  std::set<const clang::VarDecl*> deferred_;                      // declared with no value
  std::map<const clang::VarDecl*, std::vector<int>> assigned_in_; // loop_ids_ then

  void check_flat(const Binding& b, const clang::Expr* at);
  bool declare_reference(const clang::VarDecl* v);
  bool declare_row(const clang::VarDecl* v);
};

} // namespace dpgen::lowering
