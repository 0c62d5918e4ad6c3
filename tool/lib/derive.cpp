// Derive (phase 3): one differentiation rule per IR node, the maths above each rule.
// Values that are integers, booleans or pass through floor/ceil carry no
// derivative; every other node has an exact rule or is rejected earlier by
// the lowering.
#include "derive.hpp"

#include "ops.hpp"
#include "print.hpp"
#include "prove.hpp"

#include <map>
#include <optional>
#include <stdexcept>

namespace dpgen {

namespace {

class Deriver {
public:
  Deriver(const std::set<const Expr*>& reads, DeriveNames& names) : reads_(reads), names_(names) {}
  // Forward mode: a read of an active array `a[k]` has the derivative
  // `a_dot[k]`, and each local's derivative is a local of its own.
  Deriver(const std::set<std::string>& active, DeriveNames& names, TangentLocals& tangents)
      : reads_(no_reads_), names_(names), active_(&active), tangents_(&tangents) {}

  ExprP d(const ExprP& e) {
    if (!is_real(e->type))
      return zero(e->type); // integers and booleans are not differentiable values
    if (e->op == Op::Local) {
      auto& memo = tangents_ ? tangents_->memo : local_memo_;
      auto it = memo.find(e->local.get());
      if (it != memo.end())
        return it->second;
      const ExprP& def = e->local->def;
      // A call's rule reuses its value (d exp(a) = exp(a)·da): use the local.
      // (The local is evaluated where the kernel defines it, outside the arms
      // it is used in: its derivative is, too.)
      std::vector<PathCond> arms;
      arms.swap(arms_);
      ExprP r = def->op == Op::Call ? call_rule(def, e) : d(def);
      arms.swap(arms_);
      if (!is_zero(r) && tangents_ && r->op != Op::Read && r->op != Op::RealConst)
        r = tangent_local(*e->local, r);
      memo[e->local.get()] = r;
      if (!tangents_)
        local_ds_.emplace_back(r, e->local.get());
      return r;
    }
    switch (e->op) {
    case Op::IntConst:
    case Op::RealConst:
    case Op::Param:
    case Op::LoopVar:
      return zero(e->type);
    case Op::Read:
      if (active_) // forward mode: d a[k] = a_dot[k]
        return active_->count(e->name) ? read(e->name + "_dot", e->ops[0], e->type, e->pos,
                                                    e->shape)
                                       : zero(e->type);
      // d a[k] / d a[k] = 1 for the occurrences we differentiate by
      return reads_.count(e.get()) ? one(e) : zero(e->type);
    case Op::Neg:
      // d(-a) = -da
      return neg(d(e->ops[0]));
    case Op::Add:
      // d(a + b) = da + db
      return add(d(e->ops[0]), d(e->ops[1]));
    case Op::Sub:
      // d(a - b) = da - db
      return add(d(e->ops[0]), neg(d(e->ops[1])));
    case Op::Mul: {
      // d(a*b) = b·da + a·db
      const ExprP &a = e->ops[0], &b = e->ops[1];
      return add(mul(b, d(a)), mul(a, d(b)));
    }
    case Op::Div: {
      // d(a/b) = da/b - a·db/b²; da/b is da·(1/b) when b is the same in every
      // iteration and da is not (1/b is then hoisted: no division per cell, as
      // a hand-written adjoint would have it; at most one rounding more than
      // da/b while 1/b is a normal number: a subnormal b gives an infinite
      // 1/b). An invariant da/b stays as written: it is hoisted whole.
      const ExprP &a = e->ops[0], &b = e->ops[1];
      ExprP da = d(a), db = d(b);
      const bool reciprocal = loop_invariant(b) && !loop_invariant(da);
      ExprP t1 = is_zero(da)  ? da
                 : reciprocal ? mul(da, binary(Op::Div, real_const(1, e->type), b))
                              : binary(Op::Div, da, b);
      ExprP t2 = is_zero(db) ? db : binary(Op::Div, binary(Op::Mul, a, db), binary(Op::Mul, b, b));
      return add(t1, neg(t2));
    }
    case Op::Select: {
      // d(c ? a : b) = c ? da : db   (the condition is piecewise constant)
      arms_.push_back({e->ops[0], true});
      ExprP da = d(e->ops[1]);
      arms_.back().positive = false;
      ExprP db = d(e->ops[2]);
      arms_.pop_back();
      if (is_zero(da) && is_zero(db))
        return zero(e->type);
      return select(e->ops[0], arm(da, e), arm(db, e));
    }
    case Op::Cast:
      // float <-> double: the derivative converts too; int -> real: zero
      return is_real(e->ops[0]->type) ? cast_or_zero(d(e->ops[0]), e->type) : zero(e->type);
    case Op::Call:
      return call_rule(e, std::nullopt);
    default:
      // Cannot occur: an internal error, never a silent zero derivative.
      throw std::logic_error("derive: a local, integer or boolean node reached the rules");
    }
    // Every Op has its case above (no default: -Wswitch names a new one); a
    // value outside the enum would otherwise get a silent zero derivative.
    throw std::logic_error("derive: no rule for a real-valued expression of this kind");
  }

  /// Reverse mode: `r`, a partial d() built, with each local's derivative
  /// that `r` uses more than once named as a local of its own
  /// (`x2_d0 = x1 * x1_d1 + ...`), as the tangent names `x2_dot`. Why: a
  /// derivative is a DAG that shares each local's derivative among its uses
  /// (d(x1 * x1 + x1) uses dx1 three times); printed as a tree, a chain of
  /// such locals grows as 3^depth (14 of them ran out of memory). Evaluating
  /// the named one where the locals are defined is safe: it reads nothing
  /// its local's definition does not, and computes in floating point only.
  ExprP name_shared(const ExprP& r) {
    std::map<const Expr*, int> refs; // operand references, each node's once
    std::set<const Expr*> seen;
    count_refs(r, refs, seen);
    std::map<const Expr*, const LocalVar*> named_as;
    for (const auto& [dl, l] : local_ds_)
      if (refs[dl.get()] >= 2 && !trivial(dl))
        named_as.emplace(dl.get(), l);
    if (named_as.empty())
      return r;
    std::map<const Expr*, ExprP> done;
    return rename(r, named_as, done);
  }

private:
  static inline const std::set<const Expr*> no_reads_{};
  /// The derivatives of locals d() built (reverse mode), in order, with the local of each.
  std::vector<std::pair<ExprP, const LocalVar*>> local_ds_;

  static void count_refs(const ExprP& e, std::map<const Expr*, int>& refs,
                         std::set<const Expr*>& seen) {
    if (!seen.insert(e.get()).second || e->op == Op::Local)
      return; // (a local's definition is the primal's, printed once under its name)
    for (const auto& o : e->ops) {
      ++refs[o.get()];
      count_refs(o, refs, seen);
    }
  }
  // A leaf, a local, a read or the negation of one: printing it twice costs nothing.
  static bool trivial(const ExprP& e) {
    const Expr* x = e->op == Op::Neg ? e->ops[0].get() : e.get();
    return x->ops.empty() || x->op == Op::Local || x->op == Op::Read;
  }
  // `e` with each node in `named_as` replaced by a local defined as it (its
  // operands replaced first, so a local's definition names only earlier ones).
  ExprP rename(const ExprP& e, const std::map<const Expr*, const LocalVar*>& named_as,
               std::map<const Expr*, ExprP>& done) {
    if (auto it = done.find(e.get()); it != done.end())
      return it->second;
    ExprP out = e->op == Op::Local
                    ? e
                    : map_operands(e, [&](const ExprP& o) { return rename(o, named_as, done); });
    if (auto it = named_as.find(e.get()); it != named_as.end()) {
      auto l = std::make_shared<LocalVar>();
      l->name = it->second->name + "_d" + std::to_string(names_.next_partial);
      l->name = free_name(l->name, true);
      l->type_name = type_spelling(e->type);
      l->def = out;
      l->id = 3000000 + names_.next_partial++; // after every other local
      out = local_ref(l);
    }
    return done[e.get()] = out;
  }
  const std::set<const Expr*>& reads_;
  DeriveNames& names_;
  const std::set<std::string>* active_ = nullptr;
  TangentLocals* tangents_ = nullptr;

  // `<local>_dot`, defined after every primal and derivative-rule local.
  ExprP tangent_local(const LocalVar& primal, const ExprP& def) {
    auto l = std::make_shared<LocalVar>();
    l->name = primal.name + "_dot";
    while (tangents_->taken.count(l->name))
      l->name += "_";
    tangents_->taken.insert(l->name);
    l->type_name = type_spelling(def->type);
    l->def = def;
    l->id = 2000000 + int(tangents_->locals.size());
    l->kernel_level = primal.kernel_level;
    tangents_->locals.push_back(l);
    return local_ref(l);
  }
  std::map<const LocalVar*, ExprP> local_memo_;
  /// The arms of conditionals the derivative being built is in.
  std::vector<PathCond> arms_;

  // `base`, or with `_` appended until no kernel name is it; `record`: added
  // to DeriveNames::given. (A call's value needs no record: the adjoint and
  // the tangent name it alike, and no name made up later ends in `_v<n>`.)
  std::string free_name(std::string base, bool record) {
    while (names_.taken && names_.taken->count(base))
      base += "_";
    if (record && names_.given)
      names_.given->insert(base);
    return base;
  }

  static ExprP one(const ExprP& like) { return real_const(1, like->type); }
  // The same value in every iteration of the kernel's loops, and computable
  // before them: scalar parameters, constants and locals defined before the
  // loops, combined by arithmetic, comparisons, selects and math functions;
  // nothing the pass `hoist` would not move (an integer division, a shift, a
  // real converted to an integer: hoist.cpp's safe_anywhere), so 1 / b is
  // then computed once.
  static bool loop_invariant(const ExprP& e) {
    switch (e->op) {
    case Op::LoopVar:
    case Op::Read:
    case Op::Shl:
    case Op::Shr:
      return false;
    case Op::Local:
      return e->local->kernel_level;
    case Op::Div:
    case Op::Rem:
      if (!is_real(e->type))
        return false;
      break;
    case Op::Cast:
      if (!is_real(e->type) && is_real(e->ops[0]->type))
        return false;
      break;
    default:
      break;
    }
    for (const ExprP& o : e->ops)
      if (!loop_invariant(o))
        return false;
    return true;
  }
  // A derivative as an arm of conditional `like`: an exact zero in its type.
  static ExprP arm(const ExprP& d, const ExprP& like) { return is_zero(d) ? zero(like->type) : d; }

  // The rules' arithmetic on derivatives, folding the exact zero (zero(),
  // ir.hpp): 0 + b = b, a + 0 = a, -0 = 0, 0·b = a·0 = 0, (T)0 = 0.
  static ExprP add(ExprP a, ExprP b) {
    if (is_zero(a))
      return b;
    if (is_zero(b))
      return a;
    return binary(Op::Add, a, b);
  }
  static ExprP neg(ExprP a) { return is_zero(a) ? a : unary(Op::Neg, a); }
  static ExprP mul(ExprP a, ExprP b) {
    if (is_zero(a))
      return a;
    if (is_zero(b))
      return b;
    return binary(Op::Mul, a, b);
  }
  static ExprP cast_or_zero(ExprP a, Type t) { return is_zero(a) ? zero(t) : cast(a, t); }

  // The value of call `e` for rules that reuse it: `self` when the call is a
  // local's definition, else a local of its own, so it is evaluated once. The
  // same call node always gets the same local, numbered in the order the
  // kernel's derivatives first need them: names depend on the kernel only.
  // A call in an arm of a conditional (`i + 1 < n ? exp(a[i + 1]) : 0.0`)
  // gets a local evaluated only there, `i + 1 < n ? exp(a[i + 1]) : 0`: the
  // local is defined before the expression that uses it, and the call may
  // read outside the arrays where the arm does not run.
  ExprP named(const ExprP& e, const std::optional<ExprP>& self) {
    if (self)
      return *self;
    const ExprP cond = path_condition(arms_);
    const auto key = std::make_pair(e.get(), cond ? print(cond) : std::string());
    auto it = names_.calls.find(key);
    if (it != names_.calls.end())
      return local_ref(it->second);
    auto l = std::make_shared<LocalVar>();
    l->name = free_name(e->name + "_v" + std::to_string(names_.next), false);
    l->type_name = type_spelling(e->type);
    l->def = cond ? select(cond, e, zero(e->type)) : e;
    l->id = 1000000 + names_.next++; // after every user local
    names_.calls[key] = l;
    return local_ref(l);
  }

  // d f(a_1..a_n) = sum_i df/da_i · da_i, each term from the function's row
  // of the table (ops.hpp); an argument without a derivative adds nothing.
  ExprP call_rule(const ExprP& e, const std::optional<ExprP>& self) {
    const MathFn& f = math_function(e->name);
    if (f.piecewise_constant)
      return zero(e->type); // zero almost everywhere
    std::vector<ExprP> ds;
    for (const auto& a : e->ops)
      ds.push_back(d(a));
    bool none = true;
    for (const auto& di : ds)
      none = none && is_zero(di);
    if (none)
      return zero(e->type);
    CallRule r{e, ds, [&] { return named(e, self); }};
    if (f.whole)
      return f.whole(r);
    if (f.partials.size() != ds.size())
      throw std::logic_error("derive: '" + f.name + "' has " + std::to_string(f.partials.size()) +
                             " partial rule(s) for " + std::to_string(ds.size()) + " argument(s)");
    ExprP sum = zero(e->type);
    for (size_t i = 0; i < ds.size(); ++i)
      if (!is_zero(ds[i]))
        sum = add(sum, f.partials[i](r, ds[i]));
    return sum;
  }
};

bool has(const std::vector<PathCond>& conds, const PathCond& pc) {
  return std::any_of(conds.begin(), conds.end(), [&](const PathCond& q) {
    return q.cond == pc.cond && q.positive == pc.positive;
  });
}

// What a condition implies, split at its conjunctions (`a && b` holds: a and
// b; `a || b` fails: a and b fail) and negations.
void add_atoms(const ExprP& c, bool positive, std::vector<PathCond>& out) {
  if (c->op == Op::Not)
    return add_atoms(c->ops[0], !positive, out);
  if (c->op == (positive ? Op::And : Op::Or)) {
    add_atoms(c->ops[0], positive, out);
    add_atoms(c->ops[1], positive, out);
    return;
  }
  if (!has(out, {c, positive}))
    out.push_back({c, positive});
}

std::vector<PathCond> atoms_of(const std::vector<PathCond>& conds) {
  std::vector<PathCond> out;
  for (const auto& pc : conds)
    add_atoms(pc.cond, pc.positive, out);
  return out;
}

void collect_reads(const ExprP& e, std::vector<PathCond>& conds, std::vector<ReadSite>& out,
                   std::set<const Expr*>& seen, std::set<const LocalVar*>& seen_locals) {
  if (e->op == Op::Local) {
    if (seen_locals.insert(e->local.get()).second) {
      std::vector<PathCond> none;
      collect_reads(e->local->def, none, out, seen, seen_locals);
    }
    return;
  }
  if (e->op == Op::Read) {
    if (seen.insert(e.get()).second) {
      out.push_back({e.get(), conds});
    } else {
      // Read again under other conditions (one node in both arms of a
      // select, or in a condition and in a value): it happens where any
      // occurrence's conditions hold; keep the conditions all occurrences
      // share, wherever they stand in each list (`c ? x : 0` with x = `i == 0
      // ? 0 : a[i - 1]` reads a[i - 1] under `i != 0` both in c and in the arm).
      for (auto& site : out)
        if (site.read == e.get()) {
          // (also the conjuncts both imply, where the lists differ: `c1 && c2
          // ? x : (c1 ? y : 0)` with a[i - 1] in x and in y reads it under c1)
          const std::vector<PathCond> before = atoms_of(site.conds), here = atoms_of(conds);
          site.conds.erase(std::remove_if(site.conds.begin(), site.conds.end(),
                                          [&](const PathCond& pc) { return !has(conds, pc); }),
                           site.conds.end());
          const std::vector<PathCond> kept = atoms_of(site.conds);
          for (const PathCond& a : before)
            if (has(here, a) && !has(kept, a) && !has(site.conds, a))
              site.conds.push_back(a);
        }
    }
  }
  if (e->op == Op::Select) {
    collect_reads(e->ops[0], conds, out, seen, seen_locals);
    for (bool arm : {true, false}) {
      conds.push_back({e->ops[0], arm});
      collect_reads(e->ops[arm ? 1 : 2], conds, out, seen, seen_locals);
      conds.pop_back();
    }
    return;
  }
  for (const auto& o : e->ops)
    collect_reads(o, conds, out, seen, seen_locals);
}

} // namespace

ExprP derivative(const ExprP& value, const std::set<const Expr*>& reads, DeriveNames& names) {
  Deriver d(reads, names);
  return d.name_shared(d.d(value));
}

const ExprP& Partials::of(const Store& s, const std::set<const Expr*>& reads) {
  auto [it, added] = table_.try_emplace({&s, reads});
  if (added)
    it->second = derivative(s.value, reads, names_);
  return it->second;
}

Partials derive(const Kernel& k, std::set<std::string>* names) {
  Partials partials(&k.names, names);
  for (const auto& param : k.params) {
    if (param.kind != ParamKind::In)
      continue;
    for (const auto& nest : k.nests)
      for (const auto& store : nest.stores) {
        std::vector<PathCond> guards;
        if (store_domain(nest, store, guards).empty())
          continue; // never executes
        for (const auto& site : reads_in(store.value))
          if (site.read->name == param.name)
            partials.of(store, {site.read});
      }
  }
  return partials;
}

ExprP tangent(const ExprP& value, const std::set<std::string>& active, DeriveNames& names,
              TangentLocals& tangents) {
  return Deriver(active, names, tangents).d(value);
}

std::vector<ReadSite> reads_in(const ExprP& e) {
  std::vector<ReadSite> out;
  std::vector<PathCond> conds;
  std::set<const Expr*> seen;
  std::set<const LocalVar*> seen_locals;
  collect_reads(e, conds, out, seen, seen_locals);
  return out;
}

} // namespace dpgen
