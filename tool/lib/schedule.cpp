// Schedule (phase 4): group every read of a DPGEN_IN array into gather blocks or
// scatter units (see schedule.hpp for the worked example).
#include "schedule.hpp"

#include "ir_walk.hpp"

#include "derive.hpp"
#include "print.hpp"
#include "prove.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <memory>
#include <tuple>

namespace dpgen {

namespace {

// A domain as a value compared by its fields: per box, per counter, the
// bound sets.
using DomainKey =
    std::vector<std::map<std::string, std::pair<std::vector<Poly>, std::vector<Poly>>>>;

DomainKey domain_key(const Domain& d) {
  DomainKey key;
  for (const auto& b : d) {
    key.emplace_back();
    for (const auto& [v, iv] : b.dims)
      key.back()[v] = {iv.lo, iv.hi};
  }
  return key;
}

// The layout decomposition of one affine index: coefficient per counter,
// shift per counter, base. nullopt if the index is not affine in the counters.
struct Decomposed {
  std::vector<std::pair<std::string, Poly>> layout;
  std::map<std::string, Poly> shift;
  Poly base;
};

std::optional<Decomposed> decompose(const Poly& index, const Nest& nest) {
  Decomposed out;
  Poly rest = index;
  for (const auto& l : nest.loops) {
    Poly c = index.coefficient(Sym::counter(l.var));
    if (c.mentions_any_counter())
      return std::nullopt; // a product of counters: not affine
    if (c == Poly())
      continue;
    out.layout.push_back({l.var, c});
    rest = rest - c * Poly::counter(l.var);
  }
  if (rest.mentions_any_counter())
    return std::nullopt;
  // Shifts: the largest coefficient first takes the multiples of its leading
  // monomial (`+nx` with layout j*nx + i is j+1); a unit coefficient last
  // takes what is left (`+1` is i+1).
  std::vector<size_t> order(out.layout.size());
  for (size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return out.layout[a].second.degree() > out.layout[b].second.degree();
  });
  // Row-pointer symbols (ir.hpp): a term with one belongs to the row (or
  // plane) dimension, never to a unit-coefficient column.
  auto is_row_symbol = [](const Sym& s) {
    return !s.is_counter() && level_of_symbol(s.name) > 0;
  };
  auto row_symbol_of = [&](const Poly& p) -> std::optional<Sym> {
    for (const auto& [m, coef] : p.terms())
      for (const auto& s : m)
        if (is_row_symbol(s))
          return s;
    return std::nullopt;
  };
  for (size_t idx : order) {
    const auto& [var, c] = out.layout[idx];
    Poly delta;
    std::optional<Sym> row = row_symbol_of(c);
    if (row && c.terms().size() == 1 && c.terms().begin()->first.size() == 1) {
      // c = ±R: the row shift is every multiple of R (`u[ny - 1 - j][i]`:
      // rest R*ny - R, shift -ny + 1).
      long long cc = c.terms().begin()->second;
      Poly multiples = rest.coefficient(*row);
      bool divisible = true;
      for (const auto& [m, coef] : multiples.terms())
        divisible = divisible && coef % cc == 0 && (m.empty() || !is_row_symbol(m[0]));
      if (divisible)
        for (const auto& [m, coef] : multiples.terms())
          delta = delta + Poly::term(coef / cc, m);
    } else if (c.is_constant()) {
      long long cc = c.constant_term();
      bool divisible = true;
      for (const auto& [m, coef] : rest.terms())
        divisible = divisible && coef % cc == 0;
      if (divisible) {
        for (const auto& [m, coef] : rest.terms()) {
          Poly t = Poly::term(coef / cc, m);
          if (!row_symbol_of(t))
            delta = delta + t;
        }
      }
    } else {
      // leading monomial of c (highest degree, then first in order)
      const Poly::Monomial* lead = nullptr;
      long long lead_coef = 0;
      for (const auto& [m, coef] : c.terms())
        if (!lead || m.size() > lead->size()) {
          lead = &m;
          lead_coef = coef;
        }
      auto it = rest.terms().find(*lead);
      if (it != rest.terms().end() && it->second % lead_coef == 0)
        delta = Poly::constant(it->second / lead_coef);
    }
    if (!(delta == Poly())) {
      out.shift[var] = delta;
      rest = rest - c * delta;
    }
  }
  out.base = rest;
  return out;
}

// Reads that share a gather group: the same input, loop nest (its index in
// the kernel), layout and base.
struct GroupKey {
  std::string array;
  size_t nest;
  std::vector<std::pair<std::string, Poly>> layout;
  Poly base;
  bool operator<(const GroupKey& o) const {
    return std::tie(array, nest, layout, base) < std::tie(o.array, o.nest, o.layout, o.base);
  }
};

// Reads that share a block of a group: the same store (its index in the
// nest), shift, iteration domain and run-time guards (printed conditions and
// their signs).
struct BlockKey {
  size_t group;
  size_t store;
  std::map<std::string, Poly> shift;
  DomainKey domain;
  std::vector<std::pair<bool, std::string>> guards;
  bool operator<(const BlockKey& o) const {
    return std::tie(group, store, shift, domain, guards) <
           std::tie(o.group, o.store, o.shift, o.domain, o.guards);
  }
};

// A block is bulk when its domain is one box that is not provably narrow
// (a constant number of cells) in any layout counter.
bool is_bulk(const Block& b, const GatherGroup& g) {
  if (b.domain.size() != 1)
    return false;
  const Box& box = b.domain.front();
  for (const auto& [v, c] : g.layout) {
    auto it = box.dims.find(v);
    if (it == box.dims.end())
      return false;
    for (const auto& lo : it->second.lo)
      for (const auto& hi : it->second.hi)
        if ((hi - lo).is_constant())
          return false;
  }
  return true;
}

// The index reads data (an array, or a real value converted to int).
// The value depends on array elements or real numbers that vary within the
// kernel (a kernel-level local such as `int x_min = *xmin;` is one value for
// the call, like a parameter).
bool data_dependent(const ExprP& e) {
  bool found = false;
  std::set<const LocalVar*> seen;
  walk(
      e,
      [&](const ExprP& x) {
        found = found || x->op == Op::Read || (x->op == Op::Cast && is_real(x->ops[0]->type));
        return !found;
      },
      [](const ExprP& l) { return !l->local->kernel_level; }, seen);
  return found;
}

bool uses_rem(const ExprP& e) {
  return any_node(e, [](const ExprP& x) { return x->op == Op::Rem; });
}

std::string describe_read(const Expr* r) {
  if (!r->source.empty())
    return r->source;
  return fmt::format("{}[{}]", r->name, print(r->ops[0]));
}

bool reads_array(const ExprP& e, const std::string& array, std::set<const LocalVar*>& seen) {
  return any_node(
      e, [&](const ExprP& x) { return x->op == Op::Read && x->name == array; }, seen);
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

// The gather groups and scatter units of `k`'s reads.
AdjointPlan schedule_reads(const Kernel& k, Partials& partials) {
  AdjointPlan plan;
  plan.kernel = &k;
  std::map<GroupKey, size_t> group_index;
  std::map<BlockKey, size_t> block_index;
  // The store and reads of each block (group, block index); its term and the
  // term's partial are made once every read is in.
  std::map<std::pair<size_t, size_t>, std::pair<const Store*, std::set<const Expr*>>> merged;

  for (const auto& param : k.params) {
    if (param.kind != ParamKind::In)
      continue;
    for (const auto& nest : k.nests) {
      for (const auto& store : nest.stores) {
        std::vector<PathCond> guards;
        Domain sdom = store_domain(nest, store, guards);
        if (sdom.empty())
          continue; // never executes
        ScatterUnit scatter{param.name, &nest, &store, {}};
        for (const auto& site : reads_in(store.value)) {
          const Expr* r = site.read;
          if (r->name != param.name)
            continue;
          const ExprP& partial = partials.of(store, {r});
          if (is_zero(partial))
            continue; // read only through a condition or an index
          auto pieces = index_pieces(r->ops[0]);
          std::vector<std::pair<IndexPiece, Decomposed>> affine;
          bool invertible = pieces.has_value();
          if (pieces)
            for (const auto& piece : *pieces) {
              auto dec = decompose(piece.value, nest);
              if (!dec) {
                invertible = false;
                break;
              }
              affine.push_back({piece, *dec});
            }
          if (!invertible) {
            scatter.reads.push_back({r, partial, site.conds});
            bool dependent = data_dependent(r->ops[0]);
            bool has_rem = uses_rem(r->ops[0]) && !dependent;
            plan.remarks.push_back(
                {r->pos, fmt::format("read '{}' in kernel '{}' has an index that {}: its "
                                     "adjoint is computed in scatter form, serially{}",
                                     describe_read(r), k.name,
                                     dependent ? "depends on array values (data-dependent)"
                                               : "dpgen cannot invert (not affine in the loop "
                                                 "counters, or piecewise on a condition it "
                                                 "cannot bound)",
                                     has_rem ? " (for the gather form, write a periodic wrap "
                                               "as a conditional index: i == n - 1 ? 0 : i + 1)"
                                             : "")});
            continue;
          }
          // Conditions of the arms the read sits in: index conditions narrow
          // its domain (so no cell outside what the source reads appears),
          // others become guards.
          Domain rdom = sdom;
          std::vector<PathCond> rguards = guards;
          std::vector<std::pair<bool, std::string>> guard_key;
          for (const auto& pc : site.conds) {
            if (auto cd = condition_domain(pc.cond)) {
              rdom = pc.positive ? intersect(rdom, *cd) : subtract(rdom, *cd);
            } else {
              rguards.push_back(pc);
              guard_key.push_back({pc.positive, print(pc.cond)});
            }
          }
          for (const auto& [piece, dec] : affine) {
            Domain bdom = intersect(rdom, piece.where);
            if (bdom.empty())
              continue;
            GroupKey gkey{param.name, size_t(&nest - k.nests.data()), dec.layout, dec.base};
            auto git = group_index.find(gkey);
            if (git == group_index.end()) {
              GatherGroup g;
              g.array = param.name;
              g.nest = &nest;
              g.layout = dec.layout;
              g.base = dec.base;
              for (const auto& l : nest.loops) {
                bool in_layout = false;
                for (const auto& [v, c] : dec.layout)
                  in_layout = in_layout || v == l.var;
                if (!in_layout)
                  g.reduced.push_back(l.var);
              }
              plan.gathers.push_back(g);
              git = group_index.emplace(gkey, plan.gathers.size() - 1).first;
            }
            GatherGroup& g = plan.gathers[git->second];
            BlockKey bkey{git->second, size_t(&store - nest.stores.data()), dec.shift,
                          domain_key(bdom), guard_key};
            auto bit = block_index.find(bkey);
            if (bit == block_index.end()) {
              Block b;
              b.shift = dec.shift;
              b.domain = bdom;
              b.guards = rguards;
              b.comment = describe_read(r);
              g.blocks.push_back(b);
              bit = block_index.emplace(bkey, g.blocks.size() - 1).first;
            } else if (g.blocks[bit->second].comment.find(describe_read(r)) == std::string::npos) {
              g.blocks[bit->second].comment += ", " + describe_read(r);
            }
            auto& block_reads = merged[{git->second, bit->second}];
            block_reads.first = &store;
            block_reads.second.insert(r);
          }
        }
        if (!scatter.reads.empty())
          plan.scatters.push_back(scatter);
      }
    }
  }
  // Partials of the merged reads of each block, and the bulk classification.
  for (size_t gi = 0; gi < plan.gathers.size(); ++gi) {
    GatherGroup& g = plan.gathers[gi];
    for (size_t bi = 0; bi < g.blocks.size(); ++bi) {
      Block& b = g.blocks[bi];
      const auto& [store, reads] = merged.at({gi, bi});
      b.terms.push_back({store, reads, partials.of(*store, reads)});
      b.bulk = is_bulk(b, g);
    }
    // A merged partial that vanishes: emit never sees a zero term.
    g.blocks.erase(std::remove_if(g.blocks.begin(), g.blocks.end(),
                                  [](const Block& b) { return is_zero(b.terms.front().partial); }),
                   g.blocks.end());
  }
  plan.gathers.erase(std::remove_if(plan.gathers.begin(), plan.gathers.end(),
                                    [](const GatherGroup& g) { return g.blocks.empty(); }),
                     plan.gathers.end());
  return plan;
}

} // namespace

AdjointPlan schedule(const Kernel& k, Partials& partials) {
  AdjointPlan plan = schedule_reads(k, partials);
  if (!k.intermediates.empty())
    for (size_t j = 0; j < k.nests.size(); ++j) {
      auto s = std::make_shared<Kernel>(k);
      s->name = fmt::format("{}_nest{}", k.name, j + 1);
      s->nests = {k.nests[j]};
      s->size_checks.clear();
      // The accumulators' hidden arrays are the stages' parameters like any
      // work array (the driver passes its buffers).
      s->params.insert(s->params.end(), s->hidden.begin(), s->hidden.end());
      s->hidden.clear();
      for (auto& p : s->params)
        if (k.intermediates.count(p.name)) {
          p.kind = nest_reads(k.nests[j], p.name) ? ParamKind::In : ParamKind::Out;
          p.view_buffered = p.view; // the driver's buffers, read and written as the view is
        }
      Partials stage_partials = derive(*s, &s->names);
      auto stage_plan = std::make_shared<AdjointPlan>(schedule_reads(*s, stage_partials));
      plan.stages.push_back({s, stage_plan});
    }
  return plan;
}

} // namespace dpgen
