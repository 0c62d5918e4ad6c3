// Emit: gather loops (bounding box, branch-free interior, guarded edges),
// scatter loops, and the file around them.
#include "emit.hpp"

#include "emit_checked.hpp"
#include "emit_util.hpp"
#include "print.hpp"

#include <clang/Format/Format.h>
#include <clang/Tooling/Core/Replacement.h>

#include <algorithm>
#include <deque>
#include <fmt/format.h>
#include <functional>
#include <set>

namespace dpgen {

namespace {

// ---- expression rewriting under a known box --------------------------------

// Replaces conditional expressions whose index condition is decided inside
// `box` (only comparisons differing by a constant are decided), so an
// interior loop reads a[i + 1] instead of a[(i == n - 1) ? 0 : i + 1].
class Specializer {
public:
  explicit Specializer(const Box& box) : box_(box) {}

  ExprP operator()(const ExprP& e) {
    if (!e)
      return e;
    if (e->op == Op::Local) {
      if (e->local->kernel_level)
        return e;
      auto it = memo_.find(e->local.get());
      if (it != memo_.end())
        return it->second;
      ExprP def = (*this)(e->local->def);
      ExprP out = e;
      if (def != e->local->def) {
        auto l = std::make_shared<LocalVar>(*e->local);
        l->def = def;
        out = local_ref(l);
      }
      memo_[e->local.get()] = out;
      return out;
    }
    if (e->op == Op::Select) {
      if (auto cd = condition_domain(e->ops[0])) {
        if (box_inside(box_, *cd))
          return (*this)(e->ops[1]);
        if (box_disjoint(box_, *cd))
          return (*this)(e->ops[2]);
      }
    }
    return map_operands(e, [&](const ExprP& o) { return (*this)(o); });
  }

private:
  const Box& box_;
  std::map<const LocalVar*, ExprP> memo_;
};

std::string elem_of(const Kernel& k, const std::string& array) {
  const Param* p = k.find_param(array);
  return p ? p->elem_name : "double";
}

std::string loop_type(const Nest&, const std::string&) { return kCellType; }

// ---- one block: the terms of one (store, shift, piece) at one iteration -------

struct Factored;

struct BlockContext {
  const Kernel& k;
  const GatherGroup& g;
  Code& code;
  std::string acc;
  std::string hit;    // flag set when a term applies (edge cells)
  bool edge;          // guarded: check that the iteration is in the domain
  const Box* interior; // cell-space interior box (interior mode)
  Factored* factored = nullptr; // interior: shared invariant partials
};

// The locals a term needs, recomputed at its iteration, then `acc += partial
// * seed`, all specialized to the box the iteration is known to lie in.
// True when `e` is the same in every iteration (parameters and kernel-level
// locals only): a partial that can be factored out of the cell's sum.
bool invariant(const ExprP& e) {
  if (e->op == Op::LoopVar || e->op == Op::Read)
    return false;
  if (e->op == Op::Local && !e->local->kernel_level)
    return false;
  for (const auto& o : e->ops)
    if (!invariant(o))
      return false;
  return true;
}

// Partials shared by several terms of an interior cell, factored out:
//   acc += P * g1; acc += P * g2   ->   s0 += g1; s0 += g2; ... acc += P * s0
// (one multiplication instead of one per term, and a shorter dependence
// chain on acc; the sum is the same up to rounding).
struct Factored {
  std::string prefix;                              // the accumulator's name
  std::vector<std::pair<std::string, ExprP>> sums; // name, partial
  std::string name_for(const ExprP& partial) {
    std::string key = print(partial);
    for (const auto& [name, p] : sums)
      if (print(p) == key)
        return name;
    sums.push_back({fmt::format("{}_s{}", prefix, sums.size()), partial});
    return sums.back().first;
  }
};

void emit_terms(Code& code, const Term& t, const Box& where, const std::vector<PathCond>& guards,
                const std::string& acc, const std::string& set_hit,
                Factored* factored = nullptr) {
  Specializer spec(where);
  ExprP partial = spec(t.partial);
  ExprP seed_index = spec(t.store->index);
  std::vector<ExprP> gs;
  for (const auto& pc : guards)
    gs.push_back(spec(pc.positive ? pc.cond : unary(Op::Not, pc.cond)));
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
      parts.push_back(print(g));
    code.open(fmt::format("if ({})", fmt::join(parts, " && ")));
  }
  define_locals(code, locals, done);
  ExprP seed = read(t.store->array + "_adj", seed_index, t.store->value->type, {});
  if (factored && gs.empty() && invariant(partial))
    code.line("{} += {};", factored->name_for(partial), print(seed));
  else
    code.line("{} += {};", acc, print(binary(Op::Mul, partial, seed)));
  if (!set_hit.empty())
    code.line("{}", set_hit);
  if (!gs.empty())
    code.close();
}

// Emits one block inside a cell lambda.
void emit_block(const BlockContext& cx, const Block& b) {
  const Nest& nest = *cx.g.nest;
  std::map<std::string, Poly> back; // "@v" -> -shift, cell space -> iteration space
  for (const auto& [v, c] : cx.g.layout) {
    auto it = b.shift.find(v);
    back["@" + v] = it == b.shift.end() ? Poly() : -it->second;
  }
  Code& code = cx.code;
  std::string iter_desc;
  for (const auto& [v, c] : cx.g.layout) {
    Poly it = Poly::symbol("c_" + v) + back["@" + v];
    iter_desc += (iter_desc.empty() ? "" : ", ") + fmt::format("{} = {}", v, it.code());
  }
  const Store& s = *b.terms.front().store;
  std::string out_cell = s.array + subscript(s.index);
  code.line("// {} reads {}{}: acc += ∂{}/∂{} · {}_adj{}", out_cell, b.comment,
            iter_desc.empty() ? "" : " at " + iter_desc, out_cell, b.comment, s.array,
            subscript(s.index));

  std::vector<Box> boxes;
  if (cx.edge) {
    boxes = b.domain;
  } else {
    Domain in_iter = shift({*cx.interior}, back);
    boxes = intersect(b.domain, in_iter);
    if (boxes.size() != 1)
      boxes = b.domain; // cannot happen for a bulk block; keep it exact anyway
  }
  for (const Box& box : boxes) {
    code.open("");
    // Layout counters come from the cell.
    for (const auto& [v, c] : cx.g.layout) {
      Poly it = Poly::symbol("c_" + v) + back["@" + v];
      code.line("const {} {} = {};", loop_type(nest, v), v, it.code());
    }
    int opened = 0;
    if (cx.edge) {
      std::vector<std::string> conds;
      for (const auto& [v, c] : cx.g.layout) {
        auto d = box.dims.find("@" + v);
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
      auto d = box.dims.find("@" + r);
      std::string t = loop_type(nest, r);
      code.open(fmt::format("for ({} {} = {}; {} < {}; ++{})", t, r,
                            print_max(d->second.lo, t), r, print_min(d->second.hi, t), r));
      ++opened;
    }
    emit_terms(code, b.terms.front(), box, b.guards, cx.acc,
               cx.hit.empty() ? "" : cx.hit + " = true;", cx.factored);
    for (int i = 0; i < opened; ++i)
      code.close();
    code.close();
  }
}

// Fewer cells than this run serially: a parallel region costs microseconds.
constexpr int kMinParallelCells = 8192;

// ---- a gather group ------------------------------------------------------------

void collect_selects(const ExprP& e, std::vector<ExprP>& conds, std::set<const LocalVar*>& seen) {
  if (!e)
    return;
  if (e->op == Op::Local) {
    if (!e->local->kernel_level && seen.insert(e->local.get()).second)
      collect_selects(e->local->def, conds, seen);
    return;
  }
  if (e->op == Op::Select)
    conds.push_back(e->ops[0]);
  for (const auto& o : e->ops)
    collect_selects(o, conds, seen);
}

// Shrinks the interior so that the index conditions of its terms (a periodic
// wrap `i == n - 1 ? 0 : i + 1`) are decided there: a narrow condition box at
// the low end raises the interior's lower bound, one at the high end lowers
// its upper bound. Cells given up go to the guarded edge loop.
void narrow_for_selects(const GatherGroup& g, Box& interior) {
  for (const auto& b : g.blocks) {
    if (!b.bulk)
      continue;
    std::vector<ExprP> conds;
    std::set<const LocalVar*> seen;
    const Term& t = b.terms.front();
    collect_selects(t.partial, conds, seen);
    collect_selects(t.store->index, conds, seen);
    for (const auto& pc : b.guards)
      collect_selects(pc.cond, conds, seen);
    for (const auto& c : conds) {
      auto cd = condition_domain(c);
      if (!cd)
        continue;
      for (const auto& box : *cd)
        for (const auto& [key, iv] : box.dims) {
          auto in = interior.dims.find(key);
          if (in == interior.dims.end() || iv.lo.size() != 1 || iv.hi.size() != 1)
            continue;
          Poly width = iv.hi[0] - iv.lo[0];
          if (!width.is_constant())
            continue;
          auto sit = b.shift.find(key.substr(1));
          Poly d = sit == b.shift.end() ? Poly() : sit->second;
          Poly lo = iv.lo[0] + d, hi = iv.hi[0] + d; // in cell space
          auto near = [](const std::vector<Poly>& set, const Poly& p) {
            for (const auto& q : set)
              if ((p - q).is_constant())
                return true;
            return false;
          };
          if (near(in->second.lo, lo))
            in->second.lo.push_back(hi);
          else if (near(in->second.hi, hi))
            in->second.hi.push_back(lo);
        }
    }
  }
}

std::vector<Poly> shifted(const std::vector<Poly>& set, const Poly& d) {
  std::vector<Poly> out;
  for (const auto& p : set)
    out.push_back(p + d);
  return out;
}

// min over candidates of max(candidate set), printed.
std::string min_of_max(const std::vector<std::vector<Poly>>& cands, const std::string& t,
                       bool lower) {
  std::vector<std::string> parts;
  std::set<std::string> seen;
  std::vector<Poly> singles;
  for (const auto& c : cands) {
    if (c.size() == 1) {
      singles.push_back(c.front());
      continue;
    }
    std::string s = lower ? print_max(c, t) : print_min(c, t);
    if (seen.insert(s).second)
      parts.push_back(s);
  }
  // Singletons that differ by a constant: keep the extreme one.
  std::vector<Poly> kept;
  for (const auto& p : singles) {
    bool drop = false;
    for (auto it = kept.begin(); it != kept.end();) {
      Poly d = p - *it;
      if (!d.is_constant()) {
        ++it;
        continue;
      }
      long long v = d.constant_term();
      bool p_better = lower ? v < 0 : v > 0;
      if (p_better)
        it = kept.erase(it);
      else {
        drop = true;
        break;
      }
    }
    if (!drop)
      kept.push_back(p);
  }
  for (const auto& p : kept)
    if (seen.insert(p.code()).second)
      parts.push_back(p.code());
  if (parts.size() == 1)
    return parts[0];
  std::string fn = lower ? "min" : "max";
  if (parts.size() == 2)
    return fmt::format("std::{}<{}>({}, {})", fn, t, parts[0], parts[1]);
  return fmt::format("std::{}<{}>({{{}}})", fn, t, fmt::join(parts, ", "));
}

// Cell bounding box of a group, per layout counter: (lo, hi) as C++.
std::map<std::string, std::pair<std::string, std::string>> cell_bounds(const GatherGroup& g) {
  std::map<std::string, std::pair<std::string, std::string>> bounds;
  for (const auto& [v, c] : g.layout) {
    std::vector<std::vector<Poly>> los, his;
    for (const auto& b : g.blocks) {
      auto sit = b.shift.find(v);
      Poly d = sit == b.shift.end() ? Poly() : sit->second;
      for (const auto& box : b.domain) {
        const Interval& iv = box.dims.at("@" + v);
        los.push_back(shifted(iv.lo, d));
        his.push_back(shifted(iv.hi, d));
      }
    }
    bounds[v] = {min_of_max(los, kCellType, true), min_of_max(his, kCellType, false)};
  }
  return bounds;
}

// The memory index of cell (c_j, c_i, ...) of a group's layout.
std::string cell_index(const GatherGroup& g) {
  Poly index = g.base;
  for (const auto& [v, c] : g.layout)
    index = index + c * Poly::symbol("c_" + v);
  return index.code();
}

std::string adj_cell(const GatherGroup& g) {
  Poly index = g.base;
  for (const auto& [v, c] : g.layout)
    index = index + c * Poly::symbol("c_" + v);
  return g.array + "_adj" + subscript(index);
}

// One cell loop for one or more gather groups that share a layout and a cell
// box (several inputs of one kernel, fused so the loop reads shared data once).
void emit_gather(Code& code, const Kernel& k, const std::vector<const GatherGroup*>& gs) {
  const GatherGroup& g0 = *gs.front();
  const bool fused = gs.size() > 1;
  auto acc_name = [&](const GatherGroup& g) { return fused ? "acc_" + g.array : std::string("acc"); };
  auto hit_name = [&](const GatherGroup& g) { return fused ? "hit_" + g.array : std::string("hit"); };

  std::string layout_desc;
  for (const auto& [v, c] : g0.layout)
    layout_desc += (layout_desc.empty() ? "" : ", ") + v;
  std::vector<std::string> cells;
  for (const auto* g : gs)
    cells.push_back(adj_cell(*g));
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
  if (fused)
    code.open("");
  else
    code.open(fmt::format("if ({}_adj != nullptr)", g0.array));
  auto store_if = [&](const GatherGroup&, const std::string& cond) {
    return cond.empty() ? std::string() : fmt::format("if ({})", cond);
  };

  auto edge_body = [&]() {
    for (const auto* g : gs) {
      code.line("{} {} = 0;", elem_of(k, g->array), acc_name(*g));
      code.line("bool {} = false;", hit_name(*g));
      for (const auto& b : g->blocks)
        emit_block({k, *g, code, acc_name(*g), hit_name(*g), true, nullptr}, b);
      code.line("{}", store_if(*g, hit_name(*g)));
      code.line("  {} += {};", adj_cell(*g), acc_name(*g));
    }
  };
  if (g0.layout.empty()) {
    // A single cell (a constant index, e.g. the periodic wrap d[0]): sum the
    // iterations that read it.
    edge_body();
    code.close();
    return;
  }

  std::vector<std::string> cell_params;
  for (const auto& [v, c] : g0.layout)
    cell_params.push_back(fmt::format("const {} c_{}", kCellType, v));
  std::string params = fmt::format("{}", fmt::join(cell_params, ", "));

  // Interior box (cell space, "@v" keys): inside every bulk block of every
  // group, narrowed so index conditions are decided.
  Box interior;
  bool any_bulk = false;
  for (const auto& [v, c] : g0.layout) {
    Interval& in = interior.dims["@" + v];
    for (const auto* g : gs)
      for (const auto& b : g->blocks) {
        if (!b.bulk)
          continue;
        any_bulk = true;
        auto sit = b.shift.find(v);
        Poly d = sit == b.shift.end() ? Poly() : sit->second;
        const Interval& iv = b.domain.front().dims.at("@" + v);
        for (const auto& p : shifted(iv.lo, d))
          in.lo.push_back(p);
        for (const auto& p : shifted(iv.hi, d))
          in.hi.push_back(p);
      }
  }
  for (const auto* g : gs)
    narrow_for_selects(*g, interior);
  interior = simplify(interior);

  // Edge cell: every block, each checked against its iteration domain.
  code.open(fmt::format("auto edge = [=]({})", params));
  edge_body();
  code.close(";");
  if (any_bulk) {
    code.open(fmt::format("auto interior = [=]({})", params));
    for (const auto* g : gs) {
      bool has_bulk = false;
      for (const auto& b : g->blocks)
        has_bulk = has_bulk || b.bulk;
      if (!has_bulk)
        continue; // no term of this input reaches the interior
      std::string elem = elem_of(k, g->array);
      code.line("{} {} = 0;", elem, acc_name(*g));
      // A term under a run-time guard (a condition that is not a box of
      // counters) may apply to no iteration of an interior cell, which the
      // source then never read: such a cell is not written, as at an edge.
      bool guarded = false;
      for (const auto& b : g->blocks)
        guarded = guarded || (b.bulk && !b.guards.empty());
      if (guarded)
        code.line("bool {} = false;", hit_name(*g));
      // The blocks go to a buffer first: the sums they factor out are
      // declared before them.
      Factored factored{acc_name(*g), {}};
      Code blocks(code.depth());
      for (const auto& b : g->blocks)
        if (b.bulk)
          emit_block({k, *g, blocks, acc_name(*g), guarded ? hit_name(*g) : "", false, &interior,
                      guarded ? nullptr : &factored},
                     b);
      if (!factored.sums.empty())
        code.line("// partials the same in every iteration, factored out: sums of seeds");
      for (const auto& [name, p] : factored.sums)
        code.line("{} {} = 0;", elem, name);
      code.raw(blocks.str());
      for (const auto& [name, p] : factored.sums)
        code.line("{} += {};", acc_name(*g), print(binary(Op::Mul, p, param(name, p->type))));
      std::string cond = store_if(*g, guarded ? hit_name(*g) : "");
      if (!cond.empty())
        code.line("{}", cond);
      code.line("{}{} += {};", cond.empty() ? "" : "  ", adj_cell(*g), acc_name(*g));
    }
    code.close(";");
  }

  // Ranges.
  auto bounds = cell_bounds(g0);
  for (const auto& [v, c] : g0.layout)
    code.line("const {} lo_{} = {}, hi_{} = {};", kCellType, v, bounds[v].first, v,
              bounds[v].second);
  // The interior holds only if no narrow (edge) block reaches into it.
  if (any_bulk) {
    std::vector<std::string> apart;
    for (const auto* g : gs)
      for (const auto& b : g->blocks) {
        if (b.bulk)
          continue;
        std::map<std::string, Poly> fwd;
        for (const auto& [v, c] : g->layout) {
          auto it = b.shift.find(v);
          fwd["@" + v] = it == b.shift.end() ? Poly() : it->second;
        }
        for (const auto& box : shift(b.domain, fwd)) {
          Box cells_box;
          for (const auto& [v, c] : g->layout)
            cells_box.dims["@" + v] = box.dims.at("@" + v);
          if (box_disjoint(cells_box, {interior}))
            continue;
          std::vector<std::string> ors;
          for (const auto& [key, iv] : box.dims) {
            std::string v = key.substr(1);
            std::string t = kCellType;
            std::string lo = print_max(iv.lo, t), hi = print_min(iv.hi, t);
            ors.push_back(fmt::format("{} >= {}", lo, hi)); // empty
            if (cells_box.dims.count(key)) {
              ors.push_back(fmt::format("{} <= in_lo_{}", hi, v));
              ors.push_back(fmt::format("{} >= in_hi_{}", lo, v));
            }
          }
          apart.push_back("(" + fmt::format("{}", fmt::join(ors, " || ")) + ")");
        }
      }
    for (const auto& [v, c] : g0.layout) {
      std::string t = kCellType;
      const Interval& iv = interior.dims["@" + v];
      code.line("{} in_lo_{} = std::max<{}>(lo_{}, std::min<{}>({}, hi_{}));", t, v, t, v, t,
                print_max(iv.lo, t), v);
      code.line("{} in_hi_{} = std::max<{}>(in_lo_{}, std::min<{}>({}, hi_{}));", t, v, t, v, t,
                print_min(iv.hi, t), v);
    }
    if (!apart.empty()) {
      code.open(fmt::format("if (!({}))", fmt::join(apart, " && ")));
      code.line("// an edge term reaches into the interior: treat every cell as an edge");
      for (const auto& [v, c] : g0.layout)
        code.line("in_lo_{} = in_hi_{} = hi_{};", v, v, v);
      code.close();
    }
  }

  // Threads only for enough cells to pay for a parallel region, and only if
  // the layout is one-to-one over the cell box (mixed radix): else serial.
  std::vector<std::string> extents, conds;
  for (const auto& [v, c] : g0.layout)
    extents.push_back(fmt::format("(hi_{} - lo_{})", v, v));
  conds.push_back(fmt::format("{} >= {}", fmt::join(extents, " * "), kMinParallelCells));
  bool unit_1d = g0.layout.size() == 1 && g0.layout[0].second.is_constant();
  if (!unit_1d) {
    auto order = g0.layout;
    std::stable_sort(order.begin(), order.end(), [](const auto& a, const auto& b) {
      return smaller_coefficient(a.second, b.second);
    });
    std::vector<std::string> reach;
    for (size_t i = 0; i < order.size(); ++i) {
      const auto& [v, c] = order[i];
      std::string coef = c.is_constant() ? std::to_string(std::llabs(c.constant_term())) : c.code();
      if (i > 0)
        conds.push_back(fmt::format("{} < {}", fmt::join(reach, " + "), coef));
      else if (!c.is_constant())
        conds.push_back(fmt::format("{} != 0", coef));
      reach.push_back(fmt::format("({} - 1) * {}", fmt::format("(hi_{} - lo_{})", v, v),
                                  c.is_constant() ? coef : "(" + coef + ")"));
    }
    code.line("// threads if the cells are many and distinct memory (mixed-radix test)");
  } else {
    code.line("// threads if the cells are many");
  }
  code.line("const bool parallel_ok = {};", fmt::join(conds, " && "));
  std::string parallel_if = " if (parallel_ok)";

  // Loops: outer counters with a per-row interior test, the innermost split
  // into edge / interior / edge.
  size_t d = g0.layout.size();
  std::vector<std::string> all_cells;
  for (const auto& [u, c] : g0.layout)
    all_cells.push_back("c_" + u);
  std::string args = fmt::format("{}", fmt::join(all_cells, ", "));
  std::function<void(size_t, std::string)> loops = [&](size_t level, std::string outer_edge) {
    const std::string& v = g0.layout[level].first;
    std::string t = kCellType;
    if (level + 1 < d) {
      if (level == 0)
        code.line("#pragma omp parallel for{}", parallel_if);
      code.open(fmt::format("for ({} c_{} = lo_{}; c_{} < hi_{}; ++c_{})", t, v, v, v, v, v));
      std::string e = fmt::format("c_{} < in_lo_{} || c_{} >= in_hi_{}", v, v, v, v);
      if (!any_bulk)
        e = "true";
      code.line("const bool edge_{} = {}{};", v, outer_edge.empty() ? "" : outer_edge + " || ", e);
      loops(level + 1, "edge_" + v);
      code.close();
      return;
    }
    auto loop = [&](const std::string& from, const std::string& to, const std::string& fn,
                    bool pragma) {
      if (pragma)
        code.line("#pragma omp parallel for{}", parallel_if);
      code.line("for ({} c_{} = {}; c_{} < {}; ++c_{})", t, v, from, v, to, v);
      code.line("  {}({});", fn, args);
    };
    bool top = level == 0;
    if (!any_bulk) {
      loop("lo_" + v, "hi_" + v, "edge", top);
      return;
    }
    if (!outer_edge.empty()) {
      code.open(fmt::format("if ({})", outer_edge));
      loop("lo_" + v, "hi_" + v, "edge", false);
      code.line("continue;");
      code.close();
    }
    loop("lo_" + v, "in_lo_" + v, "edge", false);
    loop("in_lo_" + v, "in_hi_" + v, "interior", top);
    loop("in_hi_" + v, "hi_" + v, "edge", false);
  };
  loops(0, "");
  code.close();
}

// ---- scatter units ---------------------------------------------------------------

void emit_scatter(Code& code, const ScatterUnit& u) {
  const Nest& nest = *u.nest;
  const Store& s = *u.store;
  code.line("// {}_adj: reads of {} in {}{} at indices that cannot be inverted; scatter form, "
            "serial",
            u.array, u.array, s.array, subscript(s.index));
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
  if (!s.path.empty()) {
    std::map<int, LocalP> cond_locals;
    for (const auto& pc : s.path)
      collect(pc.cond, cond_locals, vars);
    define_locals(code, cond_locals, done);
    code.open(fmt::format("if ({})", conjunction(s.path)));
    ++opened;
  }
  std::map<int, LocalP> seed_locals;
  collect(s.index, seed_locals, vars);
  define_locals(code, seed_locals, done);
  code.line("const {} seed = {}_adj{};", type_spelling(s.value->type), s.array, subscript(s.index));
  for (const auto& r : u.reads) {
    code.line("// {}{} = f(..., {}, ...): {}_adj{} += ∂f/∂{} · seed", s.array,
              subscript(s.index), r.read->text, r.read->name, subscript(r.read->ops[0]),
              r.read->text);
    bool guarded = !r.conds.empty();
    if (guarded) {
      std::map<int, LocalP> cond_locals;
      for (const auto& pc : r.conds)
        collect(pc.cond, cond_locals, vars);
      define_locals(code, cond_locals, done);
      code.open(fmt::format("if ({})", conjunction(r.conds)));
    }
    std::map<int, LocalP> locals;
    collect(r.partial, locals, vars);
    collect(r.read->ops[0], locals, vars);
    std::set<int> inner = done;
    define_locals(code, locals, guarded ? inner : done);
    code.line("{}_adj{} += {};", r.read->name, subscript(r.read->ops[0]),
              print(binary(Op::Mul, r.partial, param("seed", s.value->type))));
    if (guarded)
      code.close();
  }
  for (int i = 0; i < opened; ++i)
    code.close();
}

// The adjoint's parameters. `shaped`: arrays of rows as the kernel declares
// them (`const double (*a)[64]`); otherwise every array is a flat pointer.
std::string param_list(const Kernel& k, bool shaped = true) {
  std::vector<std::string> ps;
  auto array = [&](const Param& p, bool is_const, const std::string& name) {
    return array_declaration(p, is_const, name, shaped, k.c_linkage);
  };
  for (const auto& p : k.params) {
    if (shaped && (p.synthetic || !p.twin_of.empty()))
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

// The call from the shaped entry point to the flat one: rows of a
// multi-dimensional array are contiguous, so its first element's address is
// the flat array.
std::string flat_arguments(const Kernel& k) {
  std::vector<std::string> as;
  auto array = flat_argument;
  for (const auto& p : k.params) {
    switch (p.kind) {
    case ParamKind::In:
      as.push_back(array(p, true, p.name));
      as.push_back(array(p, false, p.name + "_adj"));
      break;
    case ParamKind::Out:
      as.push_back(p.twin_of.empty() ? array(p, true, p.name + "_adj")
                                     : p.twin_of + "_seed.data()");
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
// the gather loops (fused where they share a nest, layout and cell box) and
// the scatter loops.
void emit_body(Code& code, const AdjointPlan& plan) {
  const Kernel& k = *plan.kernel;
  for (const auto& l : k.kernel_locals)
    code.line("const {} {} = {};", l->type_name, l->name, print(l->def));
  emit_size_checks(code, k, k.name + "_adjoint");
  // Gather groups of different inputs that share a loop nest, a layout and a
  // cell box run in one fused loop.
  std::set<const GatherGroup*> done;
  auto key = [](const GatherGroup& g) {
    std::string s = fmt::format("{}|{}|", static_cast<const void*>(g.nest), cell_index(g));
    for (const auto& [v, b] : cell_bounds(g))
      s += v + ":" + b.first + "," + b.second + ";";
    return s;
  };
  for (const auto& p : k.params) {
    if (p.kind != ParamKind::In)
      continue;
    for (const auto& g : plan.gathers) {
      if (g.array != p.name || done.count(&g))
        continue;
      std::vector<const GatherGroup*> fused = {&g};
      for (const auto& h : plan.gathers)
        if (&h != &g && h.array != g.array && !done.count(&h) && !h.layout.empty() &&
            key(h) == key(g) && std::none_of(fused.begin(), fused.end(), [&](const auto* f) {
              return f->array == h.array;
            }))
          fused.push_back(&h);
      for (const auto* f : fused)
        done.insert(f);
      if (fused.size() == 1) {
        emit_gather(code, k, fused);
        continue;
      }
      // Fused when every input is active; one loop each when some adjoint
      // is null (an inactive input).
      std::vector<std::string> all;
      for (const auto* f : fused)
        all.push_back(f->array + "_adj != nullptr");
      code.open(fmt::format("if ({})", fmt::join(all, " && ")));
      emit_gather(code, k, fused);
      code.close();
      code.open("else");
      for (const auto* f : fused)
        emit_gather(code, k, {f});
      code.close();
    }
    for (const auto& u : plan.scatters)
      if (u.array == p.name)
        emit_scatter(code, u);
  }
}

// `T* name` for a parameter of the forward kernel's declaration.
std::string forward_params(const Kernel& k) {
  std::vector<std::string> ps;
  for (const auto& p : k.params)
    if (!p.synthetic)
      ps.push_back(p.declaration);
  return fmt::format("{}", fmt::join(ps, ", "));
}

bool reads_array(const ExprP& e, const std::string& array, std::set<const LocalVar*>& seen) {
  if (!e)
    return false;
  if (e->op == Op::Read && e->name == array)
    return true;
  if (e->op == Op::Local)
    return seen.insert(e->local.get()).second && reads_array(e->local->def, array, seen);
  for (const auto& o : e->ops)
    if (reads_array(o, array, seen))
      return true;
  return false;
}

bool nest_reads(const Nest& n, const std::string& array) {
  std::set<const LocalVar*> seen;
  for (const auto& st : n.stores) {
    if (reads_array(st.value, array, seen) || reads_array(st.index, array, seen))
      return true;
    for (const auto& pc : st.path)
      if (reads_array(pc.cond, array, seen))
        return true;
  }
  return false;
}

// A kernel whose later loop nests read what earlier ones wrote (work
// arrays): one adjoint per nest, run in reverse order. The driver recomputes
// the work arrays with the forward kernel (into buffers, NaN where the
// kernel writes nothing), seeds them with their own seeds, and lets each
// nest's adjoint add to them before the nest that wrote them reads them.
void emit_staged(Code& code, const Kernel& k, const std::string& fn_name) {
  std::deque<Kernel> stages;
  std::vector<AdjointPlan> plans;
  for (size_t j = 0; j < k.nests.size(); ++j) {
    Kernel s = k;
    s.name = fmt::format("{}_nest{}", k.name, j + 1);
    s.nests = {k.nests[j]};
    s.size_checks.clear();
    for (auto& p : s.params)
      if (k.intermediates.count(p.name))
        p.kind = nest_reads(k.nests[j], p.name) ? ParamKind::In : ParamKind::Out;
    stages.push_back(std::move(s));
    plans.push_back(schedule(stages.back()));
  }
  code.raw("namespace {\n");
  for (size_t j = 0; j < stages.size(); ++j) {
    const Kernel& s = stages[j];
    code.line("// Adjoint of loop nest {} of {} ({}:{}).", j + 1, k.name, base_name(k.file),
              s.nests.front().stores.front().pos.line);
    code.open(fmt::format("void {}_adjoint({})", s.name, param_list(s, false)));
    emit_body(code, plans[j]);
    code.close();
    code.raw("\n");
  }
  code.raw("} // namespace\n\n");
  code.line("// The forward kernel, which recomputes the work arrays.");
  code.line("{}void {}({});", k.c_linkage ? "extern \"C\" " : "", k.name, forward_params(k));
  code.raw("\n");
  code.line("// Adjoint of {} ({}:{}): its loop nests backwards; the work arrays {} are "
            "recomputed first.",
            k.name, base_name(k.file), k.pos.line,
            fmt::join(k.intermediates.begin(), k.intermediates.end(), ", "));
  code.open(fmt::format("void {}({})", fn_name, param_list(k, false)));
  for (const auto& l : k.kernel_locals)
    code.line("const {} {} = {};", l->type_name, l->name, print(l->def));
  emit_size_checks(code, k, k.name + "_adjoint");
  std::vector<std::string> fwd;
  for (const auto& p : k.params) {
    if (p.kind == ParamKind::Out) {
      code.line("const std::ptrdiff_t {}_n = {};", p.name, k.extent.at(p.name));
      code.line("std::vector<{}> {}_v(static_cast<std::size_t>({}_n), "
                "std::numeric_limits<{}>::quiet_NaN());",
                p.elem_name, p.name, p.name, p.elem_name);
      if (k.intermediates.count(p.name))
        code.line("std::vector<{}> {}_b({}_adj, {}_adj + {}_n); // its seed, then more", p.elem_name,
                  p.name, p.name, p.name, p.name);
      std::string data = p.name + "_v.data()";
      fwd.push_back(p.rows.empty() ? data
                                   : fmt::format("reinterpret_cast<{} (*){}>({})", p.elem_name,
                                                 p.rows, data));
    } else if (p.kind == ParamKind::Scalar || p.rows.empty()) {
      fwd.push_back(p.name);
    } else {
      fwd.push_back(fmt::format("reinterpret_cast<const {} (*){}>({})", p.elem_name, p.rows,
                                p.name));
    }
  }
  code.line("{}({});", k.name, fmt::join(fwd, ", "));
  for (size_t j = stages.size(); j-- > 0;) {
    const Kernel& s = stages[j];
    std::vector<std::string> args;
    for (const auto& p : s.params) {
      bool work = k.intermediates.count(p.name) > 0;
      switch (p.kind) {
      case ParamKind::In:
        args.push_back(work ? p.name + "_v.data()" : p.name);
        args.push_back(work ? p.name + "_b.data()" : p.name + "_adj");
        break;
      case ParamKind::Out:
        args.push_back(work ? p.name + "_b.data()" : p.name + "_adj");
        break;
      case ParamKind::ConstArray:
      case ParamKind::Scalar:
        args.push_back(p.name);
        break;
      }
    }
    code.line("{}_adjoint({});", s.name, fmt::join(args, ", "));
  }
  code.close();
}

// An in-place array u: on entry u_adj holds the seed of its new values, on
// return the adjoint of its old ones. The flat adjoint sees u as an input and
// its new values as the output u_new: so u_adj starts as 0 where the kernel
// writes u (the old value reaches the new one only through the kernel) and
// as the seed elsewhere (an element the kernel leaves is passed through).
void emit_inout_prologue(Code& code, const Kernel& k) {
  if (!has_inout(k))
    return;
  for (const auto& l : k.kernel_locals)
    code.line("const {} {} = {};", l->type_name, l->name, print(l->def));
  for (const auto& p : k.params) {
    if (!p.inout)
      continue;
    const std::string twin = p.name + "_new";
    code.line("// '{}' is updated in place: {}_adj holds the seed of its new values on entry",
              p.name, p.name);
    code.line("// and the adjoint of its old values on return.");
    code.line("const std::ptrdiff_t {}_n = {};", p.name, k.extent.at(twin));
    code.line("std::vector<{}> {}_seed({}_adj, {}_adj + {}_n);", p.elem_name, p.name, p.name, p.name,
              p.name);
    for (const auto& nest : k.nests) {
      bool writes = false;
      for (const auto& s : nest.stores)
        writes = writes || s.array == twin;
      if (!writes)
        continue;
      code.open("");
      int opened = 1;
      for (const auto& l : nest.loops) {
        code.open(fmt::format("for ({} {} = {}; {} < {}; ++{})", kCellType, l.var, print(l.lo),
                              l.var, print(l.hi), l.var));
        ++opened;
      }
      std::set<int> done;
      std::set<std::string> vars;
      for (const auto& s : nest.stores) {
        if (s.array != twin)
          continue;
        std::map<int, LocalP> locals;
        for (const auto& pc : s.path)
          collect(pc.cond, locals, vars);
        collect(s.index, locals, vars);
        define_locals(code, locals, done);
        if (s.path.empty())
          code.line("{}_adj{} = 0;", p.name, subscript(s.index));
        else
          code.line("if ({}) {}_adj{} = 0;", conjunction(s.path), p.name, subscript(s.index));
      }
      for (int i = 0; i < opened; ++i)
        code.close();
    }
  }
}

void emit_kernel(Code& code, const AdjointPlan& plan) {
  const Kernel& k = *plan.kernel;
  open_namespaces(code, k);
  bool rows = has_rows(k) || has_inout(k);
  std::string name = k.name + (rows ? "_adjoint_flat" : "_adjoint");
  if (rows)
    code.raw("namespace {\n");
  if (!k.intermediates.empty()) {
    emit_staged(code, k, name);
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

} // namespace

std::string adjoint_signature(const Kernel& k) {
  return fmt::format("void {}_adjoint({})", k.name, param_list(k));
}

EmittedFile emit_file(const std::vector<AdjointPlan>& plans, const std::string& source_name,
                      const std::string& stem) {
  EmittedFile out;
  Code h;
  h.raw(fmt::format(kBanner, source_name));
  h.raw("//\n"
        "// Reverse-mode (vector-Jacobian product) kernels. For a kernel\n"
        "// f(in..., out..., constants...), f_adjoint takes the same parameters in order,\n"
        "// each DPGEN_IN array followed by its <name>_adj, which is accumulated with +=,\n"
        "// and each DPGEN_OUT array replaced by its read-only seed <name>_adj.\n"
        "#pragma once\n\n"
        "#include <stddef.h> // size_t, for the checked entry points (C and C++)\n\n");
  bool vectors = false;
  for (const auto& p : plans)
    vectors = vectors || has_vectors(*p.kernel);
  if (vectors)
    h.raw("#include <vector>\n\n");
  for (const auto& p : plans) {
    open_namespaces(h, *p.kernel);
    h.raw(fmt::format("/// Adjoint of {} ({}:{}).\n", p.kernel->name, base_name(p.kernel->file),
                      p.kernel->pos.line));
    if (p.kernel->c_linkage) // a C kernel: callable from C
      h.raw("#ifdef __cplusplus\nextern \"C\" {\n#endif\n");
    h.raw(adjoint_signature(*p.kernel) + ";\n");
    if (has_checked_entry(*p.kernel))
      h.raw(fmt::format("/// The same, each array followed by its number of elements: sizes too small\n"
                        "/// for the elements the kernel touches throw std::invalid_argument.\n"
                        "{};\n",
                        checked_signature(*p.kernel)));
    if (p.kernel->c_linkage)
      h.raw("#ifdef __cplusplus\n}\n#endif\n");
    close_namespaces(h, *p.kernel);
    h.raw("\n");
  }
  out.header = formatted(h.str(), stem + "_adjoint.hpp");

  // The forward kernels' declarations, so a caller includes them instead of
  // writing them by hand.
  Code d;
  d.raw(fmt::format(kBanner, source_name));
  d.raw("//\n// Declarations of the forward kernels, as the kernel file defines them.\n"
        "#pragma once\n\n");
  bool vec = false;
  for (const auto& p : plans)
    vec = vec || has_vectors(*p.kernel);
  if (vec)
    d.raw("#include <vector>\n\n");
  for (const auto& p : plans) {
    const Kernel& k = *p.kernel;
    open_namespaces(d, k);
    d.raw(fmt::format("/// {}:{}.\n", base_name(k.file), k.pos.line));
    std::vector<std::string> ps, flat;
    for (const auto& prm : k.params) {
      if (prm.synthetic || !prm.twin_of.empty())
        continue;
      ps.push_back(prm.inout ? fmt::format("{}* {}", prm.elem_name, prm.name) : prm.declaration);
      bool is_const = prm.kind == ParamKind::In ? !prm.inout : prm.kind == ParamKind::ConstArray;
      flat.push_back(prm.kind == ParamKind::Scalar
                         ? fmt::format("{} {}", prm.spelling, prm.name)
                         : fmt::format("{}{}* {}", is_const ? "const " : "", prm.elem_name,
                                       prm.name));
    }
    if (k.c_linkage) {
      // C's variable-length rows and restrict are not C++: from C++ the same
      // function is declared with flat pointers (the same ABI).
      d.raw(fmt::format("#ifdef __cplusplus\nextern \"C\" void {}({});\n#else\n", k.name,
                        fmt::join(flat, ", ")));
      d.raw(fmt::format("void {}({});\n#endif\n", k.name, fmt::join(ps, ", ")));
    } else {
      d.raw(fmt::format("void {}({});\n", k.name, fmt::join(ps, ", ")));
    }
    close_namespaces(d, k);
    d.raw("\n");
  }
  out.kernels = formatted(d.str(), stem + "_kernels.hpp");

  Code c;
  c.raw(fmt::format(kBanner, source_name));
  c.raw("//\n"
        "// Gather form: each adjoint cell is written by exactly one loop iteration, which\n"
        "// sums the contributions of every forward iteration that read that cell, each\n"
        "// recomputed from the primal inputs (no tape). Interior cells run a branch-free\n"
        "// loop; edge cells check each term's iteration domain.\n");
  c.raw(fmt::format("#include \"{}_adjoint.hpp\"\n\n", stem));
  c.raw("#include <algorithm>\n#include <cmath>\n#include <cstddef>\n#include <limits>\n");
  bool checks = false;
  for (const auto& p : plans)
    checks = checks || !p.kernel->size_checks.empty() || has_vectors(*p.kernel);
  c.raw("#include <stdexcept>\n#include <string>\n"); // the checked entry points
  bool staged = false;
  for (const auto& p : plans)
    staged = staged || !p.kernel->intermediates.empty();
  for (const auto& p : plans)
    staged = staged || has_inout(*p.kernel);
  if (staged)
    c.raw("#include <vector>\n");
  c.raw("\n");
  c.raw("#if defined(__GNUC__) && !defined(__clang__)\n"
        "// Cell ranges are clamped at run time (std::max/std::min), which GCC cannot see\n"
        "// through when it bounds a loop's trip count: its overflow warning is spurious.\n"
        "#pragma GCC diagnostic ignored \"-Waggressive-loop-optimizations\"\n"
        "#endif\n\n");
  c.raw("namespace {\n"
        "// std::min/std::max with the same result (the first argument on ties), by\n"
        "// value so loops around them vectorize.\n"
        "template <typename T> inline T dpgen_min(T a, T b) { return b < a ? b : a; }\n"
        "template <typename T> inline T dpgen_max(T a, T b) { return a < b ? b : a; }\n"
        "} // namespace\n\n");
  for (const auto& p : plans) {
    emit_kernel(c, p);
    c.raw("\n");
    if (has_checked_entry(*p.kernel)) {
      emit_checked_entry(c, *p.kernel);
      c.raw("\n");
    }
  }
  out.source = formatted(c.str(), stem + "_adjoint.cpp");
  return out;
}

} // namespace dpgen
