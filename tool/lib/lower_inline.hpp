// Lowering, helpers and lambdas (lower_inline.cpp): a part of the lowering
// with no state of its own beyond the stack of calls being inlined, which
// the statement lowering reads too (Lowerer::frames_). A user function
// called from a kernel (a limiter, a flux, minmod) or a lambda is
// differentiated by inlining: its parameters are bound to the arguments'
// values (arrays to the kernel's arrays), its body is lowered like the
// kernel's, and its returns become one value, selected by the conditions
// under which each return is reached. Included by lower_impl.hpp only.
#pragma once

#include "lower_common.hpp"

#include <optional>
#include <set>
#include <string>

namespace clang {
class CallExpr;
class CXXRecordDecl;
class FunctionDecl;
class LambdaExpr;
class VarDecl;
} // namespace clang

namespace dpgen::lowering {

class Lowerer;

class Inliner {
public:
  explicit Inliner(Lowerer& lowerer) : L(lowerer) {}

  // The value of call `c` of helper `f` (void helpers: their stores and
  // out-parameters, and a null value).
  ExprP inline_call(const clang::CallExpr* c, const clang::FunctionDecl* f);
  // `c` calls the operator() or operator[] of an accessor the kernel made over its arrays.
  bool made_accessor(const clang::CallExpr* c) const;
  // `U(i, j)` (or `U[k]`) of such an accessor whose operator returns a reference, its body
  // `return p[j * nx + i];`: that element of the kernel's array (written to, or read); nullopt for
  // any other call.
  std::optional<Access> accessor_element(const clang::CallExpr* c);
  // `auto f = [&](int i) { ... };`: called later, inlined like a helper. A
  // variable captured by copy must still have the value it had here when the
  // lambda is called; init-captures and `this` are outside the subset.
  void declare_lambda(const clang::VarDecl* v, const clang::CXXRecordDecl* rd);
  // The Binding of a lambda expression, its captures by copy recorded
  // (declare_lambda, a lambda passed to a helper).
  Binding lambda_binding(const clang::LambdaExpr* le, const std::string& name);

private:
  // After a call whose frame began at path depth `depth`: each variable in
  // `visible` (the caller's, and the out-parameters) merged over `exits`.
  void merge_exits(const FrameExits& exits, size_t depth,
                   const std::set<const clang::VarDecl*>& visible);
  // Refuses a local bound to an out-parameter or a `const&` parameter of
  // call `c` that a lambda argument of the same call, or the called lambda,
  // captured by reference.
  void check_aliases(
      const clang::CallExpr* c, const clang::FunctionDecl* def,
      const std::vector<std::pair<const clang::VarDecl*, Binding>>& binds,
      const std::vector<std::pair<const clang::ParmVarDecl*, const clang::VarDecl*>>& outs);

  Lowerer& L;
};

} // namespace dpgen::lowering
