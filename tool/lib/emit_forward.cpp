// Emit (phase 6): a forward kernel printed from the IR (emit_forward.hpp).
#include "emit_forward.hpp"

#include "hoist.hpp"
#include "print.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace dpgen {

namespace {

// A loop bound in the counters' type (a size_t size minus one stays signed).
std::string bound(const ExprP& e) {
  if (e->op == Op::IntConst)
    return print(e);
  return fmt::format("static_cast<{}>({})", kCellType, print(e));
}

} // namespace

void emit_forward_nest(Code& code, const Kernel& k, const ForwardNest& plan, bool tangent,
                       const ForwardOptions& options) {
  const Nest& nest = *plan.nest;
  code.open("");
  int opened = 1;
  // The outermost loop on every thread: its body a lambda of its counter (threaded_loop).
  std::string threads, header, iteration;
  for (size_t d = 0; d < nest.loops.size(); ++d) {
    const Loop& l = nest.loops[d];
    const std::string for_line = fmt::format("for ({} {} = {}; {} < {}; ++{})", kCellType, l.var,
                                             bound(l.lo), l.var, bound(l.hi), l.var);
    if (d == 0 && plan.parallel && options.threads) {
      // Every element is written by one iteration (proved, or checked on
      // entry), so iterations are independent (and their order is free).
      std::vector<std::string> extents;
      for (const auto& m : nest.loops)
        extents.push_back(fmt::format("({} - {})", bound(m.hi), bound(m.lo)));
      threads = fmt::format("{} >= {}", fmt::join(extents, " * "), kMinParallelIterations);
      header = for_line;
      iteration = k.fresh("iteration");
      code.open(fmt::format("auto {} = [&](const {} {})", iteration, kCellType, l.var));
    } else if (l.descending) {
      // counted down as the kernel counts: a sum adds in the kernel's order
      code.open(fmt::format("for ({} {} = {} - 1; {} >= {}; --{})", kCellType, l.var, bound(l.hi),
                            l.var, bound(l.lo), l.var));
    } else {
      code.open(for_line);
    }
    ++opened;
  }
  std::set<int> done;
  std::set<std::string> vars;
  if (plan.stores.size() != nest.stores.size() ||
      (tangent && std::any_of(plan.stores.begin(), plan.stores.end(),
                              [](const ForwardStore& fs) { return !fs.dot; })))
    throw std::logic_error("internal error: emit: a forward nest's stores are not planned");
  for (const ForwardStore& fs : plan.stores) {
    const Store& s = *fs.store;
    const ExprP& index = fs.index;
    const ExprP& value = fs.value;
    const ExprP dot = tangent ? fs.dot : zero(s.value->type);
    bool guarded = open_guard(code, fs.path, done, vars);
    std::map<int, LocalP> locals;
    collect(index, locals, vars);
    collect(value, locals, vars);
    collect(dot, locals, vars);
    std::set<int> inner = done;
    define_locals(code, locals, guarded ? inner : done);
    const char* op = s.accumulate ? "+=" : "=";
    std::string idx = subscript(index, k.shape_of(s.array));
    std::string dot_text = !is_zero(dot)                             ? print(dot)
                           : type_spelling(s.value->type) == "float" ? "0.0f"
                                                                     : "0.0";
    const Param* twin = k.find_param(s.array);
    if (twin && !twin->twin_of.empty() && options.in_place) {
      // In place: both values from the old element first, then the stores.
      // (in a block of its own: a later in-place store under a condition in
      // the same iteration declares the same names without shadowing these)
      const std::string& u = twin->twin_of;
      const std::string new_value = k.fresh(u + "_new_value");
      const std::string value_dot = k.fresh(u + "_new_dot");
      code.open("");
      code.line("const {} {} = {};", type_spelling(s.value->type), new_value, print(value));
      if (tangent)
        code.line("const {} {} = {};", type_spelling(s.value->type), value_dot, dot_text);
      code.line("{}{} = {};", u, idx, new_value);
      if (tangent)
        code.line("{}_dot{} = {};", u, idx, value_dot);
      code.close();
    } else if (s.extremum != 0 || !tangent) {
      // (a min/max scan is a constant to derivatives: its tangent stays what
      // its first store set, 0)
      code.line("{}", store_statement(s, s.array + idx, print(value)));
    } else {
      code.line("{}{} {} {};", s.array, idx, op, print(value));
      code.line("{}_dot{} {} {};", s.array, idx, op, dot_text);
    }
    if (guarded)
      code.close();
  }
  for (int i = 0; i < opened; ++i) {
    if (i == opened - 2 && !iteration.empty()) { // the outermost loop's body
      code.close(";");
      threaded_loop(code, threads, header,
                    fmt::format("{}({});", iteration, nest.loops.front().var));
    } else {
      code.close();
    }
  }
}

void emit_recompute(Code& code, const ForwardPlan& plan, const std::string& name) {
  const Kernel& k = *plan.kernel;
  std::vector<std::string> ps;
  for (const auto& p : k.params) {
    if (p.global)
      continue;
    if (!p.twin_of.empty()) { // an in-place array's new values: to a buffer
      ps.push_back(fmt::format("{}* {}", p.elem_name, p.name));
      continue;
    }
    if (p.kind == ParamKind::Scalar)
      ps.push_back(fmt::format("{} {}", p.spelling, p.name));
    else if (p.view && p.kind == ParamKind::Out) { // the driver's buffer laid out like the view,
      // and the view's seed, whose shape is the view's (what the kernel reads of it)
      ps.push_back(fmt::format("{}& {}", view_buffer_type(p), p.name));
      ps.push_back("[[maybe_unused]] " + array_declaration(p, true, p.name + "_adj", false,
                                                           k.c_linkage));
    }
    else
      ps.push_back(array_declaration(p, p.kind != ParamKind::Out, p.name, false, k.c_linkage));
  }
  for (const auto& h : k.hidden)
    ps.push_back(fmt::format("{}* {}", h.elem_name, h.name));
  if (k.hidden.empty()) { // (an in-place array's new values, view outputs)
    std::vector<std::string> what;
    if (std::any_of(k.params.begin(), k.params.end(),
                    [](const Param& p) { return !p.twin_of.empty(); }))
      what.push_back("in-place arrays' new values");
    if (std::any_of(k.params.begin(), k.params.end(),
                    [](const Param& p) { return p.view && p.kind == ParamKind::Out; }))
      what.push_back("view outputs (laid out like their seeds)");
    code.line("// {} as its IR says, writing its {} to buffers.", k.name,
              fmt::join(what, " and "));
  } else
    code.line("// {} as its IR says, with {} ({}) kept in arrays.", k.name,
            std::all_of(k.hidden.begin(), k.hidden.end(), [](const Param& h) { return !is_buffer(h); })
                ? "the sums of its accumulators"
                : "the sums of its accumulators and the rows of its line buffers",
            [&] {
              std::vector<std::string> names; // (a min/max reduction has four)
              for (const auto& h : k.hidden)
                if (std::find(names.begin(), names.end(), h.spelling) == names.end())
                  names.push_back(h.spelling);
              return fmt::format("{}", fmt::join(names, ", "));
            }());
  code.open(fmt::format("void {}({})", name, fmt::join(ps, ", ")));
  define_kernel_locals(code, k);
  // serial, the in-place arrays' new values to their buffers
  ForwardOptions serial;
  serial.threads = false;
  serial.in_place = false;
  emit_forward_nests(code, plan, serial, false);
  code.close();
}

void emit_forward_nests(Code& code, const ForwardPlan& plan, const ForwardOptions& options,
                        bool comments) {
  emit_hoisted(code, plan.hoisted);
  for (size_t n = 0; n < plan.nests.size(); ++n) {
    const ForwardNest& f = plan.nests[n];
    if (comments)
      code.line("// loop nest {}{}", n + 1,
                f.parallel || f.nest->loops.empty() ? "" : " (serial: a store adds)");
    emit_forward_nest(code, *plan.kernel, f, false, options);
  }
}

bool has_parallel_forward(const Kernel& k) {
  // (the sums of accumulators would need buffers the kernel does not
  // allocate; in-place arrays, views, objects and the rest are no torch
  // arguments)
  if (!k.hidden.empty() || has_inout(k) || has_vectors(k) || !k.member_class.empty() ||
      !k.template_name.empty())
    return false;
  for (const auto& p : k.params)
    if (p.view || p.object || p.global || p.row_pointers || p.scalar_ref || p.returned || p.tag ||
        !p.twin_of.empty())
      return false;
  const ForwardPlan plan = plan_forward(k);
  return std::any_of(plan.nests.begin(), plan.nests.end(),
                     [](const ForwardNest& n) { return n.parallel; });
}

std::string parallel_forward_signature(const Kernel& k) {
  std::vector<std::string> ps;
  for (const auto& p : k.params)
    ps.push_back(p.kind == ParamKind::Scalar
                     ? fmt::format("{} {}", p.spelling, p.name)
                     : array_declaration(p, p.kind != ParamKind::Out, p.name, false, k.c_linkage));
  return fmt::format("void {}_parallel_forward({})", k.name, fmt::join(ps, ", "));
}

void emit_parallel_forward(Code& code, const ForwardPlan& plan) {
  const Kernel& k = *plan.kernel;
  code.line("// {} ({}:{}) printed from the IR, its nests that set each element once on every "
            "thread: the same stores in the same order per element, so the same results.",
            k.name, base_name(k.file), k.pos.line);
  code.open(parallel_forward_signature(k));
  define_kernel_locals(code, k);
  emit_size_checks(code, k, k.name);
  emit_forward_nests(code, plan, ForwardOptions{}, true);
  code.close();
}

} // namespace dpgen
