// Emit (phase 6, --torch): the PyTorch ops of a kernel file (see emit_torch.hpp). Each op:
//  - takes the kernel's parameters in order, outputs left out: arrays as tensors, scalars
//    as `int` / `float` / `bool` arguments, then one keyword argument `<out>_shape` per output
//    (default: the shape of the first array argument);
//  - checks every tensor (CPU, the kernel's dtype, contiguous) and its size against the
//    largest index the kernel's loops reach for the given sizes, naming the argument;
//  - allocates the outputs, calls the kernel on data pointers (no copies), and in backward
//    calls the generated <kernel>_adjoint with zero-filled input adjoints.
#include "emit_torch.hpp"

#include "accesses.hpp"
#include "affine.hpp"
#include "emit_checked.hpp"
#include "emit_forward.hpp"
#include "emit_util.hpp"
#include "ir_walk.hpp"
#include "print.hpp"

#include <llvm/ADT/SmallString.h>
#include <llvm/Support/Path.h>
#include <llvm/Support/raw_ostream.h>

#include <fmt/format.h>

#include <functional>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>

namespace dpgen {

namespace {

// (an access under a data-dependent condition counts where the condition may
// hold, all of `where`: the size is checked for more, never for less)
using AccessMap = std::map<std::string, std::vector<ArrayAccess>>;

bool is_array(const Param& p) { return p.kind != ParamKind::Scalar; }

// The op's type of a scalar parameter.
std::string schema_type(const Param& p) {
  switch (p.elem) {
  case Type::Int:
    return "int";
  case Type::Bool:
    return "bool";
  default:
    return "float";
  }
}

std::string cpp_arg_type(const Param& p) {
  switch (p.elem) {
  case Type::Int:
    return "std::int64_t";
  case Type::Bool:
    return "bool";
  default:
    return "double";
  }
}

std::vector<const Param*> outputs(const Kernel& k) {
  std::vector<const Param*> out;
  for (const auto& p : k.params)
    if (p.kind == ParamKind::Out)
      out.push_back(&p);
  return out;
}

// The op's arguments: the kernel's parameters without its outputs.
std::vector<const Param*> arguments(const Kernel& k) {
  std::vector<const Param*> out;
  for (const auto& p : k.params)
    if (p.kind != ParamKind::Out)
      out.push_back(&p);
  return out;
}

const Param* first_array(const Kernel& k) {
  for (const auto& p : k.params)
    if (p.kind == ParamKind::In)
      return &p;
  for (const auto& p : k.params)
    if (p.kind == ParamKind::ConstArray)
      return &p;
  return nullptr;
}

// ---- how far each array is accessed ------------------------------------------------------

// C++ for the largest (`largest`) or smallest value of `p` over box `b` (for the largest, the
// index + 1: one past the largest index), or nullopt if a coefficient of a counter depends on
// another counter. Each counter v contributes max(c lo_v, c (hi_v - 1)), or the min.
std::optional<std::string> box_extreme(const Poly& p, const Box& b, bool largest) {
  Poly rest = p;
  std::vector<std::string> terms;
  for (const auto& [v, iv] : b.dims) {
    if (!p.mentions_counter(v))
      continue;
    Poly c = p.coefficient(Sym::counter(v));
    if (c.mentions_any_counter() || iv.lo.empty() || iv.hi.empty())
      return std::nullopt;
    rest = rest.without(Sym::counter(v));
    const std::string lo = print_max(iv.lo, "std::int64_t");
    const std::string last = print_min(iv.hi, "std::int64_t") + " - 1";
    if (c.is_constant()) {
      // (a positive coefficient: the largest at the last counter, the smallest at the first)
      const std::string& at = (c.constant_term() > 0) == largest ? last : lo;
      terms.push_back(c.constant_term() == 1 ? fmt::format("({})", at)
                                             : fmt::format("{} * ({})", c.code(), at));
    } else {
      terms.push_back(fmt::format("std::{}<std::int64_t>(({}) * ({}), ({}) * ({}))",
                                  largest ? "max" : "min", c.code(), lo, c.code(), last));
    }
  }
  if (rest.mentions_any_counter())
    return std::nullopt;
  std::string out = rest.is_constant() && rest.constant_term() == 0 && !terms.empty()
                        ? ""
                        : rest.code();
  for (const auto& t : terms)
    out += (out.empty() ? "" : " + ") + t;
  return out;
}

// C++: the box is not empty.
std::string box_nonempty(const Box& b) {
  std::vector<std::string> parts;
  for (const auto& [v, iv] : b.dims)
    if (!iv.lo.empty() && !iv.hi.empty())
      parts.push_back(fmt::format("{} < {}", print_max(iv.lo, "std::int64_t"),
                                  print_min(iv.hi, "std::int64_t")));
  return parts.empty() ? "true" : fmt::format("{}", fmt::join(parts, " && "));
}

bool params_only(const ExprP& e) {
  if (!e)
    throw std::logic_error("internal error: torch: a null expression");
  if (e->op == Op::Read || e->op == Op::Local || e->op == Op::LoopVar)
    return false;
  for (const auto& o : e->ops)
    if (!params_only(o))
      return false;
  return true;
}

// ---- the code -------------------------------------------------------------------------------

std::string qualified(const Kernel& k, const std::string& name) {
  std::string q = "::";
  for (const auto& ns : k.namespaces)
    q += ns + "::";
  return q + name;
}

// `elem*` pointer expression of tensor `t` for parameter p, cast to the kernel's shape (the
// type array_declaration gives the kernel's and the adjoint's parameter).
std::string pointer(const Param& p, const std::string& t, bool is_const) {
  std::string ptr = fmt::format("{}.data_ptr<{}>()", t, p.elem_name);
  if (p.rows.empty())
    return ptr;
  std::string decl = array_declaration(p, is_const, "", true);
  // "const double (*)[64]" from "const double (*)[64]" with the name left out
  return fmt::format("reinterpret_cast<{}>({})", decl, ptr);
}

// The adjoint argument of input p in backward: its adjoint tensor, or nullptr where autograd
// needs no gradient for it (the generated adjoint skips an inactive input's loops).
std::string adjoint_pointer(const Param& p, const std::string& t) {
  return fmt::format("{}.defined() ? {} : nullptr", t, pointer(p, t, false));
}

// The keyword argument that gives output `p`'s shape (<output>_shape).
std::string shape_name(const Kernel& k, const Param& p) { return k.fresh(p.name + "_shape"); }

// The value the kernel gets for a scalar op argument (`op`: the generated
// variable that holds the op's name, for errors).
std::string scalar_value(const Param& p, const std::string& op) {
  if (p.elem == Type::Int)
    return fmt::format("dpgen::torch_ops::narrow<{}>({}, {}, \"{}\")", p.elem_name, p.name, op,
                       p.name);
  if (p.elem == Type::Float)
    return fmt::format("static_cast<float>({})", p.name);
  return p.name;
}

// The op's C++ parameter list (header and definition).
std::string op_params(const Kernel& k, bool defaults) {
  std::vector<std::string> ps;
  for (const Param* p : arguments(k))
    ps.push_back(is_array(*p) ? fmt::format("const torch::Tensor& {}", p->name)
                              : fmt::format("{} {}", cpp_arg_type(*p), p->name));
  for (const Param* p : outputs(k))
    ps.push_back(fmt::format("at::OptionalIntArrayRef {}{}", shape_name(k, *p),
                             defaults ? " = c10::nullopt" : ""));
  return fmt::format("{}", fmt::join(ps, ", "));
}

std::string op_return(const Kernel& k) {
  const size_t n = outputs(k).size();
  if (n == 1)
    return "torch::Tensor";
  std::vector<std::string> ts(n, "torch::Tensor");
  return fmt::format("std::tuple<{}>", fmt::join(ts, ", "));
}

// The sizes named in size errors: "n = ", n, ", dt = ", dt.
std::string sizes_message(const Kernel& k) {
  std::vector<std::string> parts;
  for (const auto& p : k.params)
    if (p.kind == ParamKind::Scalar && p.elem == Type::Int && !p.synthetic)
      parts.push_back(fmt::format("\"{}{} = \", {}", parts.empty() ? "" : ", ", p.name, p.name));
  if (parts.empty())
    return "\"these arguments\"";
  return fmt::format("{}", fmt::join(parts, ", "));
}

// Checks of one array's size against the largest index the kernel reaches.
// Returns false where some index into `p` cannot be bounded from the loops (data-dependent).
bool emit_extent_check(Code& c, const Kernel& k, const Param& p, const AccessMap& m,
                       const std::string& guard, bool reach) {
  auto it = m.find(p.name);
  if (it == m.end())
    return true;
  struct Term {
    std::string cond, end, least; // one past the largest index, and the smallest
    bool operator==(const Term& o) const {
      return cond == o.cond && end == o.end && least == o.least;
    }
  };
  std::vector<Term> terms;
  bool complete = true;
  for (const auto& a : it->second) {
    auto pieces = index_pieces(a.index);
    if (!pieces) {
      complete = false;
      continue;
    }
    for (const auto& piece : *pieces)
      for (const auto& b : intersect(a.where, piece.where)) {
        auto end = box_extreme(piece.value + Poly::constant(1), b, true);
        auto least = box_extreme(piece.value, b, false);
        if (!end || !least) {
          complete = false;
          continue;
        }
        Term t{box_nonempty(b), *end, *least};
        if (std::find(terms.begin(), terms.end(), t) == terms.end())
          terms.push_back(t);
      }
  }
  const std::string rest = reach ? fmt::format("{}, below", reach_name(k)) : "not checked here";
  if (terms.empty()) {
    if (!complete)
      c.line("// '{}' is read at data-dependent indices: its size is {}.", p.name,
             reach ? "checked by " + rest : rest);
    return complete;
  }
  c.line("{{ // '{}': one past the largest index the kernel reaches, and the smallest{}", p.name,
         complete ? "" : " (some reads are data-dependent: " + rest + ")");
  const std::string needed = k.fresh("needed"), least = k.fresh("least"), op = k.fresh("op");
  c.line("std::int64_t {} = 0, {} = 0;", needed, least);
  for (const auto& t : terms) {
    std::string when = guard.empty() ? t.cond : t.cond == "true" ? guard : guard + " && " + t.cond;
    const std::string update = fmt::format(
        "{{ {} = std::max<std::int64_t>({}, {}); {} = std::min<std::int64_t>({}, {}); }}", needed,
        needed, t.end, least, least, t.least);
    if (when == "true")
      c.line("{}", update);
    else
      c.line("if ({}) {}", when, update);
  }
  c.line("TORCH_CHECK({}.numel() >= {}, {}, \": {} '{}' has \", {}.numel(), \" elements "
         "(sizes \", {}.sizes(), \") but the kernel reaches element \", {} - 1, \" for \", "
         "{});",
         p.name, needed, op, p.kind == ParamKind::Out ? "output" : "argument", p.name, p.name,
         p.name, needed, sizes_message(k));
  c.line("TORCH_CHECK({} >= 0, {}, \": the kernel reaches element \", {}, \" of {} '{}' for \", "
         "{});",
         least, op, least, p.kind == ParamKind::Out ? "output" : "argument", p.name,
         sizes_message(k));
  c.line("}}");
  return complete;
}

// C++ for "the kernel writes each element 0 .. numel - 1 of output `p`" (`numel` a C++
// expression), or "" where the generator cannot tell: then the output is zero-filled. The test
// holds where the kernel has one store to `p`, `=` under no condition, in a nest whose every
// counter moves its index affinely: the innermost with coefficient 1, each outer one with the
// product of the inner loops' extents (row-major, no gap, no overlap). The elements written are
// then base .. base + (product of the extents) - 1, each by one iteration; the run-time part
// checks the extents are positive, base is 0 and the count is numel. (A kernel's guards, `if
// (n < 3) return;`, are on the path of every store after them: such a store does not qualify.)
std::string writes_every_element(const Kernel& k, const Param& p, const std::string& numel) {
  const Nest* nest = nullptr;
  const Store* store = nullptr;
  for (const auto& n : k.nests)
    for (const auto& s : n.stores)
      if (s.array == p.name) {
        if (store)
          return ""; // (two stores: under complementary conditions, or overwriting)
        nest = &n, store = &s;
      }
  if (!store || store->accumulate || !store->path.empty())
    return "";
  auto index = to_poly(store->index);
  if (!index)
    return "";
  Poly base = *index, inner_count = Poly::constant(1);
  std::vector<std::string> conds;
  for (auto l = nest->loops.rbegin(); l != nest->loops.rend(); ++l) {
    auto lo = to_poly(l->lo), hi = to_poly(l->hi);
    const Poly c = index->coefficient(Sym::counter(l->var));
    if (!lo || !hi || !(c == inner_count))
      return "";
    base = base.without(Sym::counter(l->var)) + c * *lo;
    const Poly extent = *hi - *lo;
    conds.push_back(fmt::format("({}) > 0", extent.code()));
    inner_count = inner_count * extent;
  }
  if (base.mentions_any_counter())
    return "";
  if (base.is_constant() && base.constant_term() != 0)
    return "";
  if (!(base == Poly()))
    conds.push_back(fmt::format("({}) == 0", base.code()));
  conds.push_back(fmt::format("({}) == {}", inner_count.code(), numel));
  return fmt::format("{}", fmt::join(conds, " && "));
}

void emit_kernel(Code& c, const Kernel& k) {
  const auto outs = outputs(k);
  const auto args = arguments(k);
  const Param* first = first_array(k);
  const AccessMap m = array_accesses(k);
  const std::string fn = k.name + "_function";
  // Kernel-level guards that mention only parameters: where they fail, the kernel writes
  // nothing and reads nothing.
  std::vector<std::string> gs;
  for (const auto& g : k.guards)
    if (params_only(g.cond))
      gs.push_back(g.positive ? "(" + print(g.cond) + ")" : "!(" + print(g.cond) + ")");
  const std::string guard = fmt::format("{}", fmt::join(gs, " && "));

  // The forward: the kernel's IR printed with its nests on every thread where each sets its
  // elements once (<kernel>_parallel_forward of the adjoint files), else the kernel as written.
  const bool parallel = has_parallel_forward(k);
  c.line("// torch.ops.dpgen.{}: forward = {} ({}:{}){}, backward = {}_adjoint.", k.name, k.name,
         base_name(k.file), k.pos.line, parallel ? ", its nests on every thread" : "", k.name);
  c.line("struct {} : public torch::autograd::Function<{}> {{", fn, fn);
  // forward
  // Generated names (Kernel::fresh: none is one of the kernel's parameters).
  const std::string ctx = k.fresh("ctx"), op = k.fresh("op"), saved_v = k.fresh("saved"),
                    grads = k.fresh("grads");
  std::vector<std::string> fparams = {"torch::autograd::AutogradContext* " + ctx};
  for (const Param* p : args)
    fparams.push_back(is_array(*p) ? fmt::format("const torch::Tensor& {}", p->name)
                                   : fmt::format("{} {}", cpp_arg_type(*p), p->name));
  for (const Param* p : outs)
    fparams.push_back(
        fmt::format("const c10::optional<std::vector<std::int64_t>>& {}", shape_name(k, *p)));
  c.line("static {} forward({}) {{", outs.size() == 1 ? "torch::Tensor" : "torch::autograd::variable_list",
         fmt::join(fparams, ", "));
  c.line("const char* {} = \"dpgen::{}\";", op, k.name);
  for (const Param* p : args)
    if (is_array(*p))
      c.line("dpgen::torch_ops::check_array<{}>({}, {}, \"{}\", \"{}\");", p->elem_name, p->name,
             op, p->name, p->elem_name);
  // Kernel-level locals (sizes derived from the size arguments: `const int m = n - 1;`), which
  // the extents below may mention; none reads an array (emit_torch_file rejects that).
  for (const auto& l : k.kernel_locals)
    c.line("[[maybe_unused]] const {} {} = {};", l->type_name, l->name, print(l->def));
  for (const Param* p : outs) {
    c.line("// Output '{}': shape {}, by default that of '{}'.", p->name, shape_name(k, *p),
           first->name);
    const std::string shape = k.fresh(p->name + "_sizes");
    c.line("const std::vector<std::int64_t> {} = dpgen::torch_ops::output_shape({}, {}, {}, "
           "\"{}\");",
           shape, shape_name(k, *p), first->name, op, p->name);
    const std::string all =
        writes_every_element(k, *p, fmt::format("dpgen::torch_ops::numel_of({})", shape));
    if (all.empty()) {
      c.line("torch::Tensor {} = dpgen::torch_ops::new_output({}, {});", p->name, shape,
             first->name);
    } else {
      c.line("// (not zero-filled where the kernel writes each of its elements)");
      c.line("torch::Tensor {} = dpgen::torch_ops::new_output({}, {}, {});", p->name, shape,
             first->name, all);
    }
    if (p->elem_name != first->elem_name)
      c.line("{} = {}.to(dpgen::torch_ops::dtype_of<{}>());", p->name, p->name, p->elem_name);
  }
  // Indices that depend on the data: the kernel's loops run once with each checked
  // (emit_checked.cpp: <kernel>_check_reach), where the adjoint files have that function.
  const bool reach = needs_probe(k);
  bool bounded = true;
  for (const auto& p : k.params)
    if (is_array(p))
      bounded = emit_extent_check(c, k, p, m, guard, reach) && bounded;
  if (!bounded && reach) {
    std::vector<std::string> args = {op};
    for (const auto& p : k.params) {
      if (p.global)
        continue;
      if (!is_array(p)) {
        args.push_back(scalar_value(p, op));
        continue;
      }
      const std::string data = fmt::format("{}.data_ptr<{}>()", p.name, p.elem_name),
                        size = fmt::format("static_cast<std::size_t>({}.numel())", p.name);
      args.insert(args.end(), {data, size});
      if (p.kind == ParamKind::In) // (no adjoint yet)
        args.insert(args.end(), {"nullptr", "0"});
    }
    // (its std::invalid_argument as the RuntimeError of the other checks)
    const std::string e = k.fresh("e");
    c.line("try {{ {}({}); }} catch (const std::invalid_argument& {}) {{ TORCH_CHECK(false, "
           "{}.what()); "
           "}}",
           qualified(k, reach_name(k)), fmt::join(args, ", "), e, e);
  }
  std::vector<std::string> call;
  for (const auto& p : k.params)
    call.push_back(!is_array(p) ? scalar_value(p, op)
                   : parallel   ? fmt::format("{}.data_ptr<{}>()", p.name, p.elem_name)
                                : pointer(p, p.name, p.kind != ParamKind::Out));
  c.line("{}({});", qualified(k, parallel ? k.name + "_parallel_forward" : k.name),
         fmt::join(call, ", "));
  std::vector<std::string> saved;
  for (const Param* p : args)
    if (is_array(*p))
      saved.push_back(p->name);
  c.line("{}->save_for_backward({{{}}});", ctx, fmt::join(saved, ", "));
  for (const Param* p : args)
    if (!is_array(*p))
      c.line("{}->saved_data[\"{}\"] = {};", ctx, p->name, p->name);
  for (const Param* p : outs)
    c.line("{}->saved_data[\"{}_shape\"] = {}.sizes().vec();", ctx, p->name, p->name);
  if (outs.size() == 1) {
    c.line("return {};", outs[0]->name);
  } else {
    std::vector<std::string> names;
    for (const Param* p : outs)
      names.push_back(p->name);
    c.line("return {{{}}};", fmt::join(names, ", "));
  }
  c.line("}}");
  c.raw("\n");

  // backward
  c.line("static torch::autograd::variable_list backward(torch::autograd::AutogradContext* {}, "
         "torch::autograd::variable_list {}) {{",
         ctx, grads);
  c.line("const char* {} = \"dpgen::{}\";", op, k.name);
  c.line("dpgen::torch_ops::no_double_backward({});", op);
  c.line("const torch::autograd::variable_list {} = {}->get_saved_variables();", saved_v, ctx);
  size_t si = 0;
  for (const Param* p : args)
    if (is_array(*p))
      c.line("const torch::Tensor& {} = {}[{}];", p->name, saved_v, si++);
    else
      c.line("const {} {} = {}->saved_data[\"{}\"].{}();", cpp_arg_type(*p), p->name, ctx,
             p->name,
             p->elem == Type::Int ? "toInt" : p->elem == Type::Bool ? "toBool" : "toDouble");
  for (size_t i = 0; i < outs.size(); ++i)
    c.line("const torch::Tensor {}_adj = dpgen::torch_ops::seed({}[{}], "
           "{}->saved_data[\"{}_shape\"].toIntVector(), {}.options());",
           outs[i]->name, grads, i, ctx, outs[i]->name, first->name);
  {
    size_t edge = 0; // the index among the tensor arguments: autograd's input edges
    for (const Param* p : args) {
      if (!is_array(*p))
        continue;
      if (p->kind == ParamKind::In)
        c.line("const torch::Tensor {}_adj = {}->needs_input_grad({}) ? torch::zeros_like({}) : "
               "torch::Tensor();",
               p->name, ctx, edge, p->name);
      ++edge;
    }
  }
  std::vector<std::string> acall;
  for (const auto& p : k.params) {
    if (p.synthetic)
      continue;
    switch (p.kind) {
    case ParamKind::In:
      acall.push_back(pointer(p, p.name, true));
      acall.push_back(adjoint_pointer(p, p.name + "_adj"));
      break;
    case ParamKind::Out:
      acall.push_back(pointer(p, p.name + "_adj", true));
      break;
    case ParamKind::ConstArray:
      acall.push_back(pointer(p, p.name, true));
      break;
    case ParamKind::Scalar:
      acall.push_back(scalar_value(p, op));
      break;
    }
  }
  c.line("{}_adjoint({});", qualified(k, k.name), fmt::join(acall, ", "));
  std::vector<std::string> ret;
  for (const Param* p : args)
    ret.push_back(p->kind == ParamKind::In ? p->name + "_adj" : "torch::Tensor()");
  for (size_t i = 0; i < outs.size(); ++i)
    ret.push_back("torch::Tensor()");
  c.line("return {{{}}};", fmt::join(ret, ", "));
  c.line("}}");
  c.line("}};");
  c.raw("\n");
}

void emit_entry(Code& c, const Kernel& k) {
  const auto outs = outputs(k);
  std::vector<std::string> as;
  for (const Param* p : arguments(k))
    as.push_back(p->name);
  for (const Param* p : outs)
    as.push_back(fmt::format("dpgen::torch_ops::shape_arg({})", shape_name(k, *p)));
  c.line("{} {}({}) {{", op_return(k), k.name, op_params(k, false));
  if (outs.size() == 1) {
    c.line("return {}_function::apply({});", k.name, fmt::join(as, ", "));
  } else {
    const std::string out = k.fresh("out");
    c.line("const torch::autograd::variable_list {} = {}_function::apply({});", out, k.name,
           fmt::join(as, ", "));
    std::vector<std::string> items;
    for (size_t i = 0; i < outs.size(); ++i)
      items.push_back(fmt::format("{}[{}]", out, i));
    c.line("return {{{}}};", fmt::join(items, ", "));
  }
  c.line("}}");
  c.raw("\n");
}

std::string error_at(const Kernel& k, const std::string& what) {
  return fmt::format("{}:{}:{}: error: {} [dpgen-torch]", k.pos.file, k.pos.line, k.pos.col, what);
}

const char* kTorchBanner = "// Generated by dpgen --torch from {} -- do not edit; edit the kernel "
                           "and rebuild.\n";

} // namespace

std::string torch_schema(const Kernel& k) {
  std::vector<std::string> as;
  for (const Param* p : arguments(k))
    as.push_back(fmt::format("{} {}", is_array(*p) ? "Tensor" : schema_type(*p), p->name));
  as.push_back("*");
  for (const Param* p : outputs(k))
    as.push_back(fmt::format("int[]? {}=None", shape_name(k, *p)));
  const size_t n = outputs(k).size();
  std::vector<std::string> rs(n, "Tensor");
  std::string ret = n == 1 ? "Tensor" : fmt::format("({})", fmt::join(rs, ", "));
  return fmt::format("{}({}) -> {}", k.name, fmt::join(as, ", "), ret);
}

TorchFile emit_torch_file(const std::vector<AdjointPlan>& plans, const std::string& source_name,
                          const std::string& stem) {
  TorchFile out;
  std::set<std::string> names;
  for (const auto& plan : plans) {
    const Kernel& k = *plan.kernel;
    if (!k.member_class.empty())
      out.errors.push_back(error_at(
          k, fmt::format("kernel '{}' is a member function: a torch op has no object to call it "
                         "on; for --torch write a free kernel taking the members it reads",
                         k.display_name())));
    for (const auto& p : k.params) {
      if (p.synthetic || !p.twin_of.empty())
        continue;
      if (p.view || p.object)
        out.errors.push_back(error_at(
            k, fmt::format("kernel '{}': {} '{}' ({}) is no tensor; for --torch pass {}",
                           k.display_name(), p.view ? "array view" : "object", p.name,
                           p.view ? p.view_type : p.elem_name,
                           p.view ? "its data as a pointer with its sizes"
                                  : "the numbers it holds as scalars")));
      else if (!p.container.empty())
        out.errors.push_back(error_at(
            k, fmt::format("kernel '{}': std::vector parameter '{}' cannot be a torch op "
                           "argument without a copy; declare it as a pointer ({}*) for --torch",
                           k.name, p.name, p.elem_name)));
      else if (p.inout)
        out.errors.push_back(error_at(
            k, fmt::format("kernel '{}': DPGEN_INOUT array '{}' is updated in place, which a "
                           "torch op cannot do to a tensor autograd tracks; for --torch write "
                           "the new values into a separate DPGEN_OUT array",
                           k.name, p.name)));
      else if (p.global)
        out.errors.push_back(error_at(
            k, fmt::format("kernel '{}': it reads global '{}', which a torch op cannot see as a "
                           "tensor; for --torch pass it as a parameter",
                           k.name, p.name)));
      else if (p.tag)
        out.errors.push_back(error_at(
            k, fmt::format("kernel '{}': its tag parameter ({}) picks an overload, which a torch "
                           "op cannot; for --torch give each overload a name of its own",
                           k.name, p.spelling)));
      else if (p.scalar_ref)
        out.errors.push_back(error_at(
            k, fmt::format("kernel '{}': {} is a scalar by reference, not a tensor; for --torch "
                           "make it a one-element array ({}* {})",
                           k.name, p.returned ? "the return value" : "'" + p.name + "'",
                           p.elem_name, p.name)));
      else if (p.row_pointers)
        out.errors.push_back(error_at(
            k, fmt::format("kernel '{}': row-pointer array '{}' ({}**) is not one tensor; for "
                           "--torch declare it as a flat pointer or as rows of a fixed length "
                           "({} (*{})[N])",
                           k.name, p.name, p.elem_name, p.elem_name, p.name)));
      else if (k.c_linkage && !p.rows.empty())
        out.errors.push_back(error_at(
            k, fmt::format("kernel '{}': C array of rows '{}' is not supported by --torch; "
                           "declare it as a flat pointer",
                           k.name, p.name)));
    }
    for (const auto& l : k.kernel_locals) {
      std::string array;
      if (any_node(l->def, [&](const ExprP& x) {
            if (x->op == Op::Read)
              array = x->name;
            return x->op == Op::Read;
          }))
        out.errors.push_back(error_at(
            k, fmt::format("kernel '{}': '{}' is read from array '{}' before the loops (a size "
                           "passed by pointer?); a torch op checks its tensors' sizes against "
                           "numbers: for --torch pass it by value",
                           k.name, l->name, array)));
    }
    if (!names.insert(k.name).second)
      out.errors.push_back(error_at(
          k, fmt::format("two kernels named '{}' in different namespaces would be the same op "
                         "torch.ops.dpgen.{}",
                         k.name, k.name)));
  }
  if (!out.errors.empty())
    return out;

  Code h;
  h.raw(fmt::format(kTorchBanner, source_name));
  h.raw("//\n"
        "// The kernels of " +
        source_name +
        " as PyTorch ops, callable from C++ here and from Python as\n"
        "// torch.ops.dpgen.<kernel>(...) once the library is loaded. Each takes the kernel's\n"
        "// parameters in order without its outputs (arrays as contiguous CPU tensors of the\n"
        "// kernel's dtype, scalars as numbers), then `<output>_shape` per output (default: the\n"
        "// shape of the first array argument); it returns the outputs. Backward runs the\n"
        "// generated adjoint.\n"
        "#pragma once\n\n#include <torch/torch.h>\n\n#include <cstdint>\n#include <tuple>\n\n"
        "namespace dpgen::ops {\n\n");
  for (const auto& plan : plans) {
    const Kernel& k = *plan.kernel;
    h.line("/// torch.ops.dpgen.{}", torch_schema(k));
    h.line("{} {}({});", op_return(k), k.name, op_params(k, true));
    h.raw("\n");
  }
  h.raw("} // namespace dpgen::ops\n");
  out.header = formatted(h.str(), stem + "_torch.hpp");

  Code c;
  c.raw(fmt::format(kTorchBanner, source_name));
  c.raw("//\n"
        "// One torch::autograd::Function per kernel: forward checks the arguments (CPU, the\n"
        "// kernel's dtype, contiguous, large enough for the largest index the loops reach),\n"
        "// allocates the outputs and calls the kernel on the tensors' data (a kernel with a nest\n"
        "// that sets each element once: <kernel>_parallel_forward, its IR printed with that\n"
        "// nest on every thread, the same values); backward calls the generated adjoint\n"
        "// with zero-filled input adjoints. Registered with\n"
        "// TORCH_LIBRARY_FRAGMENT(dpgen, m), so several generated files share the namespace.\n");
  c.raw(fmt::format("#include \"{}_torch.hpp\"\n\n#include \"{}_adjoint.hpp\"\n#include "
                    "\"{}_kernels.hpp\"\n#include \"dpgen/torch.hpp\"\n\n#include "
                    "<torch/library.h>\n\n",
                    stem, stem, stem));
  c.raw("#include <algorithm>\n#include <cstdint>\n#include <stdexcept>\n#include <vector>\n");
  c.raw("\nnamespace {\n\n");
  for (const auto& plan : plans)
    emit_kernel(c, *plan.kernel);
  c.raw("} // namespace\n\nnamespace dpgen::ops {\n\n");
  for (const auto& plan : plans)
    emit_entry(c, *plan.kernel);
  c.raw("} // namespace dpgen::ops\n\n");
  c.raw("TORCH_LIBRARY_FRAGMENT(dpgen, m) {\n");
  for (const auto& plan : plans)
    c.line("m.def(\"{}\", &dpgen::ops::{});", torch_schema(*plan.kernel), plan.kernel->name);
  c.raw("}\n");
  out.source = formatted(c.str(), stem + "_torch.cpp");
  return out;
}

bool add_torch_files(const std::vector<AdjointPlan>& plans, const std::string& input,
                     const std::string& out_dir, std::vector<PendingFile>& pending) {
  const std::string stem = llvm::sys::path::stem(input).str();
  TorchFile f = emit_torch_file(plans, llvm::sys::path::filename(input).str(), stem);
  for (const auto& e : f.errors)
    llvm::errs() << e << "\n";
  if (!f.errors.empty())
    return false;
  llvm::SmallString<256> hpp(out_dir), cpp(out_dir);
  llvm::sys::path::append(hpp, stem + "_torch.hpp");
  llvm::sys::path::append(cpp, stem + "_torch.cpp");
  pending.push_back({std::string(hpp), f.header});
  pending.push_back({std::string(cpp), f.source});
  return true;
}

} // namespace dpgen
