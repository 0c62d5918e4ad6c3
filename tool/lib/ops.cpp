// The tables of ops.hpp: the IR's operations, and the math functions with
// their derivative rules (the maths above each row).
#include "ops.hpp"

#include <stdexcept>

namespace dpgen {

namespace {

// In the order of enum class Op (op_table() checks it).
const std::vector<OpInfo> kOps = {
    //  op            name         symbol prec arity boolean
    {Op::IntConst, "int", "", 14, 0, false},
    {Op::RealConst, "real", "", 14, 0, false},
    {Op::Param, "param", "", 14, 0, false},
    {Op::LoopVar, "loopvar", "", 14, 0, false},
    {Op::Local, "local", "", 14, 0, false},
    {Op::Read, "read", "", 14, 1, false},
    {Op::Neg, "neg", "-", 12, 1, false},
    {Op::Add, "add", "+", 10, 2, false},
    {Op::Sub, "sub", "-", 10, 2, false},
    {Op::Mul, "mul", "*", 11, 2, false},
    {Op::Div, "div", "/", 11, 2, false},
    {Op::Rem, "rem", "%", 11, 2, false},
    {Op::Lt, "lt", "<", 8, 2, true, true, Op::Gt, Op::Ge},
    {Op::Le, "le", "<=", 8, 2, true, true, Op::Ge, Op::Gt},
    {Op::Gt, "gt", ">", 8, 2, true, true, Op::Lt, Op::Le},
    {Op::Ge, "ge", ">=", 8, 2, true, true, Op::Le, Op::Lt},
    {Op::Eq, "eq", "==", 7, 2, true, true, Op::Eq, Op::Ne},
    {Op::Ne, "ne", "!=", 7, 2, true, true, Op::Ne, Op::Eq},
    {Op::And, "and", "&&", 3, 2, true},
    {Op::Or, "or", "||", 2, 2, true},
    {Op::Not, "not", "!", 12, 1, true},
    {Op::Select, "select", "?:", 1, 3, false},
    {Op::Call, "call", "", 14, -1, false},
    {Op::Cast, "cast", "", 14, 1, false},
    {Op::Shl, "shl", "<<", 9, 2, false, false, Op::Shl, Op::Shl, true},
    {Op::Shr, "shr", ">>", 9, 2, false, false, Op::Shr, Op::Shr, true},
    {Op::BitAnd, "bitand", "&", 6, 2, false, false, Op::BitAnd, Op::BitAnd, true},
    {Op::BitOr, "bitor", "|", 4, 2, false, false, Op::BitOr, Op::BitOr, true},
    {Op::BitXor, "bitxor", "^", 5, 2, false, false, Op::BitXor, Op::BitXor, true},
    {Op::BitNot, "bitnot", "~", 12, 1, false},
};

ExprP div(ExprP a, ExprP b) { return binary(Op::Div, std::move(a), std::move(b)); }
ExprP mul(ExprP a, ExprP b) { return binary(Op::Mul, std::move(a), std::move(b)); }
ExprP plus(ExprP a, ExprP b) { return binary(Op::Add, std::move(a), std::move(b)); }

// d min(a,b) = a <= b ? da : db ;  d max(a,b) = a >= b ? da : db
WholeRule pick(Op cmp) {
  return [cmp](const CallRule& r) {
    auto arm = [&](const ExprP& d) { return is_zero(d) ? zero(r.type()) : d; };
    return select(binary(cmp, r.arg(0), r.arg(1)), arm(r.d[0]), arm(r.d[1]));
  };
}

// d fmin(a,b) = (a <= b || b != b) ? da : db ; d fmax likewise with >=: a
// NaN argument gives the other one, and its derivative
WholeRule pick_number(Op cmp) {
  return [cmp](const CallRule& r) {
    auto arm = [&](const ExprP& d) { return is_zero(d) ? zero(r.type()) : d; };
    ExprP first = binary(cmp, r.arg(0), r.arg(1));
    if (r.arg(1)->op != Op::RealConst) // (a constant is no NaN)
      first = binary(Op::Or, first, binary(Op::Ne, r.arg(1), r.arg(1)));
    return select(first, arm(r.d[0]), arm(r.d[1]));
  };
}

const std::vector<MathFn> kMath = {
    {"min", {}, 2, "dpgen_min", false, {}, pick(Op::Le)},
    {"max", {}, 2, "dpgen_max", false, {}, pick(Op::Ge)},
    // std::fmin/std::fmax: as min/max, but a NaN argument gives the other one
    // (printed as themselves; so does the derivative)
    {"fmin", {}, 2, "std::fmin", false, {}, pick_number(Op::Le)},
    {"fmax", {}, 2, "std::fmax", false, {}, pick_number(Op::Ge)},
    // d|a| = sign(a)·da
    {"abs",
     {"fabs"},
     1,
     "std::abs",
     false,
     {},
     [](const CallRule& r) {
       const ExprP& a = r.arg(0);
       return select(binary(Op::Lt, a, real_const(0, a->type)), unary(Op::Neg, r.d[0]), r.d[0]);
     }},
    // d sqrt(a) = da / (2·sqrt(a))
    {"sqrt", {}, 1, "std::sqrt", false, {[](const CallRule& r, const ExprP& da) {
       return div(da, mul(r.lit(2), r.value()));
     }}},
    // d exp(a) = exp(a)·da
    {"exp", {}, 1, "std::exp", false, {[](const CallRule& r, const ExprP& da) {
       return mul(r.value(), da);
     }}},
    // d log(a) = da / a
    {"log", {}, 1, "std::log", false, {[](const CallRule& r, const ExprP& da) {
       return div(da, r.arg(0));
     }}},
    // d sin(a) = cos(a)·da
    {"sin", {}, 1, "std::sin", false, {[](const CallRule& r, const ExprP& da) {
       return mul(r.fn("cos", {r.arg(0)}), da);
     }}},
    // d cos(a) = -sin(a)·da
    {"cos", {}, 1, "std::cos", false, {[](const CallRule& r, const ExprP& da) {
       return unary(Op::Neg, mul(r.fn("sin", {r.arg(0)}), da));
     }}},
    // d tanh(a) = (1 - tanh²(a))·da
    {"tanh", {}, 1, "std::tanh", false, {[](const CallRule& r, const ExprP& da) {
       ExprP t = r.value();
       return mul(binary(Op::Sub, r.lit(1), mul(t, t)), da);
     }}},
    // d a^b = b·a^(b-1)·da + a^b·log(a)·db
    {"pow",
     {},
     2,
     "std::pow",
     false,
     {[](const CallRule& r, const ExprP& da) {
        const ExprP &a = r.arg(0), &b = r.arg(1);
        return mul(mul(b, r.fn("pow", {a, binary(Op::Sub, b, r.lit(1))})), da);
      },
      [](const CallRule& r, const ExprP& db) {
        return mul(mul(r.value(), r.fn("log", {r.arg(0)})), db);
      }}},
    // piecewise constant: zero almost everywhere
    // The value of its argument, as a constant to derivatives (a stop-gradient:
    // the min/max reductions' scans and tie counts, lower_reduce.cpp). Printed as
    // a parenthesized argument.
    {"dpgen_nograd", {}, 1, "", true, {}, nullptr},
    {"floor", {}, 1, "std::floor", true, {}, nullptr},
    {"ceil", {}, 1, "std::ceil", true, {}, nullptr},
    // d atan2(y, x) = (x·dy - y·dx) / (x² + y²)
    {"atan2",
     {},
     2,
     "std::atan2",
     false,
     {[](const CallRule& r, const ExprP& dy) {
        const ExprP &y = r.arg(0), &x = r.arg(1);
        return div(mul(x, dy), plus(mul(x, x), mul(y, y)));
      },
      [](const CallRule& r, const ExprP& dx) {
        const ExprP &y = r.arg(0), &x = r.arg(1);
        return unary(Op::Neg, div(mul(y, dx), plus(mul(x, x), mul(y, y))));
      }}},
    // d hypot(a, b) = (a·da + b·db) / hypot(a, b)
    {"hypot",
     {},
     2,
     "std::hypot",
     false,
     {[](const CallRule& r, const ExprP& da) { return div(mul(r.arg(0), da), r.value()); },
      [](const CallRule& r, const ExprP& db) { return div(mul(r.arg(1), db), r.value()); }}},
    // d erf(a) = 2/sqrt(pi)·exp(-a²)·da
    {"erf", {}, 1, "std::erf", false, {[](const CallRule& r, const ExprP& da) {
       const ExprP& a = r.arg(0);
       return mul(mul(r.lit(1.1283791670955126), r.fn("exp", {unary(Op::Neg, mul(a, a))})), da);
     }}},
    // d cbrt(a) = da / (3·cbrt(a)²)
    {"cbrt", {}, 1, "std::cbrt", false, {[](const CallRule& r, const ExprP& da) {
       ExprP v = r.value();
       return div(da, mul(mul(r.lit(3), v), v));
     }}},
    // copysign(a, b) = |a|·sign(b): d = sign(a)·sign(b)·da (with the signs of
    // signed zeros, as copysign sees them); b's sign is piecewise constant.
    {"copysign",
     {},
     2,
     "std::copysign",
     false,
     {[](const CallRule& r, const ExprP& da) {
        return mul(mul(r.fn("copysign", {r.lit(1), r.arg(0)}),
                       r.fn("copysign", {r.lit(1), r.arg(1)})),
                   da);
      },
      [](const CallRule& r, const ExprP&) { return zero(r.type()); }}},
    // d fma(a, b, c) = b·da + a·db + dc
    {"fma",
     {},
     3,
     "std::fma",
     false,
     {[](const CallRule& r, const ExprP& da) { return mul(r.arg(1), da); },
      [](const CallRule& r, const ExprP& db) { return mul(r.arg(0), db); },
      [](const CallRule&, const ExprP& dc) { return dc; }}},
    // d log1p(a) = da / (1 + a)
    {"log1p", {}, 1, "std::log1p", false, {[](const CallRule& r, const ExprP& da) {
       return div(da, plus(r.lit(1), r.arg(0)));
     }}},
    // d expm1(a) = (expm1(a) + 1)·da
    {"expm1", {}, 1, "std::expm1", false, {[](const CallRule& r, const ExprP& da) {
       return mul(plus(r.value(), r.lit(1)), da);
     }}},
};

} // namespace

const std::vector<OpInfo>& op_table() { return kOps; }

const OpInfo* binary_op(const std::string& symbol) {
  for (const auto& row : kOps)
    if (row.arity == 2 && symbol == row.symbol)
      return &row;
  return nullptr;
}

const OpInfo& op_info(Op op) {
  auto i = static_cast<size_t>(op);
  if (i >= kOps.size() || kOps[i].op != op)
    unknown_op("op_info");
  return kOps[i];
}

ExprP CallRule::lit(double v) const { return real_const(v, call->type); }

ExprP CallRule::fn(const std::string& name, std::vector<ExprP> args) const {
  return dpgen::call(name, std::move(args), call->type);
}

const std::vector<MathFn>& math_functions() { return kMath; }

const MathFn* find_math_function(const std::string& name) {
  auto lookup = [](const std::string& n) -> const MathFn* {
    for (const auto& f : kMath) {
      if (f.printed.empty()) // dpgen's own, not a function a kernel calls
        continue;
      if (f.name == n)
        return &f;
      for (const auto& a : f.aliases)
        if (a == n)
          return &f;
    }
    return nullptr;
  };
  if (const MathFn* f = lookup(name))
    return f;
  // float variants: sqrtf, fminf, atan2f, ...
  if (name.size() > 1 && name.back() == 'f')
    return lookup(name.substr(0, name.size() - 1));
  return nullptr;
}

const MathFn& math_function(const std::string& name) {
  for (const auto& f : kMath)
    if (f.name == name)
      return f;
  throw std::logic_error("internal error: no math function '" + name + "' in the table");
}

std::string supported_calls() {
  std::string s;
  for (const auto& f : kMath) {
    if (f.printed.empty()) // (dpgen's own)
      continue;
    if (!s.empty())
      s += ", ";
    s += f.printed.rfind("std::", 0) == 0 ? f.printed : "std::" + f.name;
    for (const auto& a : f.aliases)
      s += "/" + a;
  }
  return s + ", std::clamp"; // (lowered to std::min of std::max: lower_expr.cpp)
}

} // namespace dpgen
