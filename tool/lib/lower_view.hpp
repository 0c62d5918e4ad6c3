// Lowering, array views (lower_view.cpp): a part of the lowering with its own
// state (the layouts proven one-to-one). A view is a class with a pointer
// member indexed by an inline, affine, one-to-one operator() (AMReX Array4,
// Kokkos::View, mdspan, an AthenaArray-like class); its element a(k, j, i) is
// the flat k * P + j * R + i of the IR (Param::view). The signature lowering
// asks it for a view parameter's Param (view_param), the element lowering
// for the flat element of a call of its operator (view_element). Included by
// lower_impl.hpp only.
#pragma once

#include "lower_common.hpp"

#include <clang/AST/Type.h>

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace clang {
class CXXOperatorCallExpr;
class DeclaratorDecl;
class FunctionDecl;
} // namespace clang

namespace dpgen::lowering {

class Lowerer;

class Views {
public:
  explicit Views(Lowerer& lowerer) : L(lowerer) {}

  // A class with an operator() or operator[]: a parameter of it is a view.
  bool is_view_class(const clang::CXXRecordDecl* rd) const;
  // The Param of a view parameter (Param::view); fails on what is outside
  // the subset.
  void view_param(const clang::DeclaratorDecl* p, const std::string& ann, Param& out);
  // The kernel file's #include line that brings in class `rd` (for the
  // generated headers); fails if the kernel file defines it.
  std::string include_for(const clang::TagDecl* rd, clang::SourceLocation use,
                          const std::string& what);
  // v(k, j, i) of a view parameter: its flat element; nullopt if `oc` is no
  // call of a view parameter's operator.
  std::optional<Access> view_element(const clang::CXXOperatorCallExpr* oc);
  // The read of a view element at a piecewise index: the selects of the
  // index, outermost first, made selects of affine reads.
  ExprP piecewise_read(const Access& a, size_t d, std::vector<ExprP> idx, SourcePos at,
                       const std::string& source);

private:
  Lowerer& L;

  // The adjoint's type of a view parameter (Param::view_class, view_pass):
  // the same class over non-const elements (recursively through template
  // arguments), and how it is taken.
  void mutable_view_type(const clang::DeclaratorDecl* p, Param& out) const;
  std::string without_element_const(clang::QualType t, bool& changed) const;
  // The operator() a view is called with maps indices one-to-one (a layout).
  void check_layout(const clang::FunctionDecl* op, const Param& p, clang::SourceLocation use);
  std::set<const clang::FunctionDecl*> layouts_ok_;
  // The row (level 1) or plane (level 2) symbol of a view or row-pointer array.
  ExprP level_symbol(const Param& p, int level);
  // The flat index of view `p` at per-dimension indices `idx`.
  ExprP view_flat(const Param& p, const std::vector<ExprP>& idx);
};

} // namespace dpgen::lowering
