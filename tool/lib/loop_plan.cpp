// Plan (phase 5): cell boxes, interiors, edge reaches, fusion, the parallel
// test of the gather loops and the terms each box prints (see loop_plan.hpp).
#include "loop_plan.hpp"

#include "ir_walk.hpp"
#include "print.hpp"

#include <stdexcept>

#include <algorithm>

namespace dpgen {

namespace {

void collect_selects(const ExprP& e, std::vector<ExprP>& conds, std::set<const LocalVar*>& seen) {
  walk(
      e,
      [&](const ExprP& x) {
        if (x->op == Op::Select)
          conds.push_back(x->ops[0]);
        return true;
      },
      [](const ExprP& l) { return !l->local->kernel_level; }, seen);
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
          auto sit = b.shift.find(key);
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

// The shift of block `b` in counter `v` (zero when it has none).
Poly shift_of(const Block& b, const std::string& v) {
  auto it = b.shift.find(v);
  return it == b.shift.end() ? Poly() : it->second;
}

// The minimum over candidates of the maximum of each (`lower`; else the
// maximum of minima). Candidate sets lose duplicate bounds, equal sets are
// kept once, and of single bounds that differ by a constant only the extreme
// one is kept.
CellBound bound_of(const std::vector<std::vector<Poly>>& cands, bool lower) {
  CellBound out;
  auto add = [&](std::vector<Poly> part) {
    if (std::find(out.parts.begin(), out.parts.end(), part) == out.parts.end())
      out.parts.push_back(std::move(part));
  };
  std::vector<Poly> singles;
  for (const auto& c : cands) {
    if (c.size() == 1) {
      singles.push_back(c.front());
      continue;
    }
    std::vector<Poly> part;
    for (const auto& p : c)
      if (std::find(part.begin(), part.end(), p) == part.end())
        part.push_back(p);
    add(part);
  }
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
    add({p});
  return out;
}

// Cell bounding box of a group, per layout counter.
std::map<std::string, CellRange> cell_bounds(const GatherGroup& g) {
  std::map<std::string, CellRange> bounds;
  for (const auto& [v, c] : g.layout) {
    std::vector<std::vector<Poly>> los, his;
    for (const auto& b : g.blocks) {
      Poly d = shift_of(b, v);
      for (const auto& box : b.domain) {
        const Interval& iv = box.dims.at(v);
        los.push_back(shifted(iv.lo, d));
        his.push_back(shifted(iv.hi, d));
      }
    }
    bounds[v] = {bound_of(los, true), bound_of(his, false)};
  }
  return bounds;
}

// Whether the cell boxes of two keys differ by constants only (each end one
// bound, the same up to a constant): fused over the box around both, the loop
// has a few more edge cells than either alone (divergence2d: u's cells are
// i in [0, nx), j in [1, ny - 1); v's i in [1, nx - 1), j in [0, ny)).
bool near_boxes(const FusionKey& a, const FusionKey& b) {
  if (a.bounds.size() != b.bounds.size())
    return false;
  auto one = [](const CellBound& c) { return c.parts.size() == 1 && c.parts[0].size() == 1; };
  auto near = [&](const CellBound& x, const CellBound& y) {
    return one(x) && one(y) && (x.parts[0][0] - y.parts[0][0]).is_constant();
  };
  for (const auto& [v, r] : a.bounds) {
    auto it = b.bounds.find(v);
    if (it == b.bounds.end() || !near(r.lo, it->second.lo) || !near(r.hi, it->second.hi))
      return false;
  }
  return true;
}

FusionKey fusion_key(const Kernel& k, const GatherGroup& g) {
  FusionKey key;
  key.nest = size_t(g.nest - k.nests.data());
  key.cell = g.base;
  for (const auto& [v, c] : g.layout)
    key.cell = key.cell + c * Poly::symbol("c_" + v);
  key.bounds = cell_bounds(g);
  return key;
}

// ---- the terms of each box: expressions under a known box --------------------

// An integer min/max of two operands (dpgen_min(a, b) = b < a ? b : a,
// dpgen_max(a, b) = a < b ? b : a): the condition under which it is its
// second operand; null for any other expression.
ExprP clamp_condition(const ExprP& e) {
  if (e->op != Op::Call || e->type != Type::Int || e->ops.size() != 2 ||
      (e->name != "min" && e->name != "max"))
    return nullptr;
  return e->name == "min" ? binary(Op::Lt, e->ops[1], e->ops[0])
                          : binary(Op::Lt, e->ops[0], e->ops[1]);
}

// Replaces conditional expressions whose index condition is decided inside
// `box` (only comparisons differing by a constant are decided), so an
// interior loop reads a[i + 1] instead of a[(i == n - 1) ? 0 : i + 1].
class Specializer {
public:
  /// `clamps`: also an integer min/max whose comparison the box decides
  /// (`std::max(i - 1, 0)` is `i - 1` for i >= 1; the forward forms' split).
  explicit Specializer(const Box& box, bool clamps = false) : box_(box), clamps_(clamps) {}

  ExprP operator()(const ExprP& e) {
    if (!e)
      throw std::logic_error("internal error: plan: a null expression to specialize");
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
    ExprP out = map_operands(e, [&](const ExprP& o) { return (*this)(o); });
    if (clamps_) {
      // (its operands first: min(max(i - 3, 0), n - 1) compares i - 3 with n - 1)
      if (const ExprP c = clamp_condition(out)) { // the second operand where c holds
        if (auto cd = condition_domain(c)) {
          if (box_inside(box_, *cd))
            return out->ops[1];
          if (box_disjoint(box_, *cd))
            return out->ops[0];
        }
      }
    }
    return out;
  }

private:
  const Box& box_;
  bool clamps_ = false;
  std::map<const LocalVar*, ExprP> memo_;
};

// The same in every iteration: parameters and kernel-level locals only.
bool same_everywhere(const ExprP& e) {
  if (e->op == Op::LoopVar || e->op == Op::Read)
    return false;
  if (e->op == Op::Local && !e->local->kernel_level)
    return false;
  return std::all_of(e->ops.begin(), e->ops.end(), same_everywhere);
}

// A partial as the schedule leaves it: never zero() (it drops the reads
// whose partial vanishes).
const ExprP& nonzero_partial(const ExprP& partial) {
  if (is_zero(partial))
    throw std::logic_error("internal error: plan: a zero partial reached the loop plan (the "
                           "schedule drops them)");
  return partial;
}

// A block's first term in one box of its iterations (BoxTerm). Its partial is
// never zero: the schedule drops the reads whose partial vanishes.
BoxTerm box_term(const Block& b, const Box& box) {
  const Term& t = b.terms.front();
  Specializer spec(box);
  BoxTerm out{box, spec(nonzero_partial(t.partial)), spec(t.store->index), {}};
  for (const auto& pc : b.guards)
    out.guards.push_back(spec(pc.positive ? pc.cond : unary(Op::Not, pc.cond)));
  out.same_everywhere = same_everywhere(out.partial);
  return out;
}

ScatterLoop scatter_loop(const ScatterUnit& u) {
  ScatterLoop out{&u, u.store->index, u.store->path, {}};
  for (const auto& r : u.reads)
    out.reads.push_back({&r, r.conds, nonzero_partial(r.partial), r.read->ops[0]});
  return out;
}

CellLoop plan_cell_boxes(const Kernel& k, const std::vector<const GatherGroup*>& gs) {
  CellLoop loop;
  loop.groups = gs;
  const GatherGroup& g0 = *gs.front();
  if (g0.layout.empty())
    return loop; // a single cell: summed over the iterations that read it
  // The box around every group's cells (the same box for groups fused by
  // equal keys; near_boxes: each end the outermost). A cell outside a
  // group's own box is an edge cell where none of its terms applies: each
  // term checks its iteration's domain, so `hit` stays false and the cell is
  // not written, as the group's own loop would not visit it.
  for (const auto& [v, c] : g0.layout) {
    std::vector<std::vector<Poly>> los, his;
    for (const auto* g : gs) {
      const CellRange r = cell_bounds(*g).at(v);
      los.insert(los.end(), r.lo.parts.begin(), r.lo.parts.end());
      his.insert(his.end(), r.hi.parts.begin(), r.hi.parts.end());
    }
    loop.bounds[v] = {bound_of(los, true), bound_of(his, false)};
  }

  // Interior box (cell space): inside every bulk block of every
  // group, narrowed so index conditions are decided.
  Box& interior = loop.interior;
  for (const auto& [v, c] : g0.layout) {
    Interval& in = interior.dims[v];
    for (const auto* g : gs)
      for (const auto& b : g->blocks) {
        if (!b.bulk)
          continue;
        loop.any_bulk = true;
        Poly d = shift_of(b, v);
        const Interval& iv = b.domain.front().dims.at(v);
        for (const auto& p : shifted(iv.lo, d))
          in.lo.push_back(p);
        for (const auto& p : shifted(iv.hi, d))
          in.hi.push_back(p);
      }
  }
  for (const auto* g : gs)
    narrow_for_selects(*g, interior);
  interior = simplify(interior);

  // The interior holds only if no narrow (edge) block reaches into it.
  if (loop.any_bulk)
    for (const auto* g : gs)
      for (const auto& b : g->blocks) {
        if (b.bulk)
          continue;
        std::map<std::string, Poly> fwd;
        for (const auto& [v, c] : g->layout)
          fwd[v] = shift_of(b, v);
        for (const auto& box : shift(b.domain, fwd)) {
          EdgeReach reach{box, {}};
          Box cells_box;
          for (const auto& [v, c] : g->layout) {
            cells_box.dims[v] = box.dims.at(v);
            reach.cell_dims.insert(v);
          }
          if (box_disjoint(cells_box, {interior}))
            continue;
          loop.reaches.push_back(reach);
        }
      }

  // Where each bulk block's iteration lies for an interior cell: its domain
  // within the interior shifted back to iteration space.
  for (const auto* g : gs) {
    loop.interior_boxes.emplace_back();
    for (const auto& b : g->blocks) {
      loop.interior_boxes.back().emplace_back();
      if (!b.bulk)
        continue;
      std::map<std::string, Poly> back; // counter -> -shift: cell space -> iteration space
      for (const auto& [v, c] : g->layout)
        back[v] = -shift_of(b, v);
      Domain boxes = intersect(b.domain, shift({interior}, back));
      if (boxes.size() != 1)
        boxes = b.domain; // cannot happen for a bulk block; keep it exact anyway
      loop.interior_boxes.back().back() = boxes;
    }
  }

  // Threads only if the layout is one-to-one over the cell box (mixed radix,
  // with the run-time extents hi - lo).
  loop.unit_1d = g0.layout.size() == 1 && g0.layout[0].second.is_constant();
  if (!loop.unit_1d) {
    std::vector<std::pair<Poly, Poly>> dims;
    for (const auto& [v, c] : g0.layout)
      dims.push_back({c, Poly::symbol(k.fresh("hi_" + v)) - Poly::symbol(k.fresh("lo_" + v))});
    loop.radix = mixed_radix(dims);
  }
  return loop;
}

// Each block's term in the boxes an edge cell and an interior cell print
// (the interior boxes planned first).
void plan_terms(CellLoop& loop) {
  for (size_t gi = 0; gi < loop.groups.size(); ++gi) {
    loop.edge_terms.emplace_back();
    loop.interior_terms.emplace_back();
    for (size_t bi = 0; bi < loop.groups[gi]->blocks.size(); ++bi) {
      const Block& b = loop.groups[gi]->blocks[bi];
      loop.edge_terms.back().emplace_back();
      for (const Box& box : b.domain)
        loop.edge_terms.back().back().push_back(box_term(b, box));
      loop.interior_terms.back().emplace_back();
      if (b.bulk && gi < loop.interior_boxes.size())
        for (const Box& box : loop.interior_boxes[gi][bi])
          loop.interior_terms.back().back().push_back(box_term(b, box));
    }
  }
}

// The terms of an edge row's cells in the interior's range of the innermost
// counter (CellLoop::row_terms); none if no term would change.
void plan_row_terms(CellLoop& loop) {
  const GatherGroup& g0 = *loop.groups.front();
  if (g0.layout.size() < 2 || !loop.any_bulk)
    return;
  const std::string& v = g0.layout.back().first;
  Box row; // cell space: the innermost counter in the interior's range
  row.dims[v] = loop.interior.dims.at(v);
  if (box_disjoint(row, universe()))
    return; // an empty range (box_disjoint with the universe: box_empty)
  bool changed = false;
  std::vector<std::vector<std::vector<BoxTerm>>> terms;
  for (size_t gi = 0; gi < loop.groups.size(); ++gi) {
    terms.emplace_back();
    for (size_t bi = 0; bi < loop.groups[gi]->blocks.size(); ++bi) {
      const Block& b = loop.groups[gi]->blocks[bi];
      terms.back().emplace_back();
      std::map<std::string, Poly> back; // cell space -> iteration space
      for (const auto& [u, c] : loop.groups[gi]->layout)
        back[u] = -shift_of(b, u);
      const Box reach = shift({row}, back).front(); // the iterations' innermost counter
      for (size_t i = 0; i < b.domain.size(); ++i) {
        const Box& box = b.domain[i];
        if (box_disjoint(reach, {box})) {
          changed = true; // applies to no cell of the range
          continue;
        }
        const Domain narrowed = intersect({box}, {reach}); // one box: not disjoint
        BoxTerm t = box_term(b, narrowed.size() == 1 ? narrowed.front() : box);
        t.box = box; // the checks printed: the box's own, ...
        auto it = box.dims.find(v);
        if (it != box.dims.end()) {
          Box inner;
          inner.dims[v] = it->second;
          if (box_inside(reach, {inner})) { // ... less the one the range decides
            t.box.dims.erase(v);
            changed = true;
          }
        }
        const BoxTerm& e = loop.edge_terms[gi][bi][i];
        changed = changed || print(t.partial) != print(e.partial) ||
                  print(t.seed_index) != print(e.seed_index);
        terms.back().back().push_back(std::move(t));
      }
    }
  }
  if (changed)
    loop.row_terms = std::move(terms);
}

CellLoop plan_cell_loop(const Kernel& k, const std::vector<const GatherGroup*>& gs) {
  CellLoop loop = plan_cell_boxes(k, gs);
  plan_terms(loop);
  plan_row_terms(loop);
  loop.factored.assign(gs.size(), {}); // (none until the pass `hoist`)
  return loop;
}

LoopPlan plan_adjoint_loops(const AdjointPlan& plan) {
  LoopPlan out;
  out.adjoint = &plan;
  for (const auto& s : plan.stages)
    out.stages.push_back(plan_adjoint_loops(*s.plan));
  if (!plan.stages.empty())
    return out; // printed stage by stage
  const Kernel& k = *plan.kernel;
  // Gather groups of different inputs that share a loop nest and a layout,
  // with the same cell box or boxes a constant apart, run in one fused loop.
  std::vector<FusionKey> keys;
  for (const auto& g : plan.gathers)
    keys.push_back(fusion_key(k, g));
  std::vector<bool> done(plan.gathers.size(), false);
  for (const auto& p : k.params) {
    if (p.kind != ParamKind::In)
      continue;
    InputLoops in;
    in.array = p.name;
    for (size_t i = 0; i < plan.gathers.size(); ++i) {
      const GatherGroup& g = plan.gathers[i];
      if (g.array != p.name || done[i])
        continue;
      std::vector<const GatherGroup*> fused = {&g};
      auto candidate = [&](size_t j) {
        const GatherGroup& h = plan.gathers[j];
        return j != i && h.array != g.array && !done[j] && !h.layout.empty() &&
               keys[j].nest == keys[i].nest && keys[j].cell == keys[i].cell &&
               std::none_of(fused.begin(), fused.end(),
                            [&](const auto* f) { return f->array == h.array; });
      };
      for (size_t j = 0; j < plan.gathers.size(); ++j)
        if (candidate(j) && keys[j] == keys[i])
          fused.push_back(&plan.gathers[j]);
      // Groups whose boxes differ by constants join too (one pass over the
      // seed, one parallel region), if the loop around them keeps a
      // branch-free interior that no edge term can reach into (else each
      // would lose its interior to the other's edges) and every group has
      // terms there.
      auto has_bulk = [](const GatherGroup* f) {
        return std::any_of(f->blocks.begin(), f->blocks.end(),
                           [](const Block& b) { return b.bulk; });
      };
      for (size_t j = 0; j < plan.gathers.size(); ++j) {
        if (!candidate(j) || keys[j] == keys[i] || !near_boxes(keys[j], keys[i]))
          continue;
        std::vector<const GatherGroup*> with = fused;
        with.push_back(&plan.gathers[j]);
        const CellLoop trial = plan_cell_boxes(k, with);
        if (trial.any_bulk && trial.reaches.empty() &&
            std::all_of(with.begin(), with.end(), has_bulk))
          fused = std::move(with);
      }
      for (const auto* f : fused)
        done[size_t(f - plan.gathers.data())] = true;
      GatherStep step;
      step.loops.push_back(plan_cell_loop(k, fused));
      // A loop of each alone, for when some input is inactive (a view never is).
      if (fused.size() > 1 && std::any_of(fused.begin(), fused.end(), [&](const auto* f) {
            return !k.find_param(f->array)->view;
          }))
        for (const auto* f : fused)
          step.loops.push_back(plan_cell_loop(k, {f}));
      in.gathers.push_back(std::move(step));
    }
    for (const auto& u : plan.scatters)
      if (u.array == p.name)
        in.scatters.push_back(scatter_loop(u));
    out.inputs.push_back(std::move(in));
  }
  return out;
}

} // namespace

LoopPlan plan_loops(const AdjointPlan& plan) {
  LoopPlan out = plan_adjoint_loops(plan);
  out.forward = plan_forward(*plan.kernel);
  peel_forward(out.forward);
  return out;
}

ForwardPlan plan_forward(const Kernel& k) {
  ForwardPlan plan;
  plan.kernel = &k;
  for (const auto& nest : k.nests) {
    const bool adds = std::any_of(nest.stores.begin(), nest.stores.end(),
                                  [](const Store& s) { return s.accumulate; });
    plan.nests.push_back({&nest, !nest.loops.empty() && !adds, {}, {}, {}});
    for (const auto& st : nest.stores)
      plan.nests.back().stores.push_back({&st, st.index, st.value, nullptr, st.path, st.chain});
  }
  return plan;
}

namespace {

// Adds `p` to one side of an interval's bounds (`lower`: the interval starts
// at their maximum; else it ends at their minimum) unless a bound there is at
// least as tight; drops the bounds `p` makes loose.
void tighten(std::vector<Poly>& bounds, const Poly& p, bool lower) {
  for (auto it = bounds.begin(); it != bounds.end();) {
    Poly d = p - *it;
    if (!d.is_constant()) {
      ++it;
      continue;
    }
    const long long v = d.constant_term();
    if (lower ? v <= 0 : v >= 0)
      return; // as tight already
    it = bounds.erase(it);
  }
  bounds.push_back(p);
}

// The interval of loop `l`'s counter where the index conditions of `stores`
// (their selects, guards and integer clamps) are decided: a piece of a condition's
// domain, or of its complement, that ends a constant from one end of the loop
// is left to the edge loops (`i == n - 1`: the last iteration; `i + 1 < n`
// fails only there). Empty bounds: nothing decided.
Interval forward_interior(const Loop& l, const std::vector<ForwardStore>& stores) {
  Interval in;
  const auto lo = to_poly(l.lo), hi = to_poly(l.hi);
  if (!lo || !hi)
    return in;
  std::vector<ExprP> conds;
  std::set<const LocalVar*> seen;
  auto collect = [&](const ExprP& e) {
    walk(
        e,
        [&](const ExprP& x) {
          if (x->op == Op::Select)
            conds.push_back(x->ops[0]);
          else if (const ExprP c = clamp_condition(x))
            conds.push_back(c);
          return true;
        },
        [](const ExprP& l) { return !l->local->kernel_level; }, seen);
  };
  for (const auto& s : stores) {
    for (const ExprP& e : {s.index, s.value, s.dot})
      if (e)
        collect(e);
    for (const auto& pc : s.path) {
      conds.push_back(pc.cond);
      collect(pc.cond);
    }
  }
  std::vector<Poly> los = {*lo}, his = {*hi}; // (the loop's own bounds first)
  for (const auto& c : conds) {
    auto cd = condition_domain(c);
    if (!cd)
      continue;
    for (const Domain& d : {*cd, subtract(universe(), *cd)})
      for (const Box& box : d) {
        auto it = box.dims.find(l.var);
        if (it == box.dims.end())
          continue;
        // (the piece ends below each of its upper bounds, starts at or above
        // each lower one)
        const Interval& iv = it->second;
        auto near = [](const std::vector<Poly>& set, const Poly& end) -> const Poly* {
          for (const auto& p : set)
            if ((p - end).is_constant())
              return &p;
          return nullptr;
        };
        if (const Poly* p = near(iv.hi, *lo))
          tighten(los, *p, true); // a piece at the low end
        else if (const Poly* q = near(iv.lo, *hi))
          tighten(his, *q, false); // at the high end
      }
  }
  for (const auto& p : los)
    if (!(p == *lo))
      in.lo.push_back(p);
  for (const auto& p : his)
    if (!(p == *hi))
      in.hi.push_back(p);
  return in;
}

// A condition inside `box`: `value` 1 or 0 where the box decides it, else -1
// and `cond` with the operands of its && and || that the box decides dropped
// (`i == 0 || j == 0` is `j == 0` for i inside; the conditions are pure, so
// an operand left unevaluated changes nothing).
struct FoldedCond {
  ExprP cond;
  int value = -1;
};

FoldedCond fold_cond(const Box& box, const ExprP& c) {
  if (auto cd = condition_domain(c)) {
    if (box_inside(box, *cd))
      return {nullptr, 1};
    if (box_disjoint(box, *cd))
      return {nullptr, 0};
  }
  if (c->op == Op::And || c->op == Op::Or) {
    const FoldedCond a = fold_cond(box, c->ops[0]), b = fold_cond(box, c->ops[1]);
    const int absorbing = c->op == Op::And ? 0 : 1; // (false && x, true || x)
    if (a.value == absorbing || b.value == absorbing)
      return {nullptr, absorbing};
    if (a.value >= 0)
      return b; // (true && x, false || x)
    if (b.value >= 0)
      return a;
    if (a.cond == c->ops[0] && b.cond == c->ops[1])
      return {c, -1};
    return {binary(c->op, a.cond, b.cond), -1};
  }
  if (c->op == Op::Not) {
    const FoldedCond a = fold_cond(box, c->ops[0]);
    if (a.value >= 0)
      return {nullptr, 1 - a.value};
    return {a.cond == c->ops[0] ? c : unary(Op::Not, a.cond), -1};
  }
  return {c, -1};
}

// A store as printed inside `box`: its conditions folded where the box
// decides them; false when its guard fails everywhere there.
bool fold_store(const Box& box, Specializer& spec, ForwardStore& s) {
  s.index = spec(s.index);
  s.value = spec(s.value);
  if (s.dot)
    s.dot = spec(s.dot);
  if (s.chain)
    s.chain = spec(s.chain);
  std::vector<PathCond> path;
  for (const auto& pc : s.path) {
    const FoldedCond f = fold_cond(box, spec(pc.cond));
    if (f.value >= 0) {
      if (f.value != int(pc.positive))
        return false; // fails in every iteration of the box
      continue;       // holds in every one
    }
    path.push_back({f.cond, pc.positive});
  }
  s.path = std::move(path);
  return true;
}

} // namespace

void peel_forward(ForwardPlan& plan) {
  for (auto& nest : plan.nests) {
    const std::vector<Loop>& loops = nest.nest->loops;
    // (the innermost loop runs as three: counted down, it would need them
    // reversed; outer loops only test each iteration)
    if (loops.empty() || nest.peeled() || loops.back().descending)
      continue;
    std::vector<Interval> ins;
    Box box;
    bool any = false;
    for (const Loop& l : loops) {
      ins.push_back(forward_interior(l, nest.stores));
      const auto lo = to_poly(l.lo), hi = to_poly(l.hi);
      if (!lo || !hi)
        continue;
      any = any || !ins.back().lo.empty() || !ins.back().hi.empty();
      Interval& iv = box.dims[l.var];
      iv = ins.back();
      iv.lo.push_back(*lo);
      iv.hi.push_back(*hi);
    }
    if (!any)
      continue;
    std::vector<ForwardStore> inside;
    bool folded = false;
    Specializer spec(box, /*clamps=*/true); // (one for the nest: its stores share their locals)
    for (ForwardStore s : nest.stores) {
      const ForwardStore before = s;
      const bool kept = fold_store(box, spec, s);
      const bool same_path =
          s.path.size() == before.path.size() &&
          std::equal(s.path.begin(), s.path.end(), before.path.begin(),
                     [](const PathCond& a, const PathCond& b) { return a.cond == b.cond; });
      folded = folded || !kept || !same_path || s.index != before.index ||
               s.value != before.value || s.dot != before.dot || s.chain != before.chain;
      if (kept)
        inside.push_back(std::move(s));
    }
    if (!folded || inside.empty())
      continue; // (nothing to gain; no store at all inside: keep one loop)
    nest.interior = std::move(ins);
    nest.interior_stores = std::move(inside);
  }
}

} // namespace dpgen
