// Expression printer: C++ precedence levels, minimal parentheses.
#include "print.hpp"

#include "ops.hpp"

#include <cmath>
#include <fmt/format.h>
#include <optional>

#include <set>
#include <stdexcept>

namespace dpgen {

namespace {

// Larger binds tighter (C++ precedence; the table's column, ops.hpp). A
// negative literal binds as a unary minus.
int precedence(const Expr& e) {
  if ((e.op == Op::IntConst && e.ival < 0) || (e.op == Op::RealConst && std::signbit(e.rval)))
    return op_info(Op::Neg).precedence;
  return op_info(e.op).precedence;
}

std::string wrap(const ExprP& e, int min_prec) {
  std::string s = print(e);
  return precedence(*e) < min_prec ? "(" + s + ")" : s;
}

std::string bound_set(const std::vector<Poly>& set, const std::string& fn,
                      const std::string& int_type) {
  std::vector<std::string> parts;
  std::set<std::string> seen;
  for (const auto& p : set)
    if (seen.insert(p.code()).second)
      parts.push_back(p.code());
  if (parts.empty())
    return fn == "max" ? fmt::format("std::numeric_limits<{}>::min()", int_type)
                       : fmt::format("std::numeric_limits<{}>::max()", int_type);
  if (parts.size() == 1)
    return parts[0];
  if (parts.size() == 2)
    return fmt::format("std::{}<{}>({}, {})", fn, int_type, parts[0], parts[1]);
  return fmt::format("std::{}<{}>({{{}}})", fn, int_type, fmt::join(parts, ", "));
}

} // namespace

std::string real_literal(double v, Type t) {
  std::string s = fmt::format("{}", v);
  if (s.find_first_of(".eEn") == std::string::npos)
    s += ".0";
  return t == Type::Float ? s + "f" : s;
}

namespace {
// The row or plane symbol an index mentions, if any (ir.hpp: row_symbol,
// plane_symbol).
std::optional<Sym> symbol_in(const Poly& p, const char* prefix) {
  for (const auto& [m, c] : p.terms())
    for (const auto& sym : m)
      if (!sym.is_counter() && sym.name.rfind(prefix, 0) == 0)
        return sym;
  return std::nullopt;
}
} // namespace

namespace {
// The index of each level of a flat index, outermost first: [k, j, i] of
// k * P + j * R + i (ir.hpp: row_symbol, plane_symbol); a missing symbol is
// level 0 (row 0).
std::vector<std::string> level_indices(const Poly& index, int levels) {
  if (levels >= 3) { // a rank-4 view: n * C + (k * P + j * R + i)
    auto cubes = symbol_in(index, "dpgen_cubes_");
    std::vector<std::string> out = {cubes ? index.coefficient(*cubes).code() : "0"};
    auto rest = level_indices(cubes ? index.without(*cubes) : index, 2);
    out.insert(out.end(), rest.begin(), rest.end());
    return out;
  }
  if (levels >= 2) {
    auto planes = symbol_in(index, "dpgen_planes_");
    std::vector<std::string> out = {planes ? index.coefficient(*planes).code() : "0"};
    auto rest = level_indices(planes ? index.without(*planes) : index, 1);
    out.insert(out.end(), rest.begin(), rest.end());
    return out;
  }
  if (levels == 1) {
    auto rows = symbol_in(index, "dpgen_rows_");
    if (!rows)
      return {"0", index.code()};
    return {index.coefficient(*rows).code(), index.without(*rows).code()};
  }
  if (symbol_in(index, "dpgen_rows_") || symbol_in(index, "dpgen_planes_") ||
      symbol_in(index, "dpgen_cubes_"))
    throw std::logic_error("internal error: subscript: a row or plane symbol in the index of a "
                           "flat array: " + index.code());
  return {index.code()};
}

std::string written(const std::vector<std::string>& indices, bool view) {
  if (view)
    return "(" + fmt::format("{}", fmt::join(indices, ", ")) + ")";
  std::string out;
  for (const auto& i : indices)
    out += "[" + i + "]";
  return out;
}
} // namespace

std::string subscript(const Poly& index, Shape shape) {
  return written(level_indices(index, shape.levels), shape.view);
}

std::string subscript(const ExprP& index, Shape shape) {
  auto p = to_poly(index);
  if (shape.levels == 0) {
    if (p)
      (void)level_indices(*p, 0); // throws on a row or plane symbol: the levels were lost
    return written({print(index)}, shape.view);
  }
  if (!p) // lower.cpp admits only affine indices of row-pointer arrays and views
    throw std::logic_error("internal error: subscript: a non-affine index of a row-pointer "
                           "array: " + print(index));
  return subscript(*p, shape);
}

// `e` as one operand of a `&&` chain: parenthesized where it binds more
// loosely than `&&` (`(a || b) && c`, not `a || b && c`).
std::string print_conjunct(const ExprP& e) { return wrap(e, op_info(Op::And).precedence); }

std::string print(const ExprP& e) {
  if (!e) // no ExprP is null (an exact zero is zero(), ir.hpp): a bug in the phase that made it
    throw std::logic_error("internal error: print: a null expression (a missing value in the IR "
                           "or plan; an exact zero is zero(), ir.hpp)");
  switch (e->op) {
  case Op::IntConst:
    return std::to_string(e->ival);
  case Op::RealConst:
    return !e->spelling.empty() ? e->spelling : real_literal(e->rval, e->type);
  case Op::Param: // (an output view's shape, read through its seed in the adjoint: ir.hpp)
    return renamed(e->name);
  case Op::LoopVar:
  case Op::Local:
    return e->name;
  case Op::Read:
    return e->name + subscript(e->ops[0], e->shape);
  case Op::Neg:
    return "-" + wrap(e->ops[0], op_info(Op::Neg).precedence + 1);
  case Op::Not:
    return "!" + wrap(e->ops[0], op_info(Op::Not).precedence + 1);
  case Op::BitNot:
    return "~" + wrap(e->ops[0], op_info(Op::BitNot).precedence + 1);
  case Op::Select:
    return fmt::format("{} ? {} : {}", wrap(e->ops[0], 2), wrap(e->ops[1], 2), wrap(e->ops[2], 1));
  case Op::Call: {
    std::vector<std::string> args;
    for (const auto& a : e->ops)
      args.push_back(print(a));
    // As the table prints it (ops.hpp): std::sqrt(a), or min/max by value
    // (dpgen_min, see kMinMaxHelpers): std::min returns a reference, which
    // keeps GCC from vectorizing the loop around it.
    const std::string& printed = math_function(e->name).printed;
    bool by_value = printed.rfind("dpgen_", 0) == 0;
    // Integer arguments may differ in width (a widened local and an int
    // parameter): name the type, as std::min's deduction would fail too.
    std::string targs = by_value && e->type == Type::Int ? "<std::ptrdiff_t>" : "";
    return fmt::format("{}{}({})", printed, targs, fmt::join(args, ", "));
  }
  case Op::Cast: // cast_type: the integer type of a widening cast ("long")
    return fmt::format("static_cast<{}>({})", e->cast_type.empty() ? type_spelling(e->type) : e->cast_type,
                       print(e->ops[0]));
  default: {
    if (op_info(e->op).arity != 2)
      unknown_op("print");
    // Binary, left-associative: a right operand of equal precedence keeps its
    // parentheses, so floating-point evaluation order is exactly the IR's.
    int p = precedence(*e);
    if (op_info(e->op).bitwise) // (ops.hpp: operands parenthesized)
      return fmt::format("{} {} {}", wrap(e->ops[0], op_info(Op::Neg).precedence),
                         op_info(e->op).symbol, wrap(e->ops[1], op_info(Op::Neg).precedence));
    if (e->op == Op::Or) { // (a && b) || c: parenthesized as -Wparentheses asks
      auto side = [&](const ExprP& x, int min) {
        return x->op == Op::And ? "(" + print(x) + ")" : wrap(x, min);
      };
      return fmt::format("{} || {}", side(e->ops[0], p), side(e->ops[1], p + 1));
    }
    return fmt::format("{} {} {}", wrap(e->ops[0], p), op_info(e->op).symbol, wrap(e->ops[1], p + 1));
  }
  }
  unknown_op("print");
}

std::string store_statement(const Store& s, const std::string& target, const std::string& value) {
  if (s.extremum != 0)
    return fmt::format("{} = {}({}, {});", target, s.extremum > 0 ? "dpgen_max" : "dpgen_min",
                       target, value);
  return fmt::format("{} {} {};", target, s.accumulate ? "+=" : "=", value);
}

const char* store_operator(const Store& s) {
  return s.extremum > 0 ? "max=" : s.extremum < 0 ? "min=" : s.accumulate ? "+=" : "=";
}

std::string print_max(const std::vector<Poly>& set, const std::string& int_type) {
  return bound_set(set, "max", int_type);
}

std::string print_min(const std::vector<Poly>& set, const std::string& int_type) {
  return bound_set(set, "min", int_type);
}

} // namespace dpgen
