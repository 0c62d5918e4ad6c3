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

namespace {

// The stores of one iteration, in order (each with its guard and the locals
// it reads).
void emit_stores(Code& code, const Kernel& k, const std::vector<ForwardStore>& stores, bool tangent,
                 const ForwardOptions& options) {
  std::set<int> done;
  std::set<std::string> vars;
  for (const ForwardStore& fs : stores) {
    const Store& s = *fs.store;
    const ExprP& index = fs.index;
    const ExprP& value = fs.value;
    const ExprP dot = tangent ? fs.dot : zero(s.value->type);
    std::set<int> inner;
    const int guards = open_guard(code, fs.path, done, vars, inner);
    std::map<int, LocalP> locals;
    collect(index, locals, vars);
    collect(value, locals, vars);
    collect(dot, locals, vars);
    if (fs.chain)
      collect(fs.chain, locals, vars);
    define_locals(code, locals, guards ? inner : done);
    const char* op = s.accumulate ? "+=" : "=";
    std::string idx = subscript(index, k.shape_of(s.array));
    std::string dot_text = !is_zero(dot)                             ? print(dot)
                           : type_spelling(s.value->type) == "float" ? "0.0f"
                                                                     : "0.0";
    // (`+=` statements merged into one store: the element's new value as the
    // kernel adds them, (x + a) + b, not x + (a + b))
    const std::string primal = fs.chain && s.extremum == 0
                                   ? fmt::format("{}{} = {};", s.array, idx, print(fs.chain))
                                   : store_statement(s, s.array + idx, print(value));
    code.line("{}", primal);
    // (a min/max scan is a constant to derivatives: its tangent stays what its
    // first store set, 0)
    if (s.extremum == 0 && tangent)
      code.line("{}_dot{} {} {};", s.array, idx, op, dot_text);
    if (auto w = options.written.find(s.array); w != options.written.end())
      code.line("{}{} = 1; // (copied back to '{}')", w->second, idx,
                k.find_param(s.array)->twin_of);
    for (int g = 0; g < guards; ++g)
      code.close();
  }
}

// The interior of loop `l` (ForwardNest::interior): `in_lo`, `in_hi` within
// its bounds, empty where `edge` (an outer counter's test) holds.
void emit_interior_bounds(Code& code, const Loop& l, const Interval& iv, const std::string& in_lo,
                          const std::string& in_hi, const std::string& edge) {
  const std::string t = kCellType, lo = bound(l.lo), hi = bound(l.hi);
  std::string from = iv.lo.empty() ? lo
                                   : fmt::format("std::max<{}>({}, std::min<{}>({}, {}))", t, lo, t,
                                                 print_max(iv.lo, t), hi);
  if (!edge.empty())
    from = fmt::format("{} ? {} : {}", edge, hi, from);
  code.line("const {} {} = {};", t, in_lo, from);
  code.line("const {} {} = {};", t, in_hi,
            iv.hi.empty() ? fmt::format("std::max<{}>({}, {})", t, in_lo, hi)
                          : fmt::format("std::max<{}>({}, std::min<{}>({}, {}))", t, in_lo, t,
                                        print_min(iv.hi, t), hi));
}

// The innermost loop of a peeled nest: the iterations near its ends (all of
// them where `edge`, an outer counter's test, holds), then those inside (on
// every thread where `threads` is a condition), then the rest, in the loop's
// order.
void emit_peeled(Code& code, const Kernel& k, const ForwardNest& plan, bool tangent,
                 const ForwardOptions& options, const std::string& threads,
                 const std::string& edge_flag) {
  const Loop& l = plan.nest->loops.back();
  const std::string t = kCellType;
  const std::string edge = k.fresh("edge"), interior = k.fresh("interior");
  const std::string in_lo = k.fresh("in_lo_" + l.var), in_hi = k.fresh("in_hi_" + l.var);
  code.line("// iterations near the ends of the loops: as the kernel writes them");
  code.open(fmt::format("auto {} = [&](const {} {})", edge, t, l.var));
  emit_stores(code, k, plan.stores, tangent, options);
  code.close(";");
  code.line("// inside: the index conditions decided there folded (the same results)");
  code.open(fmt::format("auto {} = [&](const {} {})", interior, t, l.var));
  emit_stores(code, k, plan.interior_stores, tangent, options);
  code.close(";");
  emit_interior_bounds(code, l, plan.interior.back(), in_lo, in_hi, edge_flag);
  auto loop = [&](const std::string& from, const std::string& to) {
    return fmt::format("for ({} {} = {}; {} < {}; ++{})", t, l.var, from, l.var, to, l.var);
  };
  const std::string hi = bound(l.hi);
  code.line("{}", loop(bound(l.lo), in_lo));
  code.line("  {}({});", edge, l.var);
  if (!threads.empty()) {
    threaded_loop(code, threads, loop(in_lo, in_hi), fmt::format("{}({});", interior, l.var));
  } else {
    code.line("{}", loop(in_lo, in_hi));
    code.line("  {}({});", interior, l.var);
  }
  code.line("{}", loop(in_hi, hi));
  code.line("  {}({});", edge, l.var);
}

} // namespace

void emit_forward_nest(Code& code, const Kernel& k, const ForwardNest& plan, bool tangent,
                       const ForwardOptions& options) {
  const Nest& nest = *plan.nest;
  auto unplanned = [&](const std::vector<ForwardStore>& stores) {
    return tangent && std::any_of(stores.begin(), stores.end(),
                                  [](const ForwardStore& fs) { return !fs.dot; });
  };
  if (plan.stores.size() != nest.stores.size() || unplanned(plan.stores) ||
      unplanned(plan.interior_stores) ||
      (plan.peeled() && plan.interior.size() != nest.loops.size()))
    throw std::logic_error("internal error: emit: a forward nest's stores are not planned");
  code.open("");
  int opened = 1;
  const bool threaded = plan.parallel && options.threads && !nest.loops.empty();
  // Every element is written by one iteration (proved, or checked on entry),
  // so iterations are independent (and their order is free).
  std::string threads;
  if (threaded) {
    std::vector<std::string> extents;
    for (const auto& m : nest.loops)
      extents.push_back(fmt::format("({} - {})", bound(m.hi), bound(m.lo)));
    threads = fmt::format("{} >= {}", fmt::join(extents, " * "), kMinParallelIterations);
  }
  // The outermost loop on every thread: its body a lambda of its counter
  // (threaded_loop). A peeled nest's outer loops test their counters against
  // their interiors (edge_<v>); its innermost loop is printed by emit_peeled.
  const size_t opened_loops = plan.peeled() ? nest.loops.size() - 1 : nest.loops.size();
  std::string header, iteration, edge_flag;
  for (size_t d = 0; d < opened_loops; ++d) {
    const Loop& l = nest.loops[d];
    const bool narrows =
        plan.peeled() && (!plan.interior[d].lo.empty() || !plan.interior[d].hi.empty());
    const std::string in_lo = k.fresh("in_lo_" + l.var), in_hi = k.fresh("in_hi_" + l.var);
    if (narrows)
      emit_interior_bounds(code, l, plan.interior[d], in_lo, in_hi, "");
    const std::string for_line = fmt::format("for ({} {} = {}; {} < {}; ++{})", kCellType, l.var,
                                             bound(l.lo), l.var, bound(l.hi), l.var);
    if (d == 0 && threaded) {
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
    if (narrows) {
      const std::string flag = k.fresh("edge_" + l.var);
      code.line("const bool {} = {}{} < {} || {} >= {};", flag,
                edge_flag.empty() ? "" : edge_flag + " || ", l.var, in_lo, l.var, in_hi);
      edge_flag = flag;
    }
  }
  if (plan.peeled())
    emit_peeled(code, k, plan, tangent, options, opened_loops == 0 ? threads : std::string(),
                edge_flag);
  else
    emit_stores(code, k, plan.stores, tangent, options);
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
