// Emit (phase 6): prints one kernel's adjoint from its loop plan: the gather
// loops (bounding box, branch-free interior, guarded edges), the scatter loops
// and the entry points around them. What the loops are is decided in
// loop_plan.cpp; the file around the kernels is emit_file.cpp.
#include "emit.hpp"

#include "emit_checked.hpp"
#include "emit_impl.hpp"
#include "emit_util.hpp"
#include "hoist.hpp"
#include "print.hpp"
#include "share.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <climits>
#include <functional>
#include <map>
#include <set>
#include <stdexcept>

namespace dpgen {

namespace {

// The counter of adjoint cells along loop counter `v` ("c_i").
std::string cell_counter(const Kernel& k, const std::string& v) { return k.fresh("c_" + v); }

std::string elem_of(const Kernel& k, const std::string& array) {
  const Param* p = k.find_param(array);
  return p ? p->elem_name : "double";
}

std::string loop_type(const Nest&, const std::string&) { return kCellType; }

// ---- one block: the terms of one (store, shift, piece) at one iteration -------

struct BlockContext {
  const Kernel& k;
  const GatherGroup& g;
  Code& code;
  std::string acc;
  std::string hit;    // flag set when a term applies (edge cells)
  bool edge;          // guarded: check that the iteration is in the domain
  const std::vector<BoxTerm>* terms; // the block's term in each box it prints (loop_plan)
};

// The sum of seeds that interior partial `n` of accumulator `acc` factors
// out (CellLoop::factored).
std::string factored_sum(const Kernel& k, const std::string& acc, int n) {
  return k.fresh(fmt::format("{}_s{}", acc, n));
}

// The term `t` in one box of its iterations, as planned (bt): the locals it
// needs, recomputed at its iteration, then `acc += partial * seed`.
void emit_terms(Code& code, const Kernel& k, const Term& t, const BoxTerm& bt,
                const std::string& acc, const std::string& set_hit) {
  const ExprP& partial = bt.partial;
  const ExprP& seed_index = bt.seed_index;
  const std::vector<ExprP>& gs = bt.guards;
  std::map<int, LocalP> locals;
  std::set<std::string> vars;
  collect(partial, locals, vars);
  collect(seed_index, locals, vars);
  for (const auto& g : gs)
    collect(g, locals, vars);
  std::set<int> done;
  if (!gs.empty()) {
    // The guards' own locals first: the source computed them before branching.
    std::map<int, LocalP> guard_locals;
    std::set<std::string> unused;
    for (const auto& g : gs)
      collect(g, guard_locals, unused);
    define_locals(code, guard_locals, done);
    std::vector<std::string> parts;
    for (const auto& g : gs)
      parts.push_back(gs.size() == 1 ? print(g) : print_conjunct(g));
    code.open(fmt::format("if ({})", fmt::join(parts, " && ")));
  }
  define_locals(code, locals, done);
  ExprP seed = read(t.store->array + "_adj", seed_index, t.store->value->type, {},
                    k.shape_of(t.store->array));
  if (bt.factor >= 0) {
    std::string sum = factored_sum(k, acc, bt.factor);
    if (bt.factor_negated) {
      code.line("// (the partial, negated, is the same in every iteration: acc += it · {} below)",
                sum);
      code.line("{} -= {};", sum, print(seed));
    } else {
      code.line("// (the partial is the same in every iteration: acc += it · {} below)", sum);
      code.line("{} += {};", sum, print(seed));
    }
  } else
    code.line("{} += {};", acc, print(binary(Op::Mul, partial, seed)));
  if (!set_hit.empty())
    code.line("{}", set_hit);
  if (!gs.empty())
    code.close();
}

// Emits one block inside a cell lambda.
void emit_block(const BlockContext& cx, const Block& b) {
  const Nest& nest = *cx.g.nest;
  std::map<std::string, Poly> back; // counter -> -shift, cell space -> iteration space
  for (const auto& [v, c] : cx.g.layout) {
    auto it = b.shift.find(v);
    back[v] = it == b.shift.end() ? Poly() : -it->second;
  }
  Code& code = cx.code;
  std::string iter_desc;
  for (const auto& [v, c] : cx.g.layout) {
    Poly it = Poly::symbol(cell_counter(cx.k, v)) + back[v];
    iter_desc += (iter_desc.empty() ? "" : ", ") + fmt::format("{} = {}", v, it.code());
  }
  const Store& s = *b.terms.front().store;
  std::string out_sub = subscript(s.index, cx.k.shape_of(s.array));
  std::string out_cell = s.array + out_sub;
  code.line("// {} reads {}{}: acc += ∂{}/∂{} · {}_adj{}", out_cell, b.comment,
            iter_desc.empty() ? "" : " at " + iter_desc, out_cell, b.comment, s.array, out_sub);

  for (const BoxTerm& bt : *cx.terms) {
    const Box& box = bt.box;
    code.open("");
    // Layout counters come from the cell.
    for (const auto& [v, c] : cx.g.layout) {
      Poly it = Poly::symbol(cell_counter(cx.k, v)) + back[v];
      code.line("const {} {} = {};", loop_type(nest, v), v, it.code());
    }
    int opened = 0;
    if (cx.edge) {
      std::vector<std::string> conds;
      for (const auto& [v, c] : cx.g.layout) {
        auto d = box.dims.find(v);
        if (d == box.dims.end())
          continue;
        for (const auto& lo : d->second.lo)
          conds.push_back(fmt::format("{} >= {}", v, lo.code()));
        for (const auto& hi : d->second.hi)
          conds.push_back(fmt::format("{} < {}", v, hi.code()));
      }
      if (!conds.empty()) {
        code.open(fmt::format("if ({})", fmt::join(conds, " && ")));
        ++opened;
      }
    }
    // Counters outside the layout are summed over inside the cell.
    for (const auto& r : cx.g.reduced) {
      auto d = box.dims.find(r);
      std::string t = loop_type(nest, r);
      code.open(fmt::format("for ({} {} = {}; {} < {}; ++{})", t, r,
                            print_max(d->second.lo, t), r, print_min(d->second.hi, t), r));
      ++opened;
    }
    emit_terms(code, cx.k, b.terms.front(), bt, cx.acc, cx.hit.empty() ? "" : cx.hit + " = true;");
    for (int i = 0; i < opened; ++i)
      code.close();
    code.close();
  }
}

// The value an accumulator starts from: -0.0, the identity of +, so a sum is
// its first term exactly and the compiler drops the addition (0.0 + x is not
// x for x = -0.0, so `acc = 0` cost an addition per accumulator and cell).
constexpr const char* kEmptySum = "-0.0";

// Fewer cells than this run serially: a parallel region costs microseconds.
constexpr int kMinParallelCells = 8192;

// ---- a gather group ------------------------------------------------------------

// A cell bound as C++: the minimum over its parts of the maximum of each
// (`lower`; else the maximum of minima).
std::string print_bound(const CellBound& b, const std::string& t, bool lower) {
  std::vector<std::string> parts;
  for (const auto& part : b.parts) {
    if (part.size() == 1)
      parts.push_back(part.front().code());
    else
      parts.push_back(lower ? print_max(part, t) : print_min(part, t));
  }
  if (parts.size() == 1)
    return parts[0];
  std::string fn = lower ? "min" : "max";
  if (parts.size() == 2)
    return fmt::format("std::{}<{}>({}, {})", fn, t, parts[0], parts[1]);
  return fmt::format("std::{}<{}>({{{}}})", fn, t, fmt::join(parts, ", "));
}

// The conditions under which a sum of an interior term over counters outside
// the layout (a read of `a[j * nx]` in a loop over i) runs over no iteration;
// an interior cell stores its sum unconditionally, so the interior must then
// be empty. (Ranges empty or not whatever the sizes are left out.)
std::vector<std::string> empty_sums(const CellLoop& plan) {
  std::vector<std::string> out;
  for (size_t gi = 0; gi < plan.groups.size(); ++gi)
    for (const auto& terms : plan.interior_terms[gi])
      for (const BoxTerm& bt : terms)
        for (const std::string& r : plan.groups[gi]->reduced) {
          auto d = bt.box.dims.find(r);
          if (d == bt.box.dims.end() || d->second.lo.empty() || d->second.hi.empty())
            continue;
          bool constant = true;
          long long lo = LLONG_MIN, hi = LLONG_MAX;
          for (const Poly& p : d->second.lo)
            constant = constant && p.is_constant(), lo = std::max(lo, p.constant_term());
          for (const Poly& p : d->second.hi)
            constant = constant && p.is_constant(), hi = std::min(hi, p.constant_term());
          if (constant && lo < hi)
            continue;
          std::string c = fmt::format("{} >= {}", print_max(d->second.lo, kCellType),
                                      print_min(d->second.hi, kCellType));
          if (std::find(out.begin(), out.end(), c) == out.end())
            out.push_back(c);
        }
  return out;
}

std::string adj_cell(const Kernel& k, const GatherGroup& g) {
  Poly index = g.base;
  for (const auto& [v, c] : g.layout)
    index = index + c * Poly::symbol(cell_counter(k, v));
  return g.array + "_adj" + subscript(index, k.shape_of(g.array));
}

// The values an interior strip shares between its cells (CellLoop::shared),
// each computed once per iteration of the strip into its buffer.
void emit_shared(Code& code, const Kernel& k, const CellLoop& plan, const std::string& strip_lo,
                 const std::string& strip_hi) {
  const auto& layout = plan.groups.front()->layout;
  const std::string& v = layout.back().first;
  for (const auto& sv : plan.shared) {
    const Poly at = Poly::symbol(cell_counter(k, v));
    code.line("// {} at {} = {} ..= {}, which the cells' terms read: once per iteration of the "
              "strip",
              print(sv.value), v, (at + Poly::constant(sv.lo)).code(),
              (at + Poly::constant(sv.hi)).code());
    code.line("{} {}[{}];", type_spelling(sv.value->type), sv.name,
              kShareStripCells + sv.hi - sv.lo);
    code.line("const {} {} = {};", kCellType, sv.lo_name,
              (Poly::symbol(strip_lo) + Poly::constant(sv.lo)).code());
    code.open(fmt::format("for ({} {} = {}; {} < {}; ++{})", kCellType, v, sv.lo_name, v,
                          (Poly::symbol(strip_hi) + Poly::constant(sv.hi)).code(), v));
    for (const auto& [u, shift] : sv.outer)
      code.line("const {} {} = {};", kCellType, u,
                (Poly::symbol(cell_counter(k, u)) + Poly::constant(shift)).code());
    std::map<int, LocalP> locals;
    std::set<std::string> vars;
    collect(sv.value, locals, vars);
    std::set<int> done;
    define_locals(code, locals, done);
    code.line("{}[{} - {}] = {};", sv.name, v, sv.lo_name, print(sv.value));
    code.close();
  }
}

// One cell loop for one or more gather groups that share a layout (several
// inputs of one kernel, fused so the loop reads shared data once), over the
// box around their cell boxes.
void emit_gather(Code& code, const Kernel& k, const CellLoop& plan) {
  const std::vector<const GatherGroup*>& gs = plan.groups;
  const GatherGroup& g0 = *gs.front();
  const bool fused = gs.size() > 1;
  // Generated names (Kernel::fresh: none is one of the kernel's own).
  auto acc_name = [&](const GatherGroup& g) { return k.fresh(fused ? "acc_" + g.array : "acc"); };
  auto hit_name = [&](const GatherGroup& g) { return k.fresh(fused ? "hit_" + g.array : "hit"); };
  auto cell = [&](const std::string& v) { return cell_counter(k, v); };
  auto lo_of = [&](const std::string& v) { return k.fresh("lo_" + v); };
  auto hi_of = [&](const std::string& v) { return k.fresh("hi_" + v); };
  auto in_lo = [&](const std::string& v) { return k.fresh("in_lo_" + v); };
  auto in_hi = [&](const std::string& v) { return k.fresh("in_hi_" + v); };
  const std::string edge_fn = k.fresh("edge"), interior_fn = k.fresh("interior");
  // (not `edge_row`: that is the edge flag of a counter named `row`)
  const std::string row_fn = k.fresh("interior_row");
  const std::string parallel_ok = k.fresh("parallel_ok");

  std::string layout_desc;
  for (const auto& [v, c] : g0.layout)
    layout_desc += (layout_desc.empty() ? "" : ", ") + v;
  std::vector<std::string> cells;
  for (const auto* g : gs)
    cells.push_back(adj_cell(k, *g));
  std::vector<std::string> arrays;
  for (const auto* g : gs)
    arrays.push_back(g->array);
  if (g0.layout.empty())
    code.line("// {}: one cell, summed over the iterations ({}) that read it",
              fmt::join(cells, ", "), fmt::join(g0.reduced, ", "));
  else
    code.line("// {}: each cell gathers the reads of {} made by the iterations ({}){}",
              fmt::join(cells, ", "), fmt::join(arrays, ", "), layout_desc,
              g0.reduced.empty() ? ""
                                 : fmt::format(", summed over {}", fmt::join(g0.reduced, ", ")));
  // A null adjoint marks an inactive input: its loop is skipped (a fused
  // loop runs only when all its inputs are active; see emit_body).
  if (fused || k.find_param(g0.array)->view) // (a view has no null: always active)
    code.open("");
  else
    code.open(fmt::format("if ({}_adj != nullptr)", g0.array));
  auto store_if = [&](const GatherGroup&, const std::string& cond) {
    return cond.empty() ? std::string() : fmt::format("if ({})", cond);
  };

  // An edge cell's body: every block, each term checked against its box
  // (`terms`: the edge terms, or those of an edge row's cells in the
  // innermost interior range).
  auto edge_body = [&](const std::vector<std::vector<std::vector<BoxTerm>>>& terms) {
    for (size_t gi = 0; gi < gs.size(); ++gi) {
      const GatherGroup* g = gs[gi];
      code.line("{} {} = {};", elem_of(k, g->array), acc_name(*g), kEmptySum);
      code.line("bool {} = false;", hit_name(*g));
      for (size_t bi = 0; bi < g->blocks.size(); ++bi)
        emit_block({k, *g, code, acc_name(*g), hit_name(*g), true, &terms[gi][bi]}, g->blocks[bi]);
      code.line("{}", store_if(*g, hit_name(*g)));
      code.line("  {} += {};", adj_cell(k, *g), acc_name(*g));
    }
  };
  if (g0.layout.empty()) {
    // A single cell (a constant index, e.g. the periodic wrap d[0]): sum the
    // iterations that read it.
    edge_body(plan.edge_terms);
    code.close();
    return;
  }

  std::vector<std::string> cell_params;
  for (const auto& [v, c] : g0.layout)
    cell_params.push_back(fmt::format("const {} {}", kCellType, cell(v)));
  std::string params = fmt::format("{}", fmt::join(cell_params, ", "));

  const bool any_bulk = plan.any_bulk;
  const Box& interior = plan.interior;

  // The cell functions capture by copy (scalars, pointers, shallow views);
  // by reference where the kernel takes a view by reference, whose copy may
  // be deep or read-only (an AthenaArray-like class).
  const bool by_ref = std::any_of(k.params.begin(), k.params.end(),
                                  [](const Param& p) { return p.view && view_by_reference(p); });
  const std::string capture = by_ref ? "[&]" : "[=]";
  // Edge cell: every block, each checked against its iteration domain.
  code.open(fmt::format("auto {} = {}({})", edge_fn, capture, params));
  edge_body(plan.edge_terms);
  code.close(";");
  const bool rows = !plan.row_terms.empty();
  if (rows) {
    code.line("// a cell of an edge row with {} in the interior's range: as at an edge, less "
              "the checks that range decides",
              cell(g0.layout.back().first));
    code.open(fmt::format("auto {} = {}({})", row_fn, capture, params));
    edge_body(plan.row_terms);
    code.close(";");
  }
  // Values shared between the cells of a strip (the pass `share`): the
  // interior function runs a strip of the innermost counter's cells.
  const bool strips = !plan.shared.empty();
  const std::string strip_lo = k.fresh("strip_lo"), strip_hi = k.fresh("strip_hi");
  if (any_bulk) {
    std::string interior_params = params;
    if (strips) {
      std::vector<std::string> p(cell_params.begin(), cell_params.end() - 1);
      p.push_back(fmt::format("const {} {}", kCellType, strip_lo));
      p.push_back(fmt::format("const {} {}", kCellType, strip_hi));
      interior_params = fmt::format("{}", fmt::join(p, ", "));
    }
    code.open(fmt::format("auto {} = {}({})", interior_fn, capture, interior_params));
    if (strips) {
      emit_shared(code, k, plan, strip_lo, strip_hi);
      const std::string c = cell(g0.layout.back().first);
      code.open(
          fmt::format("for ({} {} = {}; {} < {}; ++{})", kCellType, c, strip_lo, c, strip_hi, c));
    }
    // Every accumulator before any store: to the compiler a store to one
    // input's adjoint may alias what the next input's terms read, which it
    // would then load and compute again (`u[i] / dx` after `d_adj[c_i] +=`).
    std::vector<std::string> stores;
    int stored = 0; // accumulators
    for (size_t gi = 0; gi < gs.size(); ++gi) {
      const GatherGroup* g = gs[gi];
      bool has_bulk = false;
      for (const auto& b : g->blocks)
        has_bulk = has_bulk || b.bulk;
      if (!has_bulk)
        continue; // no term of this input reaches the interior
      std::string elem = elem_of(k, g->array);
      code.line("{} {} = {};", elem, acc_name(*g), kEmptySum);
      // A term under a run-time guard (a condition that is not a box of
      // counters) may apply to no iteration of an interior cell, which the
      // source then never read: such a cell is not written, as at an edge.
      bool guarded = false;
      for (const auto& b : g->blocks)
        guarded = guarded || (b.bulk && !b.guards.empty());
      if (guarded)
        code.line("bool {} = false;", hit_name(*g));
      const std::vector<ExprP>& factored = plan.factored.at(gi);
      if (!factored.empty())
        code.line("// partials the same in every iteration, factored out: sums of seeds");
      for (size_t n = 0; n < factored.size(); ++n)
        code.line("{} {} = {};", elem, factored_sum(k, acc_name(*g), int(n)), kEmptySum);
      for (size_t bi = 0; bi < g->blocks.size(); ++bi)
        if (g->blocks[bi].bulk)
          emit_block({k, *g, code, acc_name(*g), guarded ? hit_name(*g) : "", false,
                      &plan.interior_terms[gi][bi]},
                     g->blocks[bi]);
      for (size_t n = 0; n < factored.size(); ++n)
        code.line("{} += {};", acc_name(*g),
                  print(binary(Op::Mul, factored[n],
                               param(factored_sum(k, acc_name(*g), int(n)), factored[n]->type))));
      std::string cond = store_if(*g, guarded ? hit_name(*g) : "");
      if (!cond.empty())
        stores.push_back(cond);
      stores.push_back(
          fmt::format("{}{} += {};", cond.empty() ? "" : "  ", adj_cell(k, *g), acc_name(*g)));
      ++stored;
    }
    if (stored > 1)
      code.line("// the cell's adjoints, once every accumulator is computed");
    for (const auto& l : stores)
      code.line("{}", l);
    if (strips)
      code.close();
    code.close(";");
  }

  // Ranges.
  for (const auto& [v, c] : g0.layout)
    code.line("const {} {} = {}, {} = {};", kCellType, lo_of(v),
              print_bound(plan.bounds.at(v).lo, kCellType, true), hi_of(v),
              print_bound(plan.bounds.at(v).hi, kCellType, false));
  // The interior holds only if no narrow (edge) block reaches into it.
  if (any_bulk) {
    std::vector<std::string> apart;
    for (const auto& reach : plan.reaches) {
      std::vector<std::string> ors;
      for (const auto& [v, iv] : reach.box.dims) {
        std::string t = kCellType;
        std::string lo = print_max(iv.lo, t), hi = print_min(iv.hi, t);
        ors.push_back(fmt::format("{} >= {}", lo, hi)); // empty
        if (reach.cell_dims.count(v)) {
          ors.push_back(fmt::format("{} <= {}", hi, in_lo(v)));
          ors.push_back(fmt::format("{} >= {}", lo, in_hi(v)));
        }
      }
      apart.push_back("(" + fmt::format("{}", fmt::join(ors, " || ")) + ")");
    }
    for (const auto& [v, c] : g0.layout) {
      std::string t = kCellType;
      const Interval& iv = interior.dims.at(v);
      code.line("{} {} = std::max<{}>({}, std::min<{}>({}, {}));", t, in_lo(v), t, lo_of(v), t,
                print_max(iv.lo, t), hi_of(v));
      code.line("{} {} = std::max<{}>({}, std::min<{}>({}, {}));", t, in_hi(v), t, in_lo(v), t,
                print_min(iv.hi, t), hi_of(v));
    }
    if (!apart.empty()) {
      code.open(fmt::format("if (!({}))", fmt::join(apart, " && ")));
      code.line("// an edge term reaches into the interior: treat every cell as an edge");
      for (const auto& [v, c] : g0.layout)
        code.line("{} = {} = {};", in_lo(v), in_hi(v), hi_of(v));
      code.close();
    }
    const std::vector<std::string> empty = empty_sums(plan);
    if (!empty.empty()) {
      code.open(fmt::format("if ({})", fmt::join(empty, " || ")));
      code.line("// an interior sum over {} runs over no iteration, so the source reads no "
                "cell: treat every cell as an edge (written only where read)",
                fmt::join(g0.reduced, ", "));
      for (const auto& [v, c] : g0.layout)
        code.line("{} = {} = {};", in_lo(v), in_hi(v), hi_of(v));
      code.close();
    }
  }

  // Threads only for enough cells to pay for a parallel region, and only if
  // the layout is one-to-one over the cell box (mixed radix): else serial.
  std::vector<std::string> extents, conds;
  for (const auto& [v, c] : g0.layout)
    extents.push_back(fmt::format("({} - {})", hi_of(v), lo_of(v)));
  conds.push_back(fmt::format("{} >= {}", fmt::join(extents, " * "), kMinParallelCells));
  if (!plan.unit_1d) {
    // A symbolic coefficient is printed as it is: a negative one (a mirrored
    // layout) fails the test, and its loop runs serially.
    std::vector<std::string> reach;
    for (size_t i = 0; i < plan.radix.size(); ++i) {
      const RadixStep& st = plan.radix[i];
      const std::string& v = g0.layout[st.dim].first;
      const Poly& c = st.coefficient;
      std::string coef = c.is_constant() ? st.step.code() : c.code();
      if (i > 0)
        conds.push_back(fmt::format("{} < {}", fmt::join(reach, " + "), coef));
      else if (!c.is_constant())
        conds.push_back(fmt::format("{} != 0", coef));
      reach.push_back(fmt::format("({} - 1) * {}", fmt::format("({} - {})", hi_of(v), lo_of(v)),
                                  c.is_constant() ? coef : "(" + coef + ")"));
    }
    code.line("// threads if the cells are many and distinct memory (mixed-radix test)");
  } else {
    code.line("// threads if the cells are many");
  }
  code.line("const bool {} = {};", parallel_ok, fmt::join(conds, " && "));

  // Loops: outer counters with a per-row interior test, the innermost split
  // into edge / interior / edge. The outermost loop runs on every thread where
  // parallel_ok (threaded_loop); with more than one counter its body is a
  // lambda of the outermost cell counter.
  size_t d = g0.layout.size();
  std::vector<std::string> all_cells;
  for (const auto& [u, c] : g0.layout)
    all_cells.push_back(cell(u));
  std::string args = fmt::format("{}", fmt::join(all_cells, ", "));
  std::function<void(size_t, std::string)> loops = [&](size_t level, std::string outer_edge) {
    const std::string& v = g0.layout[level].first;
    std::string t = kCellType;
    const std::string header = fmt::format("for ({} {} = {}; {} < {}; ++{})", t, cell(v), lo_of(v),
                                           cell(v), hi_of(v), cell(v));
    if (level + 1 < d) {
      const std::string row = k.fresh("row_" + v);
      if (level == 0)
        code.open(fmt::format("auto {} = [&](const {} {})", row, t, cell(v)));
      else
        code.open(header);
      std::string e =
          fmt::format("{} < {} || {} >= {}", cell(v), in_lo(v), cell(v), in_hi(v));
      if (!any_bulk)
        e = "true";
      const std::string edge_v = k.fresh("edge_" + v);
      code.line("const bool {} = {}{};", edge_v, outer_edge.empty() ? "" : outer_edge + " || ", e);
      loops(level + 1, edge_v);
      if (level == 0) {
        code.close(";");
        threaded_loop(code, parallel_ok, header, fmt::format("{}({});", row, cell(v)));
      } else {
        code.close();
      }
      return;
    }
    // (`step` cells at a time, `fn` called with `call_args`: a strip; else cell by cell)
    auto loop = [&](const std::string& from, const std::string& to, const std::string& fn,
                    bool threads, int step = 1, const std::string& call_args = "") {
      const std::string next = step == 1 ? "++" + cell(v) : fmt::format("{} += {}", cell(v), step);
      const std::string for_line =
          fmt::format("for ({} {} = {}; {} < {}; {})", t, cell(v), from, cell(v), to, next);
      const std::string call = fmt::format("{}({});", fn, call_args.empty() ? args : call_args);
      if (threads) {
        threaded_loop(code, parallel_ok, for_line, call);
        return;
      }
      code.line("{}", for_line);
      code.line("  {}", call);
    };
    bool top = level == 0;
    if (!any_bulk) {
      loop(lo_of(v), hi_of(v), edge_fn, top);
      return;
    }
    if (!outer_edge.empty()) {
      code.open(fmt::format("if ({})", outer_edge));
      if (rows) {
        loop(lo_of(v), in_lo(v), edge_fn, false);
        loop(in_lo(v), in_hi(v), row_fn, false);
        loop(in_hi(v), hi_of(v), edge_fn, false);
      } else {
        loop(lo_of(v), hi_of(v), edge_fn, false);
      }
      // (the row of the outermost counter is a lambda: its loop goes on with `return`)
      code.line(level == 1 ? "return;" : "continue;");
      code.close();
    }
    loop(lo_of(v), in_lo(v), edge_fn, false);
    if (strips) {
      std::vector<std::string> strip_args(all_cells.begin(), all_cells.end() - 1);
      strip_args.push_back(cell(v));
      strip_args.push_back(
          fmt::format("std::min<{}>({} + {}, {})", t, cell(v), kShareStripCells, in_hi(v)));
      code.line("// the interior in strips of {} cells, which share values (above)",
                kShareStripCells);
      loop(in_lo(v), in_hi(v), interior_fn, top, kShareStripCells,
           fmt::format("{}", fmt::join(strip_args, ", ")));
    } else {
      loop(in_lo(v), in_hi(v), interior_fn, top);
    }
    loop(in_hi(v), hi_of(v), edge_fn, false);
  };
  loops(0, "");
  code.close();
}

// ---- scatter units ---------------------------------------------------------------

void emit_scatter(Code& code, const Kernel& k, const ScatterLoop& plan) {
  const ScatterUnit& u = *plan.unit;
  const Nest& nest = *u.nest;
  const Store& s = *u.store;
  const ExprP& out_index = plan.seed_index;
  const std::string out_sub = subscript(out_index, k.shape_of(s.array));
  code.line("// {}_adj: reads of {} in {}{} at indices that cannot be inverted; scatter form, "
            "serial",
            u.array, u.array, s.array, out_sub);
  if (k.find_param(u.array)->view) // (a view has no null: always active)
    code.open("");
  else
    code.open(fmt::format("if ({}_adj != nullptr)", u.array)); // null: an inactive input
  int opened = 1;
  for (const auto& l : nest.loops) {
    code.open(fmt::format("for ({} {} = {}; {} < {}; ++{})", l.type_name, l.var, print(l.lo),
                          l.var, print(l.hi), l.var));
    ++opened;
  }
  // The store's path first (its locals are what the source computed before
  // the branch), then the locals of the seed and of each read's partial, each
  // read guarded by the arms it sits in.
  std::set<int> done;
  std::set<std::string> vars;
  {
    std::set<int> inside; // (what follows is inside those blocks)
    opened += open_guard(code, plan.path, done, vars, inside);
    done = inside;
  }
  std::map<int, LocalP> seed_locals;
  collect(out_index, seed_locals, vars);
  define_locals(code, seed_locals, done);
  const std::string seed = k.fresh("seed");
  code.line("const {} {} = {}_adj{};", type_spelling(s.value->type), seed, s.array, out_sub);
  for (const auto& r : plan.reads) {
    code.line("// {}{} = f(..., {}, ...): {}_adj{} += ∂f/∂{} · seed", s.array, out_sub,
              r.read->read->source, r.read->read->name,
              subscript(r.read->read->ops[0], r.read->read->shape), r.read->read->source);
    std::set<int> inner;
    const int guards = open_guard(code, r.conds, done, vars, inner);
    const ExprP& partial = r.partial;
    const ExprP& index = r.index;
    std::map<int, LocalP> locals;
    collect(partial, locals, vars);
    collect(index, locals, vars);
    define_locals(code, locals, guards ? inner : done);
    code.line("{}_adj{} += {};", r.read->read->name, subscript(index, r.read->read->shape),
              print(binary(Op::Mul, partial, param(seed, s.value->type))));
    for (int g = 0; g < guards; ++g)
      code.close();
  }
  for (int i = 0; i < opened; ++i)
    code.close();
}

} // namespace

// The parts emit_staged.cpp shares (emit_impl.hpp).
namespace adjoint {

// The adjoint's parameters. `shaped`: arrays of rows as the kernel declares
// them (`const double (*a)[64]`); otherwise every array is a flat pointer.
std::string param_list(const Kernel& k, bool shaped) {
  std::vector<std::string> ps;
  auto array = [&](const Param& p, bool is_const, const std::string& name) {
    return array_declaration(p, is_const, name, shaped, k.c_linkage);
  };
  for (const auto& p : k.params) {
    if ((shaped && (p.synthetic || !p.twin_of.empty())) || p.global)
      continue;
    switch (p.kind) {
    case ParamKind::In:
      ps.push_back(array(p, true, p.name));
      ps.push_back(array(p, false, p.name + "_adj"));
      break;
    case ParamKind::Out:
      ps.push_back(array(p, true, p.name + "_adj"));
      break;
    case ParamKind::ConstArray:
      ps.push_back(array(p, true, p.name));
      break;
    case ParamKind::Scalar:
      ps.push_back(fmt::format("{} {}", p.spelling, p.name));
      break;
    }
  }
  return fmt::format("{}", fmt::join(ps, ", "));
}

// The vector adjoint of an input has its input's size (it is accumulated
// element by element).
void emit_vector_checks(Code& code, const Kernel& k) {
  emit_vector_size_checks(code, k, k.name + "_adjoint", "_adj",
                          [](const Param& p) { return p.kind == ParamKind::In; });
}

// The copy of an in-place array's seed (emit_inout_prologue).
std::string seed_buffer(const Kernel& k, const std::string& array) {
  return k.fresh(array + "_seed");
}

// The call from the shaped entry point to the flat one: rows of a
// multi-dimensional array are contiguous, so its first element's address is
// the flat array.
std::string flat_arguments(const Kernel& k) {
  std::vector<std::string> as;
  auto array = flat_argument;
  for (const auto& p : k.params) {
    if (p.global) // (read by name: in no signature)
      continue;
    switch (p.kind) {
    case ParamKind::In:
      as.push_back(array(p, true, p.name));
      as.push_back(array(p, false, p.name + "_adj"));
      break;
    case ParamKind::Out:
      as.push_back(p.twin_of.empty() ? array(p, true, p.name + "_adj")
                                     : seed_buffer(k, p.twin_of) + ".data()");
      break;
    case ParamKind::ConstArray:
      as.push_back(array(p, true, p.name));
      break;
    case ParamKind::Scalar:
      // a vector's size: the size() of the vector it follows
      if (p.synthetic) {
        std::string vec = p.name.substr(0, p.name.size() - 5); // "<vec>_size"
        const Param* v = k.find_param(vec);
        as.push_back((v && v->kind == ParamKind::Out ? vec + "_adj" : vec) + ".size()");
      } else {
        as.push_back(p.name);
      }
      break;
    }
  }
  return fmt::format("{}", fmt::join(as, ", "));
}

// The statements of an adjoint function: kernel-level locals, size checks,
// the gather loops (fused where they share a nest and layout, with near cell
// boxes) and
// the scatter loops.
void emit_body(Code& out, const LoopPlan& plan) {
  const Kernel& k = *plan.adjoint->kernel;
  define_kernel_locals(out, k);
  emit_size_checks(out, k, k.name + "_adjoint");
  emit_container_reach_checks(out, k, k.name + "_adjoint");
  emit_hoisted(out, plan.hoisted);
  for (const auto& in : plan.inputs) {
    for (const auto& step : in.gathers) {
      if (step.loops.size() == 1) {
        emit_gather(out, k, step.loops.front());
        continue;
      }
      // Fused when every input is active; one loop each when some adjoint
      // is null (an inactive input).
      std::vector<std::string> all;
      for (const auto* f : step.loops.front().groups)
        if (!k.find_param(f->array)->view) // (a view has no null: always active)
          all.push_back(f->array + "_adj != nullptr");
      out.open(fmt::format("if ({})", fmt::join(all, " && ")));
      emit_gather(out, k, step.loops.front());
      out.close();
      out.open("else");
      for (size_t i = 1; i < step.loops.size(); ++i)
        emit_gather(out, k, step.loops[i]);
      out.close();
    }
    for (const auto& u : in.scatters)
      emit_scatter(out, k, u);
  }
}

} // namespace adjoint

using namespace adjoint;

void emit_kernel(Code& code, const LoopPlan& plan) {
  const Kernel& k = *plan.adjoint->kernel;
  RenameScope seeds(seed_names(k, false));
  open_namespaces(code, k);
  bool rows = has_rows(k) || has_inout(k);
  std::string name = k.name + (rows ? "_adjoint_flat" : "_adjoint");
  if (rows)
    code.raw("namespace {\n");
  if (!k.intermediates.empty()) {
    emit_staged(code, plan, name);
  } else {
    if (rows)
      code.line("// Adjoint of {} ({}:{}) on flat arrays; {}_adjoint below takes the arrays "
                "of rows.",
                k.name, base_name(k.file), k.pos.line, k.name);
    else
      code.line("// Adjoint of {} ({}:{}).", k.name, base_name(k.file), k.pos.line);
    code.open(fmt::format("void {}({})", name, param_list(k, !rows)));
    emit_body(code, plan);
    code.close();
  }
  if (rows) {
    code.raw("} // namespace\n\n");
    code.line("// Adjoint of {} ({}:{}).", k.name, base_name(k.file), k.pos.line);
    code.open(fmt::format("void {}_adjoint({})", k.name, param_list(k)));
    emit_vector_checks(code, k);
    emit_inout_prologue(code, k);
    code.line("{}_adjoint_flat({});", k.name, flat_arguments(k));
    code.close();
  }
  close_namespaces(code, k);
}

std::string adjoint_signature(const Kernel& k) {
  return fmt::format("void {}_adjoint({})", k.name, param_list(k));
}

} // namespace dpgen
