// One table of the IR's operations and one of the math functions the kernel
// subset calls. Everything the phases need to know about an operation that is
// not its own business (how it prints, how tightly it binds, whether it is
// boolean, how it is differentiated) is a column here, so adding a math
// function is one row of kMathFunctions plus its tests.
#pragma once

#include "ir.hpp"

#include <functional>
#include <string>
#include <vector>

namespace dpgen {

/// What the IR knows about one Op.
struct OpInfo {
  Op op;
  const char* name;   // in the IR's text form (print_ir): "add", "read", ...
  const char* symbol; // the C++ operator ("+", "<=", "!"), "" for none
  int precedence;     // C++ precedence for the printer (larger binds tighter)
  int arity;          // operands; -1: any (a call)
  bool boolean;       // the result is a bool (comparisons and logic)
  /// Comparisons: `mirror` holds with the operands swapped (a < b is b > a),
  /// `negated` is the comparison's negation (!(a < b) is a >= b). Other
  /// operations: the op itself in both.
  bool comparison = false;
  Op mirror = op;
  Op negated = op;
  /// Integer bit operations: their operands print parenthesized unless they
  /// are single terms ((i + j) & 1), as people write them and GCC's
  /// -Wparentheses asks.
  bool bitwise = false;
};

/// The row of `op`. A value outside the enum is an internal error.
const OpInfo& op_info(Op op);
/// Every row, in the order of the enum (a unit test checks the order).
const std::vector<OpInfo>& op_table();

/// The row of the binary operation C++ spells `symbol` ("+", "<<", "!="),
/// or null where the IR has none (the lowering's map from the source's
/// operators: the spelling column, not a second list).
const OpInfo* binary_op(const std::string& symbol);

/// What a derivative rule of a math function gets: the call's arguments, the
/// derivative of each (zero() where an argument carries none), and the means
/// to build the result. Rules are written once and serve both modes: the
/// adjoint differentiates with respect to one read (its derivative is 1), the
/// tangent with respect to the `_dot` arrays.
struct CallRule {
  const ExprP& call;              // the call node: ops are the arguments, type the result's
  const std::vector<ExprP>& d;    // d[i]: the derivative of argument i (may be zero())
  std::function<ExprP()> value;   // the call's own value as a local (evaluated once)

  const ExprP& arg(size_t i) const { return call->ops[i]; }
  Type type() const { return call->type; }
  /// A literal of the call's type.
  ExprP lit(double v) const;
  /// A call of another math function on `args`, of the call's type.
  ExprP fn(const std::string& name, std::vector<ExprP> args) const;
};

/// The term argument `i` contributes to the call's derivative, given its
/// derivative `di` (never zero(): such arguments contribute nothing and their
/// rule is not called): ∂f/∂x_i · dx_i, written in the form that prints best.
using PartialRule = std::function<ExprP(const CallRule& r, const ExprP& di)>;
/// A rule for the whole call (functions whose derivative is not a sum of
/// per-argument terms: min, max, abs pick an argument or a sign).
using WholeRule = std::function<ExprP(const CallRule& r)>;

struct MathFn {
  std::string name;                 // in the IR ("min", "atan2")
  std::vector<std::string> aliases; // C/C++ names that mean the same ("fmin", "fabs")
  size_t arity;
  /// How the generated code calls it: "std::" + name, or a helper of the
  /// generated file ("dpgen_min": min/max by value, see kMinMaxHelpers).
  std::string printed;
  /// Piecewise constant (floor, ceil): a derivative of zero almost everywhere.
  bool piecewise_constant = false;
  /// One term per argument, summed (empty: see `whole`).
  std::vector<PartialRule> partials;
  WholeRule whole = nullptr;
};

/// The math function a kernel's call of `name` means (an alias or a float
/// variant such as `sqrtf` included), or nullptr if dpgen has no rule for it.
const MathFn* find_math_function(const std::string& name);
/// The row of IR name `name` (as in an Op::Call); an unknown name is an
/// internal error.
const MathFn& math_function(const std::string& name);
/// Every row, in the table's order.
const std::vector<MathFn>& math_functions();
/// The supported functions for diagnostics: "std::min, std::max, ...".
std::string supported_calls();

} // namespace dpgen
