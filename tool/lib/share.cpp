// The pass `share`: values the interior terms of a gather loop compute at
// several shifts of the innermost counter, computed once per iteration of a
// strip of cells (share.hpp).
#include "share.hpp"

#include "affine.hpp"
#include "hoist.hpp"
#include "ops.hpp"
#include "print.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <set>
#include <stdexcept>

namespace dpgen {

namespace {

// The most shifts of the innermost counter one buffer spans (hi - lo).
constexpr long long kMaxSpan = 16;
// A value larger than this (its locals expanded) is not shared; its parts may be.
constexpr int kMaxNodes = 200;
// The most buffers one loop's strips hold (each at most 272 doubles on the stack of the
// thread that runs the strip); values met later are computed in place, as before.
constexpr size_t kMaxBuffers = 16;

// A real product as the compiler may see it: hoist.hpp's may_be_product (a * b,
// pow), or what GCC writes as one without -ffast-math: a division by a power of
// two (x / 2.0 is x * 0.5 exactly; x / -4.0, x / h for a constant h, x / 2 too)
// and a sum of an operand with itself (x + x is x * 2.0). Each may be
// contracted into a multiply-add with a sum.
// The constant a divisor is, through locals (kernel-level ones too),
// negations and an integer converted: the compiler sees through them.
std::optional<double> real_constant(const ExprP& e) {
  if (e->op == Op::Local)
    return e->local->def ? real_constant(e->local->def) : std::nullopt;
  if (e->op == Op::RealConst)
    return e->rval;
  if (e->op == Op::Cast && e->ops[0]->op == Op::IntConst)
    return static_cast<double>(e->ops[0]->ival);
  if (e->op == Op::Neg)
    if (auto v = real_constant(e->ops[0]))
      return -*v;
  return std::nullopt;
}

// `a` and `b` are the same expression, through locals (two locals of the same
// definition are one value to the compiler). Past `budget` nodes, every one
// alike so far, they count as the same (so a sum is taken for a product: the
// side that shares less).
bool same_value(const ExprP& a, const ExprP& b, int& budget) {
  if (a == b || (a->op == Op::Local && b->op == Op::Local && a->local == b->local))
    return true;
  if (--budget < 0)
    return true;
  if (a->op == Op::Local && a->local->def)
    return same_value(a->local->def, b, budget);
  if (b->op == Op::Local && b->local->def)
    return same_value(a, b->local->def, budget);
  if (a->op != b->op || a->type != b->type || a->ival != b->ival || a->name != b->name ||
      a->cast_type != b->cast_type || a->shape.levels != b->shape.levels ||
      a->shape.view != b->shape.view || a->ops.size() != b->ops.size() ||
      (a->op == Op::RealConst && a->rval != b->rval))
    return false;
  for (size_t i = 0; i < a->ops.size(); ++i)
    if (!same_value(a->ops[i], b->ops[i], budget))
      return false;
  return true;
}

bool product_like(const ExprP& e) {
  if (!is_real(e->type))
    return false;
  if (may_be_product(e))
    return true;
  if (e->op == Op::Div) {
    const std::optional<double> c = real_constant(e->ops[1]);
    int exp = 0;
    return c && *c != 0.0 && std::fabs(std::frexp(*c, &exp)) == 0.5;
  }
  int budget = 256;
  return e->op == Op::Add && same_value(e->ops[0], e->ops[1], budget);
}

// A real division, or a math function that costs more than a multiplication.
// (Not pow, nor a division by a power of two: products, product_like.)
bool costly(const ExprP& e) {
  static const std::set<std::string> calls = {"sqrt", "cbrt", "exp",  "expm1", "log",   "log1p",
                                              "sin",  "cos",  "tanh", "atan2", "hypot", "erf"};
  return is_real(e->type) && !product_like(e) &&
         (e->op == Op::Div || (e->op == Op::Call && calls.count(e->name)));
}

// At most `budget` nodes, the loop-level locals' definitions expanded.
bool small(const ExprP& e, int& budget) {
  if (--budget < 0)
    return false;
  if (e->op == Op::Local)
    return e->local->kernel_level || small(e->local->def, budget);
  return std::all_of(e->ops.begin(), e->ops.end(),
                     [&](const ExprP& o) { return small(o, budget); });
}

// `e` with every loop-level local replaced by its definition.
ExprP inlined(const ExprP& e) {
  if (e->op == Op::Local)
    return e->local->kernel_level ? e : inlined(e->local->def);
  return map_operands(e, [](const ExprP& o) { return inlined(o); });
}

// A shareable value, as a function of the counters: its key text, and the
// layout counters other than the innermost that it mentions. The key is the
// value with its locals expanded, every read's index written as a polynomial,
// and the innermost counter moved by `move`: `u[i - 1] / dx` is `u[i] / dx`
// with i moved by -1, so both get the key of `u[i] / dx` (move 1 and 0), and
// the first at iteration c + s is the second at c + s - 1 (one buffer).
struct ValueShape {
  std::string text;
  std::set<std::string> outer;
  long long move = 0;
};

// A term's iteration relative to its cell: per layout counter, the constant
// shift (iteration = cell + shift); a counter whose shift is not constant is
// missing.
using Offsets = std::map<std::string, long long>;

class Sharer {
public:
  Sharer(const Kernel& k, CellLoop& loop) : k_(k), loop_(loop) {
    const auto& layout = loop.groups.front()->layout;
    inner_ = layout.back().first;
    for (size_t i = 0; i + 1 < layout.size(); ++i)
      outer_.insert(layout[i].first);
  }

  void run() {
    for_each_term([&](BoxTerm& t, const Offsets& off) {
      std::set<const LocalVar*> seen;
      // (a guarded term: see find(); the guards first, as emit defines their locals)
      for (size_t g = 0; g < t.guards.size(); ++g)
        find(t.guards[g], g > 0, off, seen, false);
      find(t.partial, !t.guards.empty(), off, seen, !t.guards.empty());
    });
    for (const auto& key : order_) {
      const Found& f = found_.at(key);
      if (std::any_of(f.products.begin(), f.products.end(),
                      [&](const std::string& p) { return outside_.count(p); }))
        continue; // (see Found::products)
      // The iterations in runs at most kMaxSpan long, a buffer for each of two or more (one
      // value spelled at shifts far apart, `u[i] / dx` and `u[i + 20] / dx`, gets one each).
      std::vector<std::vector<long long>> runs;
      for (long long at : f.inner)
        if (runs.empty() || at - runs.back().front() > kMaxSpan)
          runs.push_back({at});
        else
          runs.back().push_back(at);
      for (const auto& run : runs) {
        if (run.size() < 2 || loop_.shared.size() == kMaxBuffers)
          continue;
        SharedValue v;
        const std::string base = fmt::format("shared{}", loop_.shared.size());
        v.name = k_.fresh(base);
        v.lo_name = k_.fresh(base + "_lo");
        v.value = f.value;
        v.lo = run.front();
        v.hi = run.back();
        v.outer = f.outer;
        buffers_[key].push_back(loop_.shared.size());
        loop_.shared.push_back(v);
      }
    }
    if (loop_.shared.empty())
      return;
    for_each_term([&](BoxTerm& t, const Offsets& off) {
      std::map<const LocalVar*, ExprP> memo;
      for (size_t g = 0; g < t.guards.size(); ++g)
        t.guards[g] = rewrite(t.guards[g], g > 0, off, memo, false);
      t.partial = rewrite(t.partial, !t.guards.empty(), off, memo, !t.guards.empty());
    });
  }

private:
  struct Found {
    ExprP value;               // the first occurrence's expression, which the buffer holds
    long long move = 0;        // its ValueShape::move
    std::set<long long> inner; // its iterations that the cells' occurrences compute
    std::map<std::string, long long> outer;
    /// The products inside it (product_sign). Where a term computes one of
    /// them outside the occurrences (through a local, or as the same
    /// subexpression, which the compiler merges), the buffer would take away
    /// the uses inside the value, and a sum left as its only use could be
    /// contracted with it into a multiply-add: another rounding. Not shared.
    std::set<std::string> products;
  };

  // Each interior term, with its offsets. (Not those of a group that sums
  // over counters inside the cell: such a loop may run no iteration, and its
  // terms compute nothing. Not a factored term: it prints no partial.)
  template <typename F> void for_each_term(F&& f) {
    for (size_t gi = 0; gi < loop_.groups.size(); ++gi) {
      const GatherGroup& g = *loop_.groups[gi];
      if (!g.reduced.empty())
        continue;
      for (size_t bi = 0; bi < g.blocks.size(); ++bi) {
        const Block& b = g.blocks[bi];
        if (!b.bulk)
          continue;
        Offsets off;
        for (const auto& [v, c] : g.layout) {
          auto it = b.shift.find(v);
          const Poly back = it == b.shift.end() ? Poly() : -it->second;
          if (back.is_constant())
            off[v] = back.constant_term();
        }
        for (auto& t : loop_.interior_terms[gi][bi])
          if (t.factor < 0)
            f(t, off);
      }
    }
  }

  // The value's shape if it may be shared (see share.hpp), else nullopt.
  const std::optional<ValueShape>& shape(const ExprP& e) {
    auto it = shapes_.find(e.get());
    if (it != shapes_.end())
      return it->second.second;
    std::optional<ValueShape> s = make_shape(e);
    return shapes_.emplace(e.get(), std::make_pair(e, std::move(s))).first->second.second;
  }

  std::optional<ValueShape> make_shape(const ExprP& e) const {
    int budget = kMaxNodes;
    if (!costly(e) || !small(e, budget))
      return std::nullopt;
    const ExprP x = inlined(e);
    if (!safe_anywhere(x))
      return std::nullopt;
    ValueShape s;
    bool ok = true, inner = false;
    // `summand`: n's value is (through negations) an operand of a real sum or difference.
    std::function<void(const ExprP&, bool)> check = [&](const ExprP& n, bool summand) {
      // A product may be contracted into a multiply-add with a sum that takes it, but only
      // where every use of it is such a sum (GCC's rule): in the buffer that could differ
      // from in place. One that no sum inside the value takes is contracted in neither.
      if (summand && product_like(n)) {
        ok = false;
        return;
      }
      switch (n->op) {
      case Op::Select:
      case Op::And:
      case Op::Or:
        ok = false;
        return;
      case Op::LoopVar:
        if (n->name == inner_)
          inner = true;
        else if (outer_.count(n->name))
          s.outer.insert(n->name);
        else
          ok = false; // a counter summed over inside the cell
        return;
      case Op::Read: {
        const std::optional<Poly> p = n->shape.view ? std::nullopt : to_poly(n->ops[0]);
        ok = ok && p && affine_in_inner(*p);
        break;
      }
      case Op::Local:
        return; // (kernel-level: the same everywhere)
      default:
        break;
      }
      const bool sum = is_real(n->type) && (n->op == Op::Add || n->op == Op::Sub);
      for (const auto& o : n->ops)
        if (ok)
          check(o, sum || (n->op == Op::Neg && summand));
    };
    check(x, false); // (a division or a call: no product)
    if (!ok || !inner)
      return std::nullopt;
    s.move = move(x);
    int unbounded = 0; // (a key is not cut: small() bounded the value)
    s.text = spelling(x, s.move, unbounded);
    return s;
  }

  // The move that puts the first read that moves with the innermost counter
  // (coefficient +-1) at offset 0 of it (`u[i - 1]`: 1, `u[n - 1 - i]`: -1);
  // 0 where no read moves so, or where the counter occurs outside an index
  // (`i * dx` would be another expression).
  long long move(const ExprP& x) const {
    const Sym c = Sym::counter(inner_);
    bool bare = false;
    std::optional<long long> found;
    std::function<void(const ExprP&)> walk = [&](const ExprP& n) {
      if (n->op == Op::LoopVar && n->name == inner_)
        bare = true;
      if (n->op == Op::Read) {
        const Poly p = *to_poly(n->ops[0]); // (make_shape checked it)
        const Poly a = p.coefficient(c);
        if (!found && p.mentions(c) && a.is_constant() &&
            (a.constant_term() == 1 || a.constant_term() == -1))
          found = -p.without(c).constant_term() * a.constant_term();
        return; // (the counter in an index moves with the read)
      }
      for (const auto& o : n->ops)
        walk(o);
    };
    walk(x);
    return bare || !found ? 0 : *found;
  }

  // `n` as text: every node with what tells it apart. As a key (ValueShape,
  // `move` given), a read's index is the polynomial it is, the innermost counter
  // moved by `move`. As a product's sign (no `move`), a read's index is left out
  // (`q[*] * q[*]`: the same for each copy of it at any iteration, however
  // spelled, and for some others: the test that uses it errs towards not
  // sharing) and locals are seen through; past `budget` nodes the rest is "...",
  // so the size stays bounded where locals nest (x2 = x * x; x4 = x2 * x2; ...).
  std::string spelling(const ExprP& n, std::optional<long long> move, int& budget) const {
    if (!move) {
      if (--budget < 0)
        return "...";
      if (n->op == Op::Local && n->local->def)
        return spelling(n->local->def, move, budget);
    }
    std::string s = fmt::format("({} {}", op_info(n->op).name, type_spelling(n->type));
    switch (n->op) {
    case Op::IntConst:
      s += fmt::format(" {}", n->ival);
      break;
    case Op::RealConst:
      s += fmt::format(" {:a}", n->rval);
      break;
    case Op::Read: {
      s += fmt::format(" {} {} {}", n->name, n->shape.levels, n->shape.view);
      if (!move)
        return s + ")";
      const Poly p = *to_poly(n->ops[0]);
      const Poly moved = p + Poly::constant(*move) * p.coefficient(Sym::counter(inner_));
      return s + fmt::format(" [{}])", moved.str());
    }
    case Op::Cast:
      s += " " + n->cast_type;
      break;
    default: // (a parameter, counter, local or function: its name)
      s += n->name.empty() ? "" : " " + n->name;
      break;
    }
    for (const auto& o : n->ops)
      s += " " + spelling(o, move, budget);
    return s + ")";
  }

  bool affine_in_inner(const Poly& p) const {
    const Sym c = Sym::counter(inner_);
    for (const auto& [m, coef] : p.terms())
      if (std::count(m.begin(), m.end(), c) > 1)
        return false;
    return true;
  }

  // An occurrence of a shareable value at a term: its key, with the other
  // counters' shifts; its innermost shift; and its shape's move.
  struct Occurrence {
    std::string key;
    long long shift, move;
  };

  // `e`'s occurrence at a term with offsets `off`; nullopt when it is not
  // shared there.
  std::optional<Occurrence> occurrence(const ExprP& e, const Offsets& off) {
    const std::optional<ValueShape>& s = shape(e);
    if (!s || !off.count(inner_))
      return std::nullopt;
    std::string key = s->text;
    for (const auto& v : s->outer) {
      auto it = off.find(v);
      if (it == off.end())
        return std::nullopt;
      key += fmt::format(" | {} + {}", v, it->second);
    }
    return Occurrence{key, off.at(inner_), s->move};
  }

  // The iteration of the buffer's expression (Found::value) that computes
  // occurrence `o`'s value, as a shift of the cell: o computes the key's
  // expression at its iteration minus its move, which the buffer's computes
  // at that plus the buffer's move.
  static long long buffer_shift(const Occurrence& o, const Found& f) {
    return o.shift - o.move + f.move;
  }

  // Records the unconditional occurrences of shareable values in `e`. A
  // local's definition counts where the term defines it (emit_terms): before
  // anything else, unconditionally; in a term under run-time guards, the
  // guards' locals so, before the guards, and the others inside the guards
  // (`local_cond`). Of the guards, the first is evaluated unconditionally, the
  // others after `&&`. Products met outside the occurrences go to outside_.
  void find(const ExprP& e, bool cond, const Offsets& off, std::set<const LocalVar*>& seen,
            bool local_cond) {
    if (!cond) {
      if (auto o = occurrence(e, off)) {
        auto [it, fresh] = found_.try_emplace(o->key);
        if (fresh) {
          order_.push_back(o->key);
          it->second.value = e;
          it->second.move = o->move;
          for (const auto& v : shape(e)->outer)
            it->second.outer[v] = off.at(v);
        }
        it->second.inner.insert(buffer_shift(*o, it->second));
        std::set<const LocalVar*> inside;
        note_products(e, it->second.products, inside);
        return;
      }
    }
    if (product_like(e))
      outside_.insert(product_sign(e));
    if (e->op == Op::Local) {
      if (!e->local->kernel_level && seen.insert(e->local.get()).second)
        find(e->local->def, local_cond, off, seen, local_cond);
      return;
    }
    for (size_t i = 0; i < e->ops.size(); ++i)
      find(e->ops[i], cond || conditional(e, i), off, seen, local_cond);
  }

  // Operand i of `e` is evaluated only under a condition (an arm, the right of && or ||).
  static bool conditional(const ExprP& e, size_t i) {
    return i > 0 && (e->op == Op::Select || e->op == Op::And || e->op == Op::Or);
  }

  ExprP rewrite(const ExprP& e, bool cond, const Offsets& off,
                std::map<const LocalVar*, ExprP>& memo, bool local_cond) {
    if (!cond) {
      if (auto o = occurrence(e, off)) {
        // The buffer whose range holds this occurrence's iteration, if any.
        const SharedValue* v = nullptr;
        auto f = found_.find(o->key);
        auto b = buffers_.find(o->key);
        const long long at = f == found_.end() ? 0 : buffer_shift(*o, f->second);
        if (f != found_.end() && b != buffers_.end())
          for (size_t i : b->second)
            if (at >= loop_.shared[i].lo && at <= loop_.shared[i].hi)
              v = &loop_.shared[i];
        if (v) {
          // (the term's counter is at its own shift: the buffer's iteration is o->shift away)
          const long long d = at - o->shift;
          const ExprP it = d < 0 ? binary(Op::Sub, loop_var(inner_), int_const(-d))
                                 : binary(Op::Add, loop_var(inner_), int_const(d));
          return read(v->name, binary(Op::Sub, it, param(v->lo_name, Type::Int)), e->type,
                      SourcePos{});
        }
        // As find, a value not shared is not looked into. (A local inside it that the term
        // also uses elsewhere keeps its definition here and may be rewritten there: the same
        // name for the same value, and the term defines it once.)
        return e;
      }
    }
    if (e->op == Op::Local) {
      if (e->local->kernel_level)
        return e;
      auto it = memo.find(e->local.get());
      if (it != memo.end())
        return it->second;
      ExprP out = e;
      ExprP def = rewrite(e->local->def, local_cond, off, memo, local_cond);
      if (def != e->local->def) {
        auto l = std::make_shared<LocalVar>(*e->local); // (same id and name)
        l->def = def;
        out = local_ref(l);
      }
      return memo[e->local.get()] = out;
    }
    size_t i = 0;
    return map_operands(e, [&](const ExprP& o) {
      const bool c = cond || conditional(e, i++);
      return rewrite(o, c, off, memo, local_cond);
    });
  }

  // A product's spelling with indices left out, at most 64 nodes (spelling).
  std::string product_sign(const ExprP& n) const {
    int budget = 64;
    return spelling(n, std::nullopt, budget);
  }

  // The product_sign of every product in `x`, through its locals (each once).
  void note_products(const ExprP& x, std::set<std::string>& out,
                     std::set<const LocalVar*>& seen) const {
    if (product_like(x))
      out.insert(product_sign(x));
    if (x->op == Op::Local) {
      if (x->local->def && seen.insert(x->local.get()).second)
        note_products(x->local->def, out, seen);
      return;
    }
    for (const auto& o : x->ops)
      note_products(o, out, seen);
  }

  const Kernel& k_;
  CellLoop& loop_;
  std::string inner_;
  std::set<std::string> outer_;
  // Shapes by node (the node kept alive, so its address is not reused).
  std::map<const Expr*, std::pair<ExprP, std::optional<ValueShape>>> shapes_;
  std::map<std::string, Found> found_;
  std::vector<std::string> order_;       // keys in order of first occurrence
  std::map<std::string, std::vector<size_t>> buffers_; // key -> indices in loop_.shared
  std::set<std::string> outside_; // product_sign of each product outside the occurrences
};

} // namespace

void share_shifted_values(LoopPlan& plan) {
  for (auto& s : plan.stages)
    share_shifted_values(s);
  if (!plan.stages.empty())
    return; // (a staged adjoint's loops are its stages')
  for (auto& in : plan.inputs)
    for (auto& step : in.gathers)
      for (auto& loop : step.loops) {
        if (!loop.shared.empty())
          throw std::logic_error("internal error: share: the plan's values are shared already");
        if (loop.any_bulk && !loop.groups.front()->layout.empty())
          Sharer(*plan.adjoint->kernel, loop).run();
      }
}

} // namespace dpgen
