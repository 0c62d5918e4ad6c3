// Prove: see prove.hpp.
#include "prove.hpp"

#include "ops.hpp"

#include <algorithm>
#include <functional>
#include <map>
#include <numeric>
#include <set>

namespace dpgen {

namespace {

// a - b as a polynomial, if both sides are integer polynomials.
std::optional<Poly> difference(const ExprP& a, const ExprP& b) {
  auto pa = to_poly(a), pb = to_poly(b);
  if (!pa || !pb)
    return std::nullopt;
  return *pa - *pb;
}

// Facts for `c` (positive) or `!c`. True when the facts say exactly what
// the condition says (a conjunction of comparisons), not just part of it.
bool facts_of(const ExprP& c, bool positive, Facts& out, bool counters = false) {
  if (c->op == Op::Not)
    return facts_of(c->ops[0], !positive, out, counters);
  if ((c->op == Op::And && positive) || (c->op == Op::Or && !positive)) {
    bool a = facts_of(c->ops[0], positive, out, counters);
    bool b = facts_of(c->ops[1], positive, out, counters);
    return a && b;
  }
  Op op = c->op;
  if (!positive) { // !(a < b) is a >= b, ...
    if (!op_info(op).comparison)
      return false;
    op = op_info(op).negated;
  }
  if (op != Op::Lt && op != Op::Le && op != Op::Gt && op != Op::Ge && op != Op::Eq)
    return false;
  if (c->ops.size() != 2 || c->ops[0]->type != Type::Int || c->ops[1]->type != Type::Int)
    return false;
  auto d = difference(c->ops[1], c->ops[0]); // b - a
  if (!d || (!counters && d->mentions_any_counter()))
    return false;
  Poly one = Poly::constant(1);
  switch (op) {
  case Op::Lt: out.push_back(*d - one); break;  // a < b: b - a - 1 >= 0
  case Op::Le: out.push_back(*d); break;        // a <= b: b - a >= 0
  case Op::Gt: out.push_back(-*d - one); break; // a > b: a - b - 1 >= 0
  case Op::Ge: out.push_back(-*d); break;       // a >= b: a - b >= 0
  case Op::Eq:
    out.push_back(*d);
    out.push_back(-*d);
    break;
  default:
    break;
  }
  return true;
}

// A linear constraint sum(coef[v] * v) + c >= 0 over unknowns numbered v.
struct Row {
  std::map<int, long long> coef;
  long long c = 0;
  bool operator<(const Row& o) const { return std::tie(coef, c) < std::tie(o.coef, o.c); }
};

void normalize(Row& r) {
  long long g = 0;
  for (const auto& [v, a] : r.coef)
    g = std::gcd(g, a < 0 ? -a : a);
  if (g > 1) {
    for (auto& [v, a] : r.coef)
      a /= g;
    // floor(c / g): over the integers sum(a v) >= -c/g rounds up
    r.c = r.c >= 0 ? r.c / g : -((-r.c + g - 1) / g);
  }
}

constexpr long long kLimit = 1LL << 40;
constexpr size_t kMaxRows = 600;

} // namespace

void add_facts(const PathCond& pc, Facts& out) { facts_of(pc.cond, pc.positive, out); }

void add_facts_with_counters(const PathCond& pc, Facts& out) {
  facts_of(pc.cond, pc.positive, out, true);
}

void add_counter_range(const Loop& l, Facts& out) {
  auto lo = to_poly(l.lo), hi = to_poly(l.hi);
  Poly v = Poly::counter(l.var);
  if (lo)
    out.push_back(v - *lo);
  if (hi)
    out.push_back(*hi - Poly::constant(1) - v);
}

bool implied(const PathCond& pc, const Facts& facts) {
  Facts f;
  if (!facts_of(pc.cond, pc.positive, f) || f.empty())
    return false;
  for (const auto& p : f)
    if (!prove_nonneg(p, facts))
      return false;
  return true;
}

void add_nonempty(const Loop& l, Facts& out) {
  auto lo = to_poly(l.lo), hi = to_poly(l.hi);
  if (lo && hi)
    out.push_back(*hi - *lo - Poly::constant(1));
}

bool prove_nonneg(const Poly& goal, const Facts& facts) {
  if (goal.is_constant())
    return goal.constant_term() >= 0;
  // Unknowns: the non-constant monomials.
  std::map<Poly::Monomial, int> unknown;
  auto row_of = [&](const Poly& p) {
    Row r;
    for (const auto& [m, a] : p.terms()) {
      if (m.empty()) {
        r.c += a;
        continue;
      }
      auto it = unknown.emplace(m, int(unknown.size())).first;
      r.coef[it->second] += a;
    }
    return r;
  };
  Facts all = facts;
  // Lower bounds of single symbols (s - b >= 0) give s*t >= ... for products:
  // (s - b_s)(t - b_t) >= 0 when both bounds are known.
  std::map<Sym, long long> lower;
  for (const auto& f : facts) {
    if (f.terms().size() > 2 || f.degree() != 1)
      continue;
    Sym sym;
    long long a = 0, c = 0;
    for (const auto& [m, k] : f.terms())
      if (m.empty())
        c = k;
      else
        sym = m[0], a = k;
    if (a == 1) {
      auto it = lower.find(sym);
      if (it == lower.end() || -c > it->second)
        lower[sym] = -c;
    }
  }
  // Likewise for products of three or four symbols (a plane offset
  // (nz + 1) * (ny + 1) * (nx + 1)): the product of the factors s - b_s, each
  // nonnegative, is; and for the smaller products inside it, which its
  // expansion mentions.
  std::set<Poly::Monomial> products;
  auto add_products = [&](const Poly::Monomial& m) {
    if (m.size() < 2 || m.size() > 4)
      return;
    // every sub-multiset of two or more factors (at most 2^4 subsets)
    for (unsigned mask = 0; mask < (1u << m.size()); ++mask) {
      Poly::Monomial sub;
      for (size_t i = 0; i < m.size(); ++i)
        if (mask & (1u << i))
          sub.push_back(m[i]);
      if (sub.size() >= 2)
        products.insert(sub);
    }
  };
  for (const auto& [m, k] : goal.terms())
    add_products(m);
  for (const auto& f : facts)
    for (const auto& [m, k] : f.terms())
      add_products(m);
  for (const auto& m : products) {
    Poly product = Poly::constant(1);
    bool known = true;
    for (const Sym& s : m) {
      auto a = lower.find(s);
      known = known && a != lower.end() && a->second >= 0;
      if (!known)
        break;
      product = product * (Poly::of(s) - Poly::constant(a->second));
    }
    if (known)
      all.push_back(product);
  }
  std::set<Row> rows;
  for (const auto& f : all) {
    Row r = row_of(f);
    normalize(r);
    rows.insert(r);
  }
  Row neg = row_of(-goal - Poly::constant(1)); // goal <= -1
  normalize(neg);
  rows.insert(neg);
  // Fourier-Motzkin: eliminate each unknown; the system is infeasible when a
  // constant row is negative.
  for (int v = 0; v < int(unknown.size()); ++v) {
    std::vector<Row> pos, negs;
    std::set<Row> next;
    for (const auto& r : rows) {
      auto it = r.coef.find(v);
      if (it == r.coef.end() || it->second == 0)
        next.insert(r);
      else
        (it->second > 0 ? pos : negs).push_back(r);
    }
    for (const auto& p : pos)
      for (const auto& n : negs) {
        long long ap = p.coef.at(v), an = -n.coef.at(v);
        Row r;
        bool overflow = false;
        auto scaled = [&](long long a, long long b) {
          __int128 x = static_cast<__int128>(a) * b;
          if (x > kLimit || x < -kLimit)
            overflow = true;
          return static_cast<long long>(x);
        };
        for (const auto& [u, a] : p.coef)
          if (u != v)
            r.coef[u] += scaled(a, an);
        for (const auto& [u, a] : n.coef)
          if (u != v)
            r.coef[u] += scaled(a, ap);
        r.c = scaled(p.c, an) + scaled(n.c, ap);
        if (overflow)
          return false;
        for (auto it = r.coef.begin(); it != r.coef.end();)
          it = it->second == 0 ? r.coef.erase(it) : std::next(it);
        normalize(r);
        next.insert(r);
      }
    if (next.size() > kMaxRows)
      return false;
    rows = std::move(next);
  }
  for (const auto& r : rows)
    if (r.coef.empty() && r.c < 0)
      return true;
  return false;
}

namespace {

// The largest power of two dividing every coefficient of `p` (a constant
// 2^c), or the symbol of `local` when every term of `p` holds it: a modulus
// M with p = M * q, so p has no bit below M set. nullopt otherwise.
std::optional<Poly> power_of_two_factor(const Poly& p, const std::vector<LocalP>& pow2_locals) {
  if (p.terms().empty())
    return std::nullopt;
  for (const auto& l : pow2_locals) {
    Sym s = Sym::size(l->name);
    bool all = true;
    for (const auto& [m, k] : p.terms())
      all = all && std::find(m.begin(), m.end(), s) != m.end();
    if (all)
      return Poly::of(s);
  }
  long long g = 0;
  for (const auto& [m, k] : p.terms())
    g = std::gcd(g, k < 0 ? -k : k);
  if (g <= 1)
    return std::nullopt;
  return Poly::constant(g & -g); // (the lowest set bit of g)
}

} // namespace

ExprP bits_as_sum(const ExprP& index, const std::vector<Loop>& loops,
                  const std::vector<PathCond>& path, const std::vector<LocalP>& locals) {
  // the kernel-level locals `1 << s` (an integer power of two for any valid s),
  // also as made after a guard of the kernel, `c ? 1 << s : 0` (lower_stmt.cpp:
  // make_local), where the store's path holds c: c is the conjunction of the
  // path's first conditions, as the guard made it
  auto path_holds = [&](const ExprP& c) {
    for (size_t k = 1; k <= path.size(); ++k)
      if (same(path_condition(path, 0, k), c))
        return true;
    return false;
  };
  std::vector<std::pair<LocalP, ExprP>> pow2; // (local, its 1 << s)
  for (const auto& l : locals) {
    if (!l->kernel_level || !l->def)
      continue;
    ExprP v = l->def;
    if (v->op == Op::Select && v->ops[2]->op == Op::IntConst && v->ops[2]->ival == 0 &&
        path_holds(v->ops[0]))
      v = v->ops[1];
    if (v->op == Op::Shl && v->type == Type::Int && v->ops[0]->op == Op::IntConst &&
        v->ops[0]->ival == 1)
      pow2.emplace_back(l, v);
  }
  std::vector<LocalP> pow2_locals;
  for (const auto& [l, v] : pow2)
    pow2_locals.push_back(l);
  Facts facts; // where the store runs: its loops' ranges, its path
  for (const auto& l : loops) {
    add_nonempty(l, facts);
    add_counter_range(l, facts);
  }
  for (const auto& pc : path)
    add_facts_with_counters(pc, facts);
  std::function<ExprP(const ExprP&)> rewrite = [&](const ExprP& e) -> ExprP {
    if (e->type != Type::Int)
      return e;
    ExprP r = map_operands(e, rewrite);
    if (r->op == Op::Shl && r->ops[1]->op != Op::IntConst) {
      // a << s: a * (1 << s), as the local that holds 1 << s
      for (const auto& [l, v] : pow2)
        if (same(v->ops[1], r->ops[1]))
          return binary(Op::Mul, r->ops[0], local_ref(l));
      return r;
    }
    if (r->op != Op::BitOr)
      return r;
    for (int high = 0; high < 2; ++high) {
      const ExprP &a = r->ops[high], &b = r->ops[1 - high];
      auto pa = to_poly(a), pb = to_poly(b);
      if (!pa || !pb)
        continue;
      auto m = power_of_two_factor(*pa, pow2_locals);
      if (!m)
        continue;
      // 0 <= b <= M - 1: b fits in the bits below M, which a leaves clear
      if (prove_nonneg(*pb, facts) && prove_nonneg(*m - Poly::constant(1) - *pb, facts))
        return binary(Op::Add, a, b);
    }
    return r;
  };
  return rewrite(index);
}

std::optional<ExprP> remainder_as_choice(const ExprP& v, const ExprP& m,
                                         const std::vector<Loop>& loops,
                                         const std::vector<PathCond>& path) {
  if (v->type != Type::Int || m->type != Type::Int)
    return std::nullopt;
  auto pv = to_poly(v), pm = to_poly(m);
  // (a remainder of constants, `m % 2` for an unrolled m, folds as it is)
  if (!pv || !pm || pm->mentions_any_counter() || !pv->mentions_any_counter())
    return std::nullopt;
  Facts facts;
  for (const auto& l : loops) {
    add_nonempty(l, facts);
    add_counter_range(l, facts);
  }
  for (const auto& pc : path)
    add_facts_with_counters(pc, facts);
  // 0 <= w and w <= 2m - 1 for w = v - k * m, k = 0, 1, 2 (then m >= 1, v >= 0,
  // and v % m = w % m is w or w - m)
  if (!prove_nonneg(*pv, facts))
    return std::nullopt;
  for (long long k = 0; k <= 2; ++k) {
    Poly w = *pv - *pm * Poly::constant(k);
    if (!prove_nonneg(w, facts) ||
        !prove_nonneg(*pm * Poly::constant(2) - Poly::constant(1) - w, facts))
      continue;
    ExprP we = v;
    for (long long i = 0; i < k; ++i)
      we = binary(Op::Sub, we, m);
    return select(binary(Op::Lt, we, m), we, binary(Op::Sub, we, m));
  }
  return std::nullopt;
}

// Some symbol of `d` is a layout symbol (ir.hpp: row_symbol, plane_symbol).
bool mentions_layout(const Poly& d) {
  for (const auto& [m, k] : d.terms())
    for (const Sym& s : m)
      if (!s.is_counter() && level_of_symbol(s.name) > 0)
        return true;
  return false;
}

// `d`, the difference of two indices with no counter, is a nonzero constant
// times the highest layout symbol in it plus terms of lower layout ranks
// only: the indices lie in different planes (rows), never the same element.
bool layout_apart(const Poly& d) {
  if (d.mentions_any_counter())
    return false;
  int top = 0;
  std::string name;
  for (const auto& [m, k] : d.terms())
    for (const Sym& s : m)
      if (level_of_symbol(s.name) > top)
        top = level_of_symbol(s.name), name = s.name;
  if (top == 0)
    return false;
  Poly c = d.coefficient(Sym::size(name));
  if (!c.is_constant() || c.constant_term() == 0)
    return false;
  const Poly rest = d.without(Sym::size(name)); // (named: terms() is a reference into it)
  for (const auto& [m, k] : rest.terms())
    for (const Sym& s : m)
      if (level_of_symbol(s.name) >= top)
        return false;
  return true;
}

Domain store_domain(const Nest& nest, const Store& s, std::vector<PathCond>& guards) {
  Box loop_box;
  for (const auto& l : nest.loops) {
    Interval iv;
    iv.lo.push_back(*to_poly(l.lo));
    iv.hi.push_back(*to_poly(l.hi));
    loop_box.dims[l.var] = iv;
  }
  Domain d = {simplify(loop_box)};
  // A condition on the sizes that every iteration of the nest implies (an
  // early `if (n < 3) return;` before loops that need n >= 3) guards nothing.
  Facts runs;
  for (const auto& l : nest.loops)
    add_nonempty(l, runs);
  for (const auto& pc : s.path) {
    auto cd = condition_domain(pc.cond);
    if (!cd) {
      if (!nest.loops.empty() && implied(pc, runs))
        continue;
      guards.push_back(pc);
      continue;
    }
    d = pc.positive ? intersect(d, *cd) : subtract(d, *cd);
  }
  return d;
}

} // namespace dpgen
