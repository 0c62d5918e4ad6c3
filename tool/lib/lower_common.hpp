// Lowering: the types its parts share (lower_impl.hpp, lower_view.hpp,
// lower_object.hpp, ...): what a name is bound to, an element of an array,
// how an error leaves. Included by the lowering's headers only.
#pragma once

#include "ir.hpp"

#include <clang/Basic/SourceLocation.h>

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace clang {
class ASTContext;
class CXXRecordDecl;
class FieldDecl;
class NamedDecl;
class VarDecl;
} // namespace clang

namespace dpgen::lowering {

// What a name in the kernel body refers to.
struct Binding {
  enum Kind { ScalarParam, ArrayParam, LoopVar, Value, LocalArray, Lambda } kind;
  // Lambda: the closure's class, and the value each variable captured by copy
  // had when the lambda was made (a call checks it has not changed since).
  const clang::CXXRecordDecl* closure = nullptr;
  std::vector<std::pair<const clang::VarDecl*, std::optional<ExprP>>> captured;
  std::vector<std::pair<const clang::VarDecl*, std::vector<std::optional<ExprP>>>>
      captured_arrays; // local arrays captured by copy: their elements then
  std::optional<ExprP> value;              // Value: current SSA value (none: uninitialised)
  std::vector<std::optional<ExprP>> elems; // LocalArray: each element's value (none: unset)
  Type elem = Type::Double; // LocalArray: element type
  const Param* param = nullptr;
  // ArrayParam: the element of `param` a pointer local points at (`const double* row = a +
  // j * nx;`: j * nx, lower_pointer.hpp); none for the parameter itself.
  std::optional<ExprP> offset;
  bool kernel_level = false; // Value defined outside every loop
  // Value: a helper's pointer parameter bound to a caller's local (`&f`),
  // used only as `*p`; the binding holds the local's value.
  bool deref_only = false;
  // Lambda: a functor object (a class with a void operator()), run like a
  // lambda; its members' bindings (`GradMagnitude{phi, gsq, 0.5 * dxinv}`),
  // or null for `*this` of a member kernel (whose members are fields_).
  bool functor = false;
  std::shared_ptr<std::map<const clang::FieldDecl*, Binding>> fields;
};

// The ways out of an inlined call inside a branch (its returns there): the
// conditions of each, past the call's, and the bindings it left.
using FrameExits =
    std::vector<std::pair<std::vector<PathCond>, std::map<const clang::VarDecl*, Binding>>>;

// An error at `loc` through Clang (which shows the line and any macro
// expansion behind it), ending with its id: "message [dpgen-loop]".
void report_error(clang::ASTContext& ctx, clang::SourceLocation loc, const std::string& msg,
                  const std::string& id);

// Thrown to abandon a kernel after its diagnostic has been reported.
struct Rejected {};

// An element of an array parameter: `a[k]`, `a[j][i]` of a multi-dimensional
// array (flattened row-major), `*p` (element 0: a scalar passed by pointer).
struct Access {
  const Param* param;
  ExprP index;
  // A view of rank 2 or more indexed at a periodic wrap (`q(k, j, im)` with
  // `im = i == 0 ? nx - 1 : i - 1`): its indices per dimension, some a
  // select of affine arms. A read is then the select of the reads
  // (piecewise_read); `index` is the first arms' (a store is an error).
  std::vector<ExprP> dims = {}; // (empty: a flat index)
};


// The operator() (or operator[]) overloads of a class, templates included.
std::vector<const clang::NamedDecl*> call_operators(const clang::CXXRecordDecl* rd,
                                                    clang::ASTContext& ctx);

} // namespace dpgen::lowering
