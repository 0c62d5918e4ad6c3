// Lowering, the signature (lower_signature.cpp): the kernel's parameters,
// their annotations and shapes (Param), the members of a member kernel and
// the returned value (the globals the body reads: lower_globals.hpp), each
// bound for the body's lowering. A part of the lowering that runs once, before the body.
// Included by lower_impl.hpp only.
#pragma once

#include "lower_common.hpp"

#include <clang/AST/Type.h>

#include <optional>
#include <set>
#include <string>

namespace clang {
class DeclaratorDecl;
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

  // One parameter: its Param (k_.params), by its shape; an error in it is
  // reported, the parameter poisoned (its uses are not reported again) and
  // the rest of the kernel still lowered, so one run reports every error.
  void parameter(const clang::DeclaratorDecl* p);
  // The shapes, each filling `out` (name and annotation `ann` known):
  // an unnamed tag (a value of an empty class type choosing an overload);
  void tag_parameter(const clang::DeclaratorDecl* p, const std::string& ann, Param& out);
  // `DPGEN_OUT double& mass`, `DPGEN_IN const double& c` (Param::scalar_ref);
  void scalar_ref_parameter(const clang::DeclaratorDecl* p, const std::string& ann,
                            Type ref_scalar, Param& out);
  // std::vector<T>& or std::span<T> (returns the Param of its size);
  std::optional<Param> container_parameter(const clang::DeclaratorDecl* p,
                                           const std::string& ann, clang::QualType span_elem,
                                           Param& out);
  // a pointer: flat, rows, row pointers (returns a DPGEN_INOUT array's twin);
  std::optional<Param> pointer_parameter(const clang::DeclaratorDecl* p, const std::string& ann,
                                         Param& out);
  // a scalar by value.
  void value_parameter(const clang::DeclaratorDecl* p, const std::string& ann, Param& out);
  // Some parameter (or member, or global) is a DPGEN_IN / a DPGEN_OUT.
  bool any_in_ = false, any_out_ = false;

  // The parameters keep their names in every generated function, so a name
  // the generated code needs for something else is an error: the adjoint or
  // tangent of another parameter (<array>_adj, <array>_dot), the size dpgen
  // passes for a vector, the prefix dpgen_, a C++ keyword.
  void check_parameter_names();
  // The members of the kernel's class that the kernel's method, the lambdas
  // in it and the class's call operators name through `this`.
  std::set<const clang::FieldDecl*> used_fields() const;
};

} // namespace dpgen::lowering
