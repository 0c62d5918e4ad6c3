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

void emit_nest(Code& code, const Nest& nest, const Kernel& k, Hoister& hoist) {
  code.open("");
  int opened = 1;
  for (const auto& l : nest.loops) {
    code.open(fmt::format("for ({} {} = {}; {} < {}; ++{})", kCellType, l.var, bound(l.lo), l.var,
                          bound(l.hi), l.var));
    ++opened;
  }
  std::set<int> done;
  std::set<std::string> vars;
  for (const auto& s : nest.stores) {
    const ExprP index = hoist(s.index);
    // `+=`: summed (hoist.hpp)
    const ExprP value = hoist(s.value, s.accumulate && s.extremum == 0);
    bool guarded = open_guard(code, s.path, hoist, done, vars);
    std::map<int, LocalP> locals;
    collect(index, locals, vars);
    collect(value, locals, vars);
    std::set<int> inner = done;
    define_locals(code, locals, guarded ? inner : done);
    code.line("{}", store_statement(s, s.array + subscript(index, k.shape_of(s.array)),
                                    print(value)));
    if (guarded)
      code.close();
  }
  for (int i = 0; i < opened; ++i)
    code.close();
}

} // namespace

void emit_recompute(Code& code, const Kernel& k, const std::string& name) {
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
  Hoister hoist(k); // (the nests to a buffer: what they hoist comes first)
  Code nests(code.depth());
  for (const auto& n : k.nests)
    emit_nest(nests, n, k, hoist);
  hoist.emit(code);
  code.raw(nests.str());
  code.close();
}

} // namespace dpgen
