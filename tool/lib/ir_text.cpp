// The IR's text form (ir_text.hpp).
#include "ir_text.hpp"

#include "ir_walk.hpp"
#include "ops.hpp"
#include "print.hpp"
#include "prove.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <set>

namespace dpgen {

namespace {

// The locals (not kernel-level) that `exprs` use, by id: the order of their
// definitions.
std::map<int, const LocalVar*> loop_locals(std::initializer_list<ExprP> exprs) {
  std::set<const LocalVar*> seen;
  std::map<int, const LocalVar*> locals;
  for (const ExprP& e : exprs)
    walk(
        e,
        [&](const ExprP& x) {
          if (x->op == Op::Local && !x->local->kernel_level)
            locals[x->local->id] = x->local.get();
          return true;
        },
        [](const ExprP&) { return true; }, seen);
  return locals;
}

const char* kind_text(ParamKind k) {
  switch (k) {
  case ParamKind::In:
    return "in";
  case ParamKind::Out:
    return "out";
  case ParamKind::ConstArray:
    return "const-array";
  case ParamKind::Scalar:
    return "scalar";
  }
  return "?";
}

std::string pos_text(const SourcePos& p) { return fmt::format("{}:{}", p.line, p.col); }

std::string polys(const std::vector<Poly>& ps, const char* fn) {
  std::vector<std::string> s;
  for (const auto& p : ps)
    s.push_back(p.code());
  if (s.empty())
    return "*";
  return s.size() == 1 ? s[0] : fmt::format("{}({})", fn, fmt::join(s, ", "));
}

std::string box_text(const Box& b) {
  std::vector<std::string> dims;
  for (const auto& [v, iv] : b.dims)
    dims.push_back(fmt::format("{}: [{}, {})", v, polys(iv.lo, "max"), polys(iv.hi, "min")));
  return "{" + fmt::format("{}", fmt::join(dims, "; ")) + "}";
}

std::string path_text(const std::vector<PathCond>& path) {
  std::vector<std::string> s;
  for (const auto& c : path)
    s.push_back((c.positive ? "" : "!") + std::string("(") + print(c.cond) + ")");
  return fmt::format("{}", fmt::join(s, " && "));
}

std::string bound_text(const CellBound& b, const char* outer, const char* inner) {
  std::vector<std::string> parts;
  for (const auto& p : b.parts)
    parts.push_back(polys(p, inner));
  if (parts.empty())
    return "*";
  return parts.size() == 1 ? parts[0] : fmt::format("{}({})", outer, fmt::join(parts, ", "));
}

// The locals an expression uses that derive or a pass made (not the kernel's
// own, which print_ir lists), with their definitions, in id order.
void made_locals(const ExprP& e, std::string& out, const std::string& indent) {
  std::set<const LocalVar*> seen;
  std::map<int, const LocalVar*> found;
  walk(
      e,
      [&](const ExprP& x) {
        if (x->op == Op::Local && x->local->id >= 1000000)
          found[x->local->id] = x->local.get();
        return true;
      },
      [](const ExprP&) { return true; }, seen);
  for (const auto& [id, l] : found)
    out += fmt::format("{}where {} = {}\n", indent, l->name, print(l->def));
}

} // namespace

const std::vector<std::string>& pass_names() {
  static const std::vector<std::string> names = {"lower", "derive", "schedule",
                                                 "plan",  "hoist",  "share"};
  return names;
}

std::string domain_text(const Domain& d) {
  if (d.empty())
    return "{}  (empty)";
  std::vector<std::string> boxes;
  for (const auto& b : d)
    boxes.push_back(box_text(b));
  return fmt::format("{}", fmt::join(boxes, " | "));
}

std::string print_ir(const Kernel& k) {
  std::string out = fmt::format("kernel {} at {}\n", k.name, pos_text(k.pos));
  for (const auto& p : k.params) {
    std::string flags;
    if (p.inout)
      flags += " inout";
    if (!p.twin_of.empty())
      flags += " twin-of=" + p.twin_of;
    if (p.synthetic)
      flags += " synthetic";
    if (pointer_levels(p))
      flags += fmt::format(" levels={}", pointer_levels(p));
    if (!p.rows.empty())
      flags += " rows=" + p.rows;
    out += fmt::format("  param {} {} : {}{}\n", kind_text(p.kind), p.name, p.elem_name, flags);
  }
  for (const auto& p : k.hidden)
    out += fmt::format("  hidden {} : {}\n", p.name, p.elem_name);
  for (const auto& l : k.kernel_locals)
    out += fmt::format("  local {} : {} = {}\n", l->name, l->type_name, print(l->def));
  if (!k.guards.empty())
    out += fmt::format("  guard {}\n", path_text(k.guards));
  for (size_t n = 0; n < k.nests.size(); ++n) {
    const Nest& nest = k.nests[n];
    out += fmt::format("  nest {} key [{}]\n", n, fmt::join(nest.key, ", "));
    std::string indent = "    ";
    for (const auto& l : nest.loops) {
      out += fmt::format("{}for {} : {} in [{}, {})\n", indent, l.var, l.type_name, print(l.lo),
                         print(l.hi));
      indent += "  ";
    }
    for (const auto& s : nest.stores) {
      out += fmt::format("{}store #{} {}[{}] {} {}", indent, s.seq, s.array, print(s.index),
                         store_operator(s), print(s.value));
      if (!s.path.empty())
        out += "  if " + path_text(s.path);
      out += fmt::format("  at {}\n", pos_text(s.pos));
      // The locals the store needs, defined inside the loops.
      for (const auto& [id, l] : loop_locals({s.index, s.value}))
        out += fmt::format("{}  where {} = {}\n", indent, l->name, print(l->def));
    }
  }
  for (const auto& c : k.size_checks)
    out += fmt::format("  size-check {}{}  ({})\n",
                       c.premises.empty() ? "" : join_code(c.premises, " && ") + " => ",
                       c.must_hold_code(), c.what);
  for (const auto& w : k.intermediates)
    out += fmt::format("  intermediate {}\n", w);
  for (const auto& [a, e] : k.extent)
    out += fmt::format("  extent {} = {}\n", a, e.code());
  return out;
}

std::string print_partials(const Kernel& k, Partials& partials) {
  std::string out = fmt::format("partials of {}\n", k.name);
  for (const auto& param : k.params) {
    if (param.kind != ParamKind::In)
      continue;
    for (size_t n = 0; n < k.nests.size(); ++n)
      for (const auto& store : k.nests[n].stores) {
        std::vector<PathCond> guards;
        if (store_domain(k.nests[n], store, guards).empty())
          continue;
        for (const auto& site : reads_in(store.value)) {
          if (site.read->name != param.name)
            continue;
          const ExprP& d = partials.of(store, {site.read});
          std::string read = site.read->name + subscript(site.read->ops[0], site.read->shape);
          out += fmt::format("  d {}[{}] / d {} = {}\n", store.array, print(store.index), read,
                             is_zero(d) ? "0 (exact)" : print(d));
          if (!site.conds.empty())
            out += "    when " + path_text(site.conds) + "\n";
          made_locals(d, out, "    ");
        }
      }
  }
  return out;
}

std::string print_schedule(const AdjointPlan& plan) {
  const Kernel& k = *plan.kernel;
  std::string out = fmt::format("schedule of {}\n", k.name);
  for (const auto& g : plan.gathers) {
    std::vector<std::string> layout;
    for (const auto& [v, c] : g.layout)
      layout.push_back(fmt::format("{}*{}", c.code(), v));
    out += fmt::format("  gather {} layout [{}] base {}", g.array, fmt::join(layout, ", "),
                       g.base.code());
    if (!g.reduced.empty())
      out += fmt::format(" reduced [{}]", fmt::join(g.reduced, ", "));
    out += "\n";
    for (const auto& b : g.blocks) {
      std::vector<std::string> shift;
      for (const auto& [v, p] : b.shift)
        shift.push_back(fmt::format("{} = {}", v, (Poly::symbol("c_" + v) - p).code()));
      out += fmt::format("    block{} iteration {}\n", b.bulk ? " bulk" : "",
                         shift.empty() ? "= cell" : fmt::format("[{}]", fmt::join(shift, ", ")));
      out += "      domain " + domain_text(b.domain) + "\n";
      if (!b.guards.empty())
        out += "      guard " + path_text(b.guards) + "\n";
      for (const auto& t : b.terms) {
        std::vector<std::string> reads;
        for (const Expr* r : t.reads)
          reads.push_back(r->source.empty() ? r->name : r->source);
        std::sort(reads.begin(), reads.end());
        out += fmt::format("      term store #{} reads {{{}}}: {}\n", t.store->seq,
                           fmt::join(reads, ", "), print(t.partial));
      }
    }
  }
  for (const auto& s : plan.scatters) {
    out += fmt::format("  scatter {} from store #{}\n", s.array, s.store->seq);
    for (const auto& r : s.reads)
      out += fmt::format("    {}[{}]: {}\n", r.read->name, print(r.read->ops[0]),
                         print(r.partial));
  }
  for (const auto& r : plan.remarks)
    out += fmt::format("  remark at {}: {}\n", pos_text(r.pos), r.text);
  for (size_t i = 0; i < plan.stages.size(); ++i) {
    out += fmt::format("  stage {}\n", i);
    std::string inner = print_schedule(*plan.stages[i].plan);
    for (size_t a = 0, b; a < inner.size(); a = b + 1) {
      b = inner.find('\n', a);
      out += "    " + inner.substr(a, b - a) + "\n";
    }
  }
  return out;
}

std::string print_plan(const LoopPlan& plan) {
  std::string out = fmt::format("plan of {}\n", plan.adjoint->kernel->name);
  for (const auto& in : plan.inputs) {
    out += fmt::format("  input {}\n", in.array);
    for (const auto& step : in.gathers) {
      out += fmt::format("    step{}\n", step.fused() ? " fused" : "");
      for (const auto& loop : step.loops) {
        std::vector<std::string> arrays;
        for (const auto* g : loop.groups)
          arrays.push_back(g->array);
        out += fmt::format("      cells of [{}]\n", fmt::join(arrays, ", "));
        for (const auto& [v, r] : loop.bounds)
          out += fmt::format("        {} in [{}, {})\n", v, bound_text(r.lo, "min", "max"),
                             bound_text(r.hi, "max", "min"));
        if (loop.any_bulk)
          out += "        interior " + box_text(loop.interior) + "\n";
        for (const auto& r : loop.reaches)
          out += "        edge may reach " + box_text(r.box) + "\n";
        if (loop.unit_1d)
          out += "        parallel: unit stride\n";
        for (const auto& s : loop.radix)
          out += fmt::format("        parallel: radix dim {} step {} reach {}\n", s.dim,
                             s.step.code(), s.reach.code());
        // The interior terms whose conditions the interior decides (folded).
        for (size_t gi = 0; gi < loop.interior_terms.size(); ++gi)
          for (size_t bi = 0; bi < loop.interior_terms[gi].size(); ++bi)
            for (const auto& t : loop.interior_terms[gi][bi])
              if (t.partial != loop.groups[gi]->blocks[bi].terms.front().partial) {
                out += fmt::format("        interior term of {}, block {}: {}\n",
                                   loop.groups[gi]->array, bi, print(t.partial));
                for (const auto& [id, l] : loop_locals({t.partial}))
                  out += fmt::format("          where {} = {}\n", l->name, print(l->def));
              }
        // The cells of an edge row in the interior's range of the innermost
        // counter: the terms and checks that range decides.
        if (!loop.row_terms.empty()) {
          const std::string& v = loop.groups.front()->layout.back().first;
          size_t n = 0, left_out = 0, unchecked = 0;
          for (size_t gi = 0; gi < loop.row_terms.size(); ++gi)
            for (size_t bi = 0; bi < loop.row_terms[gi].size(); ++bi) {
              const Block& b = loop.groups[gi]->blocks[bi];
              left_out += loop.edge_terms[gi][bi].size() - loop.row_terms[gi][bi].size();
              for (const auto& t : loop.row_terms[gi][bi]) {
                ++n;
                unchecked += t.box.dims.count(v) == 0 &&
                             std::any_of(b.domain.begin(), b.domain.end(),
                                         [&](const Box& d) { return d.dims.count(v) != 0; });
              }
            }
          out += fmt::format("        edge rows, {} in the interior's range: {} terms ({} left "
                             "out), {} without their check of {}\n",
                             v, n, left_out, unchecked, v);
          // (the partials the range changes: a row term's edge term has its box)
          for (size_t gi = 0; gi < loop.row_terms.size(); ++gi)
            for (size_t bi = 0; bi < loop.row_terms[gi].size(); ++bi)
              for (const auto& t : loop.row_terms[gi][bi]) {
                const auto& edges = loop.edge_terms[gi][bi];
                const bool changed = std::none_of(edges.begin(), edges.end(), [&](const auto& e) {
                  return print(e.partial) == print(t.partial);
                });
                if (changed)
                  out += fmt::format("        edge-row term of {}, block {}: {}\n",
                                     loop.groups[gi]->array, bi, print(t.partial));
              }
        }
      }
    }
    for (const auto& s : in.scatters)
      out += fmt::format("    scatter from store #{} (serial)\n", s.unit->store->seq);
  }
  for (size_t i = 0; i < plan.stages.size(); ++i) {
    std::string inner = print_plan(plan.stages[i]);
    out += fmt::format("  stage {}\n", i);
    for (size_t a = 0, b; a < inner.size(); a = b + 1) {
      b = inner.find('\n', a);
      out += "    " + inner.substr(a, b - a) + "\n";
    }
  }
  return out;
}

namespace {

void hoisted_text(std::string& out, const std::string& indent, const std::string& what,
                  const std::vector<LocalP>& hoisted) {
  if (hoisted.empty())
    return;
  out += fmt::format("{}{}:\n", indent, what);
  for (const auto& l : hoisted)
    out += fmt::format("{}  {} = {}\n", indent, l->name, print(l->def));
}

void hoisted_text(std::string& out, const std::string& indent, const LoopPlan& plan) {
  hoisted_text(out, indent, "adjoint", plan.hoisted);
  for (size_t i = 0; i < plan.stages.size(); ++i) {
    out += fmt::format("{}stage {}\n", indent, i);
    hoisted_text(out, indent + "  ", plan.stages[i]);
  }
}

} // namespace

std::string print_hoisted(const LoopPlan& plan) {
  std::string out = fmt::format("hoisted in {}\n", plan.adjoint->kernel->name);
  hoisted_text(out, "  ", plan);
  hoisted_text(out, "  ", "forward", plan.forward.hoisted);
  // What the loops print with them: the interior terms that use a hoisted local.
  auto uses_hoisted = [&](const std::string& text) {
    return std::any_of(plan.hoisted.begin(), plan.hoisted.end(),
                       [&](const LocalP& l) { return names_identifier(text, l->name); });
  };
  auto terms = [&](const CellLoop& loop, const char* label) {
    for (size_t gi = 0; gi < loop.interior_terms.size(); ++gi)
      for (size_t bi = 0; bi < loop.interior_terms[gi].size(); ++bi)
        for (const auto& t : loop.interior_terms[gi][bi]) {
          const std::string text = print(t.partial);
          if (uses_hoisted(text))
            out += fmt::format("  interior term of {}{}, block {}: {}\n", loop.groups[gi]->array,
                               label, bi, text);
        }
  };
  for (const auto& in : plan.inputs)
    for (const auto& step : in.gathers)
      for (const auto& loop : step.loops)
        terms(loop, step.fused() && &loop == &step.loops.front() ? " (fused)" : "");
  return out;
}

std::string print_shared(const LoopPlan& plan) {
  std::string out = fmt::format("shared in {}\n", plan.adjoint->kernel->name);
  auto loops = [&](const LoopPlan& p, const std::string& label, auto&& self) -> void {
    const Kernel& k = *p.adjoint->kernel;
    for (size_t s = 0; s < p.stages.size(); ++s)
      self(p.stages[s], fmt::format("stage {}: ", s + 1), self);
    for (const auto& in : p.inputs)
      for (const auto& step : in.gathers)
        for (const auto& loop : step.loops) {
          std::vector<std::string> arrays;
          for (const auto* g : loop.groups)
            arrays.push_back(g->array);
          const std::string& v = loop.groups.front()->layout.empty()
                                     ? std::string()
                                     : loop.groups.front()->layout.back().first;
          for (const auto& sv : loop.shared) {
            auto at = [&](const std::string& u, long long shift) { // (emit's cell counter)
              return (Poly::symbol(k.fresh("c_" + u)) + Poly::constant(shift)).code();
            };
            std::string outer;
            for (const auto& [u, shift] : sv.outer)
              outer += fmt::format(", {} = {}", u, at(u, shift));
            out += fmt::format("  {}cells of [{}]: {} = {} at {} = {} ..= {}{}\n", label,
                               fmt::join(arrays, ", "), sv.name, print(sv.value), v, at(v, sv.lo),
                               at(v, sv.hi), outer);
            for (const auto& [id, l] : loop_locals({sv.value}))
              out += fmt::format("    where {} = {}\n", l->name, print(l->def));
          }
        }
  };
  loops(plan, "", loops);
  return out;
}

std::string print_forward_plan(const ForwardPlan& plan) {
  std::string out = fmt::format("forward loops of {}\n", plan.kernel->name);
  for (size_t n = 0; n < plan.nests.size(); ++n) {
    const ForwardNest& f = plan.nests[n];
    std::vector<std::string> loops;
    for (const auto& l : f.nest->loops)
      loops.push_back(fmt::format("{} in [{}, {})", l.var, print(l.lo), print(l.hi)));
    out += fmt::format("  nest {}: {}{}\n", n + 1,
                       f.parallel              ? "parallel"
                       : f.nest->loops.empty() ? "serial (no loop)"
                                               : "serial (a store adds)",
                       loops.empty() ? "" : fmt::format(", {}", fmt::join(loops, ", ")));
    if (!f.peeled())
      continue;
    // (peel_forward: the interior's bounds beyond the loops' own, its stores)
    Box inside;
    for (size_t d = 0; d < f.interior.size(); ++d)
      if (!f.interior[d].lo.empty() || !f.interior[d].hi.empty())
        inside.dims[f.nest->loops[d].var] = f.interior[d];
    out += fmt::format("    split, interior {}\n", box_text(inside));
    for (const auto& st : f.interior_stores) {
      const std::string path = path_text(st.path);
      out += fmt::format("    interior: {}[{}] {} {}{}\n", st.store->array, print(st.index),
                         st.store->accumulate ? "+=" : "=", print(st.value),
                         path.empty() ? "" : " if " + path);
    }
  }
  return out;
}

} // namespace dpgen
