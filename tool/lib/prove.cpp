// Prove: see prove.hpp.
#include "prove.hpp"

#include "ops.hpp"

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
  std::set<Poly::Monomial> products;
  for (const Poly* p : {&goal})
    for (const auto& [m, k] : p->terms())
      if (m.size() == 2)
        products.insert(m);
  for (const auto& f : facts)
    for (const auto& [m, k] : f.terms())
      if (m.size() == 2)
        products.insert(m);
  for (const auto& m : products) {
    auto a = lower.find(m[0]), b = lower.find(m[1]);
    if (a != lower.end() && b != lower.end() && a->second >= 0 && b->second >= 0)
      all.push_back((Poly::of(m[0]) - Poly::constant(a->second)) *
                    (Poly::of(m[1]) - Poly::constant(b->second)));
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
