// Lowering, objects (lower_object.cpp): a part of the lowering with its own
// state (the object locals and aliases, the integer values read from
// objects). A class-typed parameter that is no view (AMReX's Box, a struct of
// grid constants) or a local object made from them is read as constants of
// the kernel spelled as written (`bx.smallEnd(0)`, `u.extent(0)`,
// `grid.dx`); a functor object (a class with a void operator(), a
// parallel-for's body) is bound like a lambda. Included by lower_impl.hpp
// only.
#pragma once

#include "lower_common.hpp"

#include <map>
#include <optional>
#include <set>
#include <string>

namespace clang {
class DeclaratorDecl;
class Expr;
class FunctionDecl;
class ParmVarDecl;
} // namespace clang

namespace dpgen::lowering {

class Lowerer;

class Objects {
public:
  explicit Objects(Lowerer& lowerer) : L(lowerer) {}

  // The Param of an object parameter (Param::object); fails on what is
  // outside the subset.
  void object_param(const clang::DeclaratorDecl* p, const std::string& ann, Param& out);
  // A value read from an object or view parameter or an object local
  // (`bx.smallEnd(0)`, `u.extent(1)`, `lo.x`, `grid.dx`): a constant of the
  // kernel spelled as C++ over those names; nullopt for anything else.
  std::optional<ExprP> object_value(const clang::Expr* e);
  // The integer values read from objects, as spelled (symbols of the index
  // algebra).
  const std::set<std::string>& object_values() const { return object_values_; }
  // `const auto lo = amrex::lbound(bx);`: a local object made from objects,
  // declared again in every generated function. False if `v` is none.
  bool declare_object(const clang::VarDecl* v);
  // A helper's parameter of a class type bound to the caller's argument: a
  // lambda (Binding::Lambda, as a local holding it would be), a view
  // parameter (Binding::ArrayParam), an object (its spelling, in
  // object_aliases_: a Binding::Value without value). nullopt: not a class.
  std::optional<Binding> class_argument(const clang::ParmVarDecl* pd, const clang::Expr* arg,
                                        const clang::FunctionDecl* helper);
  // A class whose operator() returns void: a functor (a parallel-for body).
  bool is_functor_class(const clang::CXXRecordDecl* rd) const;
  // The binding of a functor object made by `init`: `*this` of a member
  // kernel, an aggregate initialization from the kernel's views, arrays and
  // values; fails on anything else.
  Binding functor_binding(const clang::Expr* init, const clang::CXXRecordDecl* rd);

private:
  Lowerer& L;

  std::optional<std::string> object_text(const clang::Expr* e);
  std::optional<std::string> materialize(const clang::Expr* e, const clang::CXXRecordDecl* rd);
  std::set<std::string> object_values_;                        // the integer ones, as spelled
  std::map<const clang::VarDecl*, std::string> object_locals_;  // -> its name in generated code
  std::map<const clang::VarDecl*, std::string> object_aliases_; // (class_argument)
};

} // namespace dpgen::lowering
