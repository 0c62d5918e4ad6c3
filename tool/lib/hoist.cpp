// The pass `hoist`: loop-invariant subexpressions moved out of the planned
// loops (hoist.hpp).
#include "hoist.hpp"

#include "ir_walk.hpp"
#include "print.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <functional>
#include <stdexcept>

namespace dpgen {

namespace {

// The same in every iteration: no loop counter, no array read, and loop-level
// locals only through definitions that are themselves invariant.
bool invariant(const ExprP& e, std::map<const LocalVar*, bool>& memo) {
  if (e->op == Op::LoopVar || e->op == Op::Read)
    return false;
  if (e->op == Op::Local) {
    if (e->local->kernel_level)
      return true;
    auto it = memo.find(e->local.get());
    if (it != memo.end())
      return it->second;
    return memo[e->local.get()] = invariant(e->local->def, memo);
  }
  for (const auto& o : e->ops)
    if (!invariant(o, memo))
      return false;
  return true;
}

} // namespace

bool safe_anywhere(const ExprP& e) {
  return !any_node(e, [](const ExprP& x) {
    switch (x->op) {
    case Op::Div:
    case Op::Rem:
      return !is_real(x->type);
    case Op::Shl:
    case Op::Shr:
      return true;
    case Op::Cast:
      return !is_real(x->type) && is_real(x->ops[0]->type);
    default:
      return false;
    }
  });
}

bool may_be_product(const ExprP& e) {
  return is_real(e->type) && (e->op == Op::Mul || (e->op == Op::Call && e->name == "pow"));
}

namespace {

// Costs an instruction worth saving (a lone cast or sum of parameters does not).
bool worth_hoisting(const ExprP& e) {
  return any_node(e, [](const ExprP& x) {
    return x->op == Op::Div || x->op == Op::Mul || x->op == Op::Call;
  });
}

bool is_leaf(const ExprP& e) {
  switch (e->op) {
  case Op::IntConst:
  case Op::RealConst:
  case Op::Param:
  case Op::LoopVar:
  case Op::Local:
  case Op::Read:
    return true;
  default:
    return false;
  }
}

} // namespace

bool Hoister::hoistable(const ExprP& e, bool summed) const {
  if (!is_real(e->type) || is_leaf(e) || e->op == Op::Neg)
    return false;
  if (summed && may_be_product(e)) // a * b + c: may become one fused multiply-add
    return false;
  std::map<const LocalVar*, bool> memo;
  if (!invariant(e, memo) || !safe_anywhere(e) || !worth_hoisting(e))
    return false;
  return locals_move(e); // its loop-level locals move with it
}

ExprP Hoister::operator()(const ExprP& e, bool summed) {
  if (!e)
    throw std::logic_error("internal error: hoist: a null expression");
  return rewrite(e, summed);
}

PathCond Hoister::operator()(const PathCond& pc) { return {rewrite(pc.cond, false), pc.positive}; }

ExprP Hoister::rewrite(const ExprP& e, bool summed) {
  if (hoistable(e, summed))
    return hoist(e);
  if (e->op == Op::Local) {
    if (e->local->kernel_level)
      return e;
    auto it = locals_.find(e->local.get());
    if (it != locals_.end())
      return it->second.second;
    // An invariant local moves before the loops as it is; any other keeps
    // its place, its definition rewritten (where the local is used is not
    // known here: the definition counts as summed).
    ExprP out = e;
    if (movable(e)) {
      out = move(e);
    } else {
      kept_.insert(e->local->name);
      ExprP def = rewrite(e->local->def, true);
      if (def != e->local->def) {
        auto l = std::make_shared<LocalVar>(*e->local);
        l->def = def;
        out = local_ref(l);
      }
    }
    locals_[e->local.get()] = {e->local, out};
    return out;
  }
  std::vector<bool> sums(e->ops.size(), false);
  switch (e->op) {
  case Op::Add:
  case Op::Sub:
    sums.assign(e->ops.size(), true);
    break;
  case Op::Neg:
    sums[0] = summed;
    break;
  case Op::Select:
    sums[1] = sums[2] = summed;
    break;
  default:
    break;
  }
  size_t i = 0;
  return map_operands(e, [&](const ExprP& o) { return rewrite(o, sums[i++]); });
}

// A loop-level local that moves before the loops: a real (index arithmetic
// stays where the index algebra sees it) whose definition is invariant, safe
// anywhere and worth hoisting (`s = 0.0` stays), not a product (a sum may use
// the local: see hoist.hpp), every local it uses moves too, and no other
// local of its name moved with another definition or stayed in the loops
// (the plan specializes locals per box: loop_plan.cpp's Specializer; a split
// forward's edge keeps `w = i == 0 ? 0.5 / dx : 1.0 / dx` where its interior
// has the invariant `w = 1.0 / dx`). Boxes are visited in print order, edges
// before interiors, so a name an edge keeps is never moved after it. (The
// other order, a name moved and a later box keeping it, still defines it in
// both places: correct values, a -Wshadow warning.)
bool Hoister::movable(const ExprP& e) const {
  const ExprP& def = e->local->def;
  std::map<const LocalVar*, bool> memo;
  if (!is_real(def->type) || !invariant(def, memo) || !safe_anywhere(def) || !worth_hoisting(def) ||
      may_be_product(def) || (def->op == Op::Neg && may_be_product(def->ops[0])))
    return false;
  auto it = moved_.find(e->local->name);
  if ((it != moved_.end() && it->second.first != print(def)) || kept_.count(e->local->name))
    return false;
  return locals_move(def);
}

// Every loop-level local `e` uses (directly, not through definitions) moves.
bool Hoister::locals_move(const ExprP& e) const {
  bool ok = true;
  std::set<const LocalVar*> seen;
  walk(
      e, [&](const ExprP&) { return ok; },
      [&](const ExprP& l) {
        ok = ok && (l->local->kernel_level || movable(l));
        return false;
      },
      seen);
  return ok;
}

ExprP Hoister::move(const ExprP& e) {
  // (met again directly, a local is the moved one: a name kept since then must
  // not make it stay in the loops as well; so in both branches)
  auto it = moved_.find(e->local->name);
  if (it != moved_.end()) {
    locals_[e->local.get()] = {e->local, it->second.second};
    return it->second.second;
  }
  auto l = std::make_shared<LocalVar>(*e->local);
  l->def = with_moved_locals(e->local->def);
  l->kernel_level = true;
  hoisted_.push_back(l);
  ExprP out = local_ref(l);
  moved_[l->name] = {print(e->local->def), out};
  locals_[e->local.get()] = {e->local, out};
  return out;
}

// `e` (invariant, its locals movable) with its loop-level locals replaced by
// the ones moved before the loops.
ExprP Hoister::with_moved_locals(const ExprP& e) {
  if (e->op == Op::Local)
    return e->local->kernel_level ? e : move(e);
  return map_operands(e, [&](const ExprP& o) { return with_moved_locals(o); });
}

ExprP Hoister::hoist(const ExprP& e) {
  ExprP def = with_moved_locals(e);
  std::string text = print(def);
  auto it = by_text_.find(text);
  if (it != by_text_.end())
    return local_ref(it->second);
  auto l = std::make_shared<LocalVar>();
  l->name = name_for(def);
  l->type_name = "auto"; // the type the expression has in place
  l->def = def;
  l->kernel_level = true;
  hoisted_.push_back(l);
  by_text_[text] = l;
  return local_ref(l);
}

// `inv_dx` for 1.0 / dx, else `hoisted<n>`; never a name of the kernel's
// (Kernel::fresh), nor one given out before.
std::string Hoister::name_for(const ExprP& e) {
  std::string base = fmt::format("hoisted{}", names_.size());
  if (e->op == Op::Div && is_const(e->ops[0], 1) &&
      (e->ops[1]->op == Op::Param || e->ops[1]->op == Op::Local) && is_real(e->ops[1]->type))
    base = "inv_" + e->ops[1]->name;
  std::string name = k_.fresh(base);
  while (names_.count(name) || (taken_ && taken_->count(name)))
    name = k_.fresh(name + "_");
  names_.insert(name);
  return name;
}

// ---- the pass: the planned expressions, in the order emit prints them ----------

namespace {

void hoist_term(Hoister& hoist, BoxTerm& t) {
  t.partial = hoist(t.partial);
  t.seed_index = hoist(t.seed_index);
  for (auto& g : t.guards)
    g = hoist(g);
}

// The interior partials that are the same in every iteration, factored out
// of the cell's sum (CellLoop::factored): those of unguarded terms, where no
// bulk block of the group is guarded (a guarded cell may not be written).
void factor_interior(CellLoop& loop, size_t gi) {
  const GatherGroup& g = *loop.groups[gi];
  std::vector<ExprP>& sums = loop.factored[gi];
  for (const auto& b : g.blocks)
    if (b.bulk && !b.guards.empty())
      return;
  for (size_t bi = 0; bi < g.blocks.size(); ++bi)
    if (g.blocks[bi].bulk)
      for (auto& t : loop.interior_terms[gi][bi]) {
        if (!t.guards.empty() || !t.same_everywhere)
          continue;
        // A partial -P shares P's sum, its seed subtracted (divergence2d's
        // `c * (g[k - 1] - g[k + 1])`: one product where there were two). A
        // sum of one sign only gives the same bits as before: -a - b is
        // -(a + b) exactly.
        const bool negated = t.partial->op == Op::Neg;
        const ExprP& base = negated ? t.partial->ops[0] : t.partial;
        const std::string key = print(base);
        auto same =
            std::find_if(sums.begin(), sums.end(), [&](const ExprP& p) { return print(p) == key; });
        t.factor = int(same - sums.begin());
        t.factor_negated = negated;
        if (same == sums.end())
          sums.push_back(base);
      }
}

// emit_gather's order: every block's edge terms; those of an edge row's
// cells in the innermost interior range; the interior's (bulk blocks; none
// for a single cell), whose invariant partials are then factored out.
void hoist_cell_loop(Hoister& hoist, CellLoop& loop) {
  for (auto* terms : {&loop.edge_terms, &loop.row_terms})
    for (auto& per_group : *terms)
      for (auto& per_block : per_group)
        for (auto& t : per_block)
          hoist_term(hoist, t);
  loop.factored.assign(loop.groups.size(), {});
  if (loop.groups.front()->layout.empty() || !loop.any_bulk)
    return;
  for (size_t gi = 0; gi < loop.groups.size(); ++gi) {
    for (size_t bi = 0; bi < loop.groups[gi]->blocks.size(); ++bi)
      if (loop.groups[gi]->blocks[bi].bulk)
        for (auto& t : loop.interior_terms[gi][bi])
          hoist_term(hoist, t);
    factor_interior(loop, gi);
  }
}

// emit_scatter's order: the seed's index, the store's path, then per read its
// conditions, partial and index.
void hoist_scatter(Hoister& hoist, ScatterLoop& u) {
  u.seed_index = hoist(u.seed_index);
  hoist.all(u.path);
  for (auto& r : u.reads) {
    hoist.all(r.conds);
    r.partial = hoist(r.partial);
    r.index = hoist(r.index);
  }
}

} // namespace

// Once per plan: run again, it would hoist from what it made and keep only
// the new definitions.
template <typename Plan> void first_time(Plan& plan) {
  if (plan.invariants_hoisted)
    throw std::logic_error("internal error: hoist: the plan's invariants are hoisted already");
  plan.invariants_hoisted = true;
}

void hoist_invariants(LoopPlan& plan) {
  first_time(plan);
  for (auto& s : plan.stages)
    hoist_invariants(s);
  if (plan.forward.kernel)
    hoist_invariants(plan.forward);
  if (!plan.stages.empty())
    return; // (a staged adjoint's loops are its stages')
  Hoister hoist(*plan.adjoint->kernel);
  for (auto& in : plan.inputs) {
    for (auto& step : in.gathers)
      for (auto& loop : step.loops)
        hoist_cell_loop(hoist, loop);
    for (auto& u : in.scatters)
      hoist_scatter(hoist, u);
  }
  plan.hoisted = hoist.hoisted();
}

// emit_forward_nest's order, per store: index, value, tangent, path (a peeled
// nest: its edge stores, then its interior's). `+=`
// adds the value to the element (summed).
void hoist_invariants(ForwardPlan& plan, const std::set<std::string>* taken) {
  first_time(plan);
  Hoister hoist(*plan.kernel, taken);
  auto stores = [&](std::vector<ForwardStore>& v) {
    for (auto& s : v) {
      const bool summed = s.store->accumulate && s.store->extremum == 0;
      s.index = hoist(s.index);
      s.value = hoist(s.value, summed);
      if (s.dot && !is_zero(s.dot))
        s.dot = hoist(s.dot, summed);
      if (s.chain)
        s.chain = hoist(s.chain);
      hoist.all(s.path);
    }
  };
  for (auto& nest : plan.nests) {
    stores(nest.stores);
    stores(nest.interior_stores); // (a peeled loop prints its interior after its edges)
  }
  plan.hoisted = hoist.hoisted();
}

void emit_hoisted(Code& code, const std::vector<LocalP>& hoisted) {
  if (hoisted.empty())
    return;
  code.line("// loop-invariant, hoisted: computed once here, the same expressions as in the "
            "loops below");
  for (const auto& l : hoisted)
    code.line("const {} {} = {};", l->type_name, l->name, print(l->def));
}

int open_guard(Code& code, const std::vector<PathCond>& conds, std::set<int>& done,
               std::set<std::string>& vars, std::set<int>& inside) {
  inside = done;
  int opened = 0;
  std::vector<PathCond> pending;
  auto open = [&] {
    code.open(fmt::format("if ({})", conjunction(pending)));
    ++opened;
    pending.clear();
  };
  for (const auto& pc : conds) {
    std::map<int, LocalP> cond_locals;
    collect(pc.cond, cond_locals, vars);
    // a local a later condition reads is defined inside the conditions
    // before it, which may be what keeps its reads in bounds (`if (i > 0 &&
    // d > 0)` with d = u[i] - u[i - 1])
    const bool missing = std::any_of(cond_locals.begin(), cond_locals.end(),
                                     [&](const auto& l) { return !inside.count(l.first); });
    if (missing && !pending.empty())
      open();
    define_locals(code, cond_locals, opened ? inside : done);
    if (!opened)
      inside = done;
    pending.push_back(pc);
  }
  if (!pending.empty())
    open();
  return opened;
}

} // namespace dpgen
