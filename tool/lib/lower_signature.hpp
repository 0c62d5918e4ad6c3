// Lowering, the signature (lower_signature.cpp): the kernel's parameters,
// their annotations and shapes (Param), the members of a member kernel, the
// returned value and the globals the body reads, each bound for the body's
// lowering. A part of the lowering that runs once, before the body.
// Included by lower_impl.hpp only.
#pragma once

#include "lower_common.hpp"

#include <set>

namespace clang {
class FieldDecl;
class Stmt;
} // namespace clang

namespace dpgen::lowering {

class Lowerer;

class Signature {
public:
  explicit Signature(Lowerer& lowerer) : L(lowerer) {}

  // The parameters (k_.params, in the order of the signature rule), checked
  // and bound; the members, the return value and the globals too.
  void header();

private:
  Lowerer& L;

  // The parameters keep their names in every generated function, so a name
  // the generated code needs for something else is an error: the adjoint or
  // tangent of another parameter (<array>_adj, <array>_dot), the size dpgen
  // passes for a vector, the prefix dpgen_, a C++ keyword.
  void check_parameter_names();
  // The members of the kernel's class that the kernel's method, the lambdas
  // in it and the class's call operators name through `this`.
  std::set<const clang::FieldDecl*> used_fields() const;
  // The globals the kernel body reads, as Params (Param::global), bound in
  // header() like parameters.
  void globals(const clang::Stmt* body);
};

} // namespace dpgen::lowering
