// Constructors for IR expressions, with the constant folding that keeps
// generated derivatives readable.
#include "ir.hpp"

#include "ops.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace dpgen {

namespace {

std::shared_ptr<Expr> node(Op op, Type t, std::vector<ExprP> ops = {}) {
  auto e = std::make_shared<Expr>();
  e->op = op;
  e->type = t;
  e->ops = std::move(ops);
  return e;
}

bool is_bool_op(Op op) { return op_info(op).boolean; }

Type promote(Type a, Type b) {
  if (a == Type::Double || b == Type::Double)
    return Type::Double;
  if (a == Type::Float || b == Type::Float)
    return Type::Float;
  return Type::Int;
}

bool const_value(const ExprP& e, double& v) {
  if (!e)
    throw std::logic_error("internal error: is_const: a null expression");
  if (e->op == Op::IntConst) {
    v = static_cast<double>(e->ival);
    return true;
  }
  if (e->op == Op::RealConst) {
    v = e->rval;
    return true;
  }
  return false;
}

} // namespace

std::string type_spelling(Type t) {
  switch (t) {
  case Type::Int:
    return "int";
  case Type::Float:
    return "float";
  case Type::Double:
    return "double";
  case Type::Bool:
    return "bool";
  }
  return "?";
}

ExprP int_const(long long v) {
  auto e = node(Op::IntConst, Type::Int);
  e->ival = v;
  return e;
}

ExprP real_const(double v, Type t, std::string spelling) {
  auto e = node(Op::RealConst, t);
  e->rval = v;
  e->spelling = std::move(spelling);
  return e;
}

ExprP zero(Type t) {
  auto e = node(Op::RealConst, t);
  e->exact_zero = true;
  return e;
}

std::optional<long long> int_value(const ExprP& e) {
  if (e->type != Type::Int)
    return std::nullopt;
  if (e->op == Op::IntConst)
    return e->ival;
  if (e->op == Op::Local)
    return int_value(e->local->def);
  if (e->op == Op::Cast)
    return int_value(e->ops[0]);
  if (e->op == Op::Neg || e->op == Op::BitNot) {
    auto a = int_value(e->ops[0]);
    if (!a)
      return std::nullopt;
    return e->op == Op::Neg ? -*a : ~*a;
  }
  if (e->ops.size() != 2)
    return std::nullopt;
  auto a = int_value(e->ops[0]), b = int_value(e->ops[1]);
  if (!a || !b)
    return std::nullopt;
  switch (e->op) {
  case Op::Add:
    return *a + *b;
  case Op::Sub:
    return *a - *b;
  case Op::Mul:
    return *a * *b;
  case Op::Div:
  case Op::Rem:
    if (*b == 0)
      return std::nullopt;
    return e->op == Op::Div ? *a / *b : *a % *b;
  case Op::Shl:
  case Op::Shr:
    if (*b < 0 || *b > 62 || *a < 0)
      return std::nullopt;
    return e->op == Op::Shl ? *a << *b : *a >> *b;
  case Op::BitAnd:
    return *a & *b;
  case Op::BitOr:
    return *a | *b;
  case Op::BitXor:
    return *a ^ *b;
  default:
    return std::nullopt;
  }
}

bool is_zero(const ExprP& e) {
  if (!e)
    throw std::logic_error("internal error: a null expression where a derivative was expected "
                           "(an exact zero is zero(), ir.hpp)");
  return e->op == Op::RealConst && e->exact_zero;
}

void unknown_op(const char* where) {
  throw std::logic_error(std::string("internal error: ") + where + ": an Op outside the enum");
}

ExprP param(const std::string& name, Type t) {
  auto e = node(Op::Param, t);
  e->name = name;
  return e;
}

ExprP loop_var(const std::string& name) {
  auto e = node(Op::LoopVar, Type::Int);
  e->name = name;
  return e;
}

ExprP local_ref(const LocalP& l) {
  auto e = node(Op::Local, l->def->type);
  e->local = l;
  e->name = l->name;
  return e;
}

ExprP read(const std::string& array, ExprP index, Type t, SourcePos pos, Shape shape) {
  auto e = node(Op::Read, t, {std::move(index)});
  e->name = array;
  e->pos = std::move(pos);
  e->shape = shape;
  return e;
}

bool is_const(const ExprP& e, double v) {
  double c;
  return const_value(e, c) && c == v;
}

ExprP unary(Op op, ExprP a) {
  if (op == Op::Neg) {
    if (a->op == Op::Neg)
      return a->ops[0]; // -(-x) = x
    if (a->op == Op::IntConst)
      return int_const(-a->ival);
    if (a->op == Op::RealConst && a->exact_zero)
      return a;                                 // (a structural zero: a derivative's)
    if (a->op == Op::RealConst && a->rval == 0) // -0.0, written so (std::copysign(x, -0.0))
      return real_const(-a->rval, a->type,
                        a->spelling.empty()     ? ""
                        : a->spelling[0] == '-' ? a->spelling.substr(1)
                                                : "-" + a->spelling);
    return node(Op::Neg, a->type, {a});
  }
  if (op == Op::Not && a->op == Op::Not)
    return a->ops[0];
  return node(op, op == Op::Not ? Type::Bool : a->type, {a});
}

ExprP binary(Op op, ExprP a, ExprP b) {
  Type t = is_bool_op(op) ? Type::Bool : promote(a->type, b->type);
  if (a->op == Op::IntConst && b->op == Op::IntConst) {
    long long x = a->ival, y = b->ival;
    switch (op) {
    case Op::Add:
      return int_const(x + y);
    case Op::Sub:
      return int_const(x - y);
    case Op::Mul:
      return int_const(x * y);
    case Op::Shl: {
      long long r = 0;
      if (y >= 0 && y < 62 && !__builtin_mul_overflow(x, 1LL << y, &r))
        return int_const(r);
      break;
    }
    case Op::Shr:
      if (y >= 0 && y < 63)
        return int_const(x >> y);
      break;
    case Op::BitAnd:
      return int_const(x & y);
    case Op::BitOr:
      return int_const(x | y);
    case Op::BitXor:
      return int_const(x ^ y);
    default:
      break;
    }
  }
  switch (op) {
  case Op::Add:
    if (is_const(a, 0) && a->type == t)
      return b;
    if (is_const(b, 0) && b->type == t)
      return a;
    if (b->op == Op::Neg)
      return binary(Op::Sub, a, b->ops[0]); // a + (-b) = a - b
    break;
  case Op::Sub:
    if (is_const(b, 0) && a->type == t)
      return a;
    if (is_const(a, 0) && b->type == t)
      return unary(Op::Neg, b);
    if (b->op == Op::Neg)
      return binary(Op::Add, a, b->ops[0]); // a - (-b) = a + b
    break;
  case Op::Mul:
    if (is_const(a, 1) && b->type == t)
      return b;
    if (is_const(b, 1) && a->type == t)
      return a;
    if (is_const(a, -1) && b->type == t)
      return unary(Op::Neg, b);
    if (is_const(b, -1) && a->type == t)
      return unary(Op::Neg, a);
    if (a->op == Op::Neg && b->op == Op::Neg)
      return binary(Op::Mul, a->ops[0], b->ops[0]);
    if (a->op == Op::Neg)
      return unary(Op::Neg, binary(Op::Mul, a->ops[0], b));
    if (b->op == Op::Neg)
      return unary(Op::Neg, binary(Op::Mul, a, b->ops[0]));
    break;
  case Op::Div:
    if (is_const(b, 1) && a->type == t)
      return a;
    if (a->op == Op::Neg)
      return unary(Op::Neg, binary(Op::Div, a->ops[0], b));
    break;
  default:
    break;
  }
  return node(op, t, {std::move(a), std::move(b)});
}

// (ir.hpp)
ExprP path_condition(const std::vector<PathCond>& path, size_t from, size_t to) {
  ExprP cond;
  for (size_t i = from; i < std::min(to, path.size()); ++i) {
    ExprP c = path[i].positive ? path[i].cond : unary(Op::Not, path[i].cond);
    cond = cond ? binary(Op::And, cond, c) : c;
  }
  return cond;
}

ExprP select(ExprP c, ExprP a, ExprP b) {
  if (same(a, b))
    return a;
  Type t = a->type == b->type ? a->type : promote(a->type, b->type);
  return node(Op::Select, t, {std::move(c), std::move(a), std::move(b)});
}

ExprP call(const std::string& fn, std::vector<ExprP> args, Type t) {
  auto e = node(Op::Call, t, std::move(args));
  e->name = fn;
  return e;
}

ExprP cast(ExprP a, Type t) {
  if (a->type == t)
    return a;
  if (a->op == Op::IntConst && is_real(t))
    return real_const(static_cast<double>(a->ival), t);
  if (a->op == Op::RealConst && is_real(t))
    return real_const(a->rval, t, t == Type::Double ? a->spelling : "");
  return node(Op::Cast, t, {std::move(a)});
}

bool same(const ExprP& a, const ExprP& b) {
  if (!a || !b)
    throw std::logic_error("internal error: same: a null expression");
  if (a == b)
    return true;
  if (a->op != b->op || a->type != b->type || a->ops.size() != b->ops.size())
    return false;
  switch (a->op) {
  case Op::IntConst:
    return a->ival == b->ival;
  case Op::RealConst:
    return a->rval == b->rval;
  case Op::Local:
    return a->local == b->local;
  case Op::Param:
  case Op::LoopVar:
  case Op::Read:
  case Op::Call:
    if (a->name != b->name)
      return false;
    break;
  default:
    break;
  }
  for (size_t i = 0; i < a->ops.size(); ++i)
    if (!same(a->ops[i], b->ops[i]))
      return false;
  return true;
}

std::string internal_error_message(const std::string& kernel, const std::string& pass,
                                   const std::string& what) {
  return "internal error in dpgen (pass '" + pass + "' on kernel '" + kernel + "'): " + what +
         ". This is a bug in dpgen, not in your kernel: please report it with the kernel";
}

void test_internal_error(const char* pass) {
  const char* want = std::getenv("DPGEN_TEST_INTERNAL_ERROR");
  if (want && std::string(want) == pass)
    throw std::logic_error(std::string("DPGEN_TEST_INTERNAL_ERROR=") + pass);
}

std::string view_buffer_type(const Param& p) {
  return fmt::format("dpgen::ViewBuffer<{}, {}>", p.view_class, p.elem_name);
}

std::string view_declared_type(const Param& p, bool is_const) {
  if (p.view_buffered)
    return "const " + view_buffer_type(p) + "&";
  if (is_const)
    return p.view_type;
  switch (p.view_pass) {
  case Param::ViewPass::ConstRef:
    return "const " + p.view_class + "&";
  case Param::ViewPass::Ref:
    return p.view_class + "&";
  case Param::ViewPass::Value:
    break;
  }
  return p.view_class;
}

bool view_by_reference(const Param& p) { return p.view_buffered || p.view_reference; }

namespace {
bool ident(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// The live scopes, innermost last (renamed() uses the innermost).
std::vector<std::map<std::string, std::string>> live_renames;
} // namespace

RenameScope::RenameScope(std::map<std::string, std::string> renames) {
  live_renames.push_back(std::move(renames));
}

RenameScope::~RenameScope() { live_renames.pop_back(); }

std::string renamed(const std::string& text) {
  if (live_renames.empty() || live_renames.back().empty())
    return text;
  const auto& renames = live_renames.back();
  std::string out;
  for (size_t i = 0; i < text.size();) {
    if (!ident(text[i]) || std::isdigit(static_cast<unsigned char>(text[i]))) {
      // (a number's digits and suffix stay together)
      size_t j = i + 1;
      if (std::isdigit(static_cast<unsigned char>(text[i])))
        while (j < text.size() && ident(text[j]))
          ++j;
      out.append(text, i, j - i);
      i = j;
      continue;
    }
    size_t j = i;
    while (j < text.size() && ident(text[j]))
      ++j;
    const std::string word = text.substr(i, j - i);
    const bool member = (i >= 1 && text[i - 1] == '.') ||
                        (i >= 2 && (text.compare(i - 2, 2, "->") == 0 ||
                                    text.compare(i - 2, 2, "::") == 0));
    auto it = renames.find(word);
    out += !member && it != renames.end() ? it->second : word;
    i = j;
  }
  return out;
}

bool names_identifier(const std::string& text, const std::string& name) {
  for (size_t at = text.find(name); at != std::string::npos; at = text.find(name, at + 1))
    if ((at == 0 || !ident(text[at - 1])) &&
        (at + name.size() == text.size() || !ident(text[at + name.size()])))
      return true;
  return false;
}

// ---- conditions and counts on the sizes ---------------------------------------------------

std::string SizeCond::code() const {
  return less ? fmt::format("({}) < ({})", a.code(), b.code()) : fmt::format("({}) >= 0", a.code());
}

std::vector<SizeCond> sorted_conds(std::vector<SizeCond> v) {
  std::vector<std::pair<std::string, SizeCond>> coded;
  for (auto& c : v)
    coded.emplace_back(c.code(), std::move(c));
  std::stable_sort(coded.begin(), coded.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<SizeCond> out;
  for (size_t i = 0; i < coded.size(); ++i)
    if (i == 0 || coded[i].first != coded[i - 1].first)
      out.push_back(std::move(coded[i].second));
  return out;
}

std::string join_code(const std::vector<SizeCond>& conds, const char* sep) {
  std::string out;
  for (const auto& c : conds)
    out += (out.empty() ? "" : sep) + c.code();
  return out;
}

std::string SizeCheck::must_hold_code() const {
  std::vector<std::string> all;
  for (const auto& any : must_hold) {
    std::string one = join_code(any, " || ");
    all.push_back(any.size() > 1 && must_hold.size() > 1 ? "(" + one + ")" : one);
  }
  return fmt::format("{}", fmt::join(all, " && "));
}

bool SizeCheck::same_as(const SizeCheck& o) const {
  return must_hold_code() == o.must_hold_code() &&
         join_code(premises, " && ") == join_code(o.premises, " && ");
}

namespace {

std::string end_code(const Extent::End& e) {
  std::string end = e.end.code();
  if (!e.runs.empty())
    end = fmt::format("{} ? {} : 0", join_code(e.runs, " && "), end);
  return fmt::format("static_cast<std::ptrdiff_t>({})", end);
}

} // namespace

void Extent::add(End e) {
  const std::string code = end_code(e);
  for (const auto& o : ends)
    if (end_code(o) == code)
      return;
  ends.push_back(std::move(e));
}

std::string Extent::code() const {
  if (row_length) {
    std::string e = fmt::format("static_cast<std::ptrdiff_t>({})", row_length->code());
    for (const auto& x : rows)
      e = fmt::format("{} * std::max<std::ptrdiff_t>(0, {})", e, x.code());
    return fmt::format("std::max<std::ptrdiff_t>(0, {})", e);
  }
  std::vector<std::string> es;
  for (const auto& e : ends)
    es.push_back(end_code(e));
  return es.size() == 1 ? fmt::format("std::max<std::ptrdiff_t>(0, {})", es[0])
                        : fmt::format("std::max<std::ptrdiff_t>({{0, {}}})", fmt::join(es, ", "));
}

} // namespace dpgen
