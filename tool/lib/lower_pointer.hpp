// Lowering, pointer locals (lower_pointer.cpp): a pointer into a flat array
// parameter of the kernel, made once and indexed after (`const double* row =
// a + j * nx;`, `double* out = &b[k];`, a helper called with `a + j * nx`).
// Its binding is the parameter's with the element offset it points at, and
// every element read or written through it is the parameter's element at the
// offset plus the index: the generated code names the parameter only.
// Included by lower_impl.hpp only.
#pragma once

#include "lower_common.hpp"

#include <optional>

namespace clang {
class Expr;
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
  // made any other way. False if `v` is neither.
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

private:
  Lowerer& L;

  void check_flat(const Binding& b, const clang::Expr* at);
  bool declare_reference(const clang::VarDecl* v);
};

} // namespace dpgen::lowering
