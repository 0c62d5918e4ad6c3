// Index analysis (used by lower, schedule and plan): polynomials, index
// pieces, box domains (see affine.hpp).
#include "affine.hpp"

#include "ops.hpp"

#include <tuple>

#include <algorithm>
#include <fmt/format.h>

namespace dpgen {

// ---- Poly ----------------------------------------------------------------

Poly Poly::constant(long long c) {
  Poly p;
  if (c != 0)
    p.terms_[{}] = c;
  return p;
}

Poly Poly::of(const Sym& s) {
  Poly p;
  p.terms_[{s}] = 1;
  return p;
}

Poly Poly::term(long long c, const Monomial& m) {
  Poly p;
  if (c != 0) {
    Monomial sorted = m;
    std::sort(sorted.begin(), sorted.end());
    p.terms_[sorted] = c;
  }
  return p;
}

Poly Poly::plus(const Poly& o, long long sign) const {
  Poly r = *this;
  for (const auto& [m, c] : o.terms_) {
    long long v = (r.terms_[m] += sign * c);
    if (v == 0)
      r.terms_.erase(m);
  }
  return r;
}

Poly Poly::operator+(const Poly& o) const { return plus(o, 1); }

Poly Poly::operator-(const Poly& o) const { return plus(o, -1); } // (no -o built)

Poly Poly::operator*(const Poly& o) const {
  Poly r;
  for (const auto& [m1, c1] : terms_)
    for (const auto& [m2, c2] : o.terms_) {
      Monomial m = m1;
      m.insert(m.end(), m2.begin(), m2.end());
      std::sort(m.begin(), m.end());
      long long v = (r.terms_[m] += c1 * c2);
      if (v == 0)
        r.terms_.erase(m);
    }
  return r;
}

bool Poly::is_constant() const {
  return terms_.empty() || (terms_.size() == 1 && terms_.begin()->first.empty());
}

long long Poly::constant_term() const {
  auto it = terms_.find({});
  return it == terms_.end() ? 0 : it->second;
}

bool Poly::mentions_any_counter() const {
  for (const auto& [m, k] : terms_)
    for (const auto& s : m)
      if (s.is_counter())
        return true;
  return false;
}

bool Poly::mentions(const Sym& s) const {
  for (const auto& [m, c] : terms_)
    if (std::find(m.begin(), m.end(), s) != m.end())
      return true;
  return false;
}

Poly Poly::coefficient(const Sym& var) const {
  Poly r;
  for (const auto& [m, c] : terms_) {
    auto it = std::find(m.begin(), m.end(), var);
    if (it == m.end())
      continue;
    Monomial rest = m;
    rest.erase(rest.begin() + (it - m.begin()));
    r.terms_[rest] += c;
  }
  return r;
}

Poly Poly::without(const Sym& var) const {
  Poly r;
  for (const auto& [m, c] : terms_)
    if (std::find(m.begin(), m.end(), var) == m.end())
      r.terms_[m] = c;
  return r;
}

int Poly::degree() const {
  int d = 0;
  for (const auto& [m, c] : terms_)
    d = std::max<int>(d, static_cast<int>(m.size()));
  return d;
}

std::string Poly::str() const {
  if (terms_.empty())
    return "0";
  // Highest degree first, the constant last: "j * nx + i - 1".
  std::vector<std::pair<Monomial, long long>> ts(terms_.begin(), terms_.end());
  std::stable_sort(ts.begin(), ts.end(),
                   [](const auto& a, const auto& b) { return a.first.size() > b.first.size(); });
  std::string out;
  for (const auto& [m, c] : ts) {
    long long mag = c < 0 ? -c : c;
    std::string body;
    for (const auto& s : m)
      body += (body.empty() ? "" : " * ") + s.name;
    std::string term = body.empty() ? std::to_string(mag)
                       : mag == 1   ? body
                                    : fmt::format("{} * {}", mag, body);
    if (out.empty())
      out = (c < 0 ? "-" : "") + term;
    else
      out += (c < 0 ? " - " : " + ") + term;
  }
  return out;
}

std::string Poly::code() const {
  if (terms_.empty())
    return "0";
  auto wide = [](const Sym& s) { return !s.is_counter() && s.name.rfind("c_", 0) == 0; };
  std::vector<std::pair<Monomial, long long>> ts(terms_.begin(), terms_.end());
  std::stable_sort(ts.begin(), ts.end(),
                   [](const auto& a, const auto& b) { return a.first.size() > b.first.size(); });
  std::string out;
  for (const auto& [m, c] : ts) {
    long long mag = c < 0 ? -c : c;
    Monomial syms = m;
    std::stable_partition(syms.begin(), syms.end(), wide);
    std::vector<std::string> factors;
    for (const auto& s : syms)
      factors.push_back(s.is_counter() ? s.name : renamed(s.name)); // (ir.hpp: RenameScope)
    if (syms.size() >= 2 && !wide(syms.front()))
      factors.front() = "static_cast<std::ptrdiff_t>(" + factors.front() + ")";
    if (mag != 1 || factors.empty())
      factors.insert(factors.begin(), std::to_string(mag)); // 2 * c_j * nx
    std::string term;
    for (const auto& f : factors)
      term += (term.empty() ? "" : " * ") + f;
    if (out.empty())
      out = (c < 0 ? "-" : "") + term;
    else
      out += (c < 0 ? " - " : " + ") + term;
  }
  return out;
}

bool smaller_coefficient(const Poly& a, const Poly& b) {
  auto key = [](const Poly& p) {
    int d = p.degree();
    long long top = 0, rest = 0;
    // Row-pointer symbols (ir.hpp) stand for lengths larger than any index:
    // a plane's above a row's above everything else.
    int rank = 0;
    for (const auto& [m, c] : p.terms()) {
      (int(m.size()) == d ? top : rest) += c < 0 ? -c : c;
      for (const auto& sym : m)
        if (!sym.is_counter())
          rank = std::max(rank, level_of_symbol(sym.name));
    }
    return std::make_tuple(rank, d, top, rest, p.str());
  };
  return key(a) < key(b);
}

std::vector<RadixStep> mixed_radix(std::vector<std::pair<Poly, Poly>> dims) {
  std::vector<RadixStep> out;
  for (size_t i = 0; i < dims.size(); ++i)
    out.push_back({i, dims[i].first, dims[i].first, Poly()});
  // (of equal coefficients, a counter that takes one value first: it reaches
  // nothing, `v[i + c]` for c in [0, 1))
  auto single = [&](const RadixStep& s) {
    const Poly& e = dims[s.dim].second;
    return e.is_constant() && e.constant_term() == 1;
  };
  std::stable_sort(out.begin(), out.end(), [&](const RadixStep& a, const RadixStep& b) {
    return smaller_coefficient(a.coefficient, b.coefficient) ||
           (!smaller_coefficient(b.coefficient, a.coefficient) && single(a) && !single(b));
  });
  Poly reach;
  for (auto& s : out) {
    bool negative = !s.step.terms().empty();
    for (const auto& [m, coef] : s.step.terms())
      negative = negative && coef < 0;
    if (negative)
      s.step = -s.step;
    s.reach = reach;
    reach = reach + s.step * (dims[s.dim].second - Poly::constant(1));
  }
  return out;
}

std::optional<Poly> to_poly(const ExprP& e) {
  switch (e->op) {
  case Op::IntConst:
    return Poly::constant(e->ival);
  case Op::Param:
    if (e->type != Type::Int)
      return std::nullopt;
    return Poly::symbol(e->name);
  case Op::LoopVar:
    return Poly::counter(e->name);
  case Op::Local: {
    if (e->type != Type::Int)
      return std::nullopt;
    if (e->local->opaque)
      return Poly::symbol(e->local->name);
    auto p = to_poly(e->local->def);
    // An integer local set once before every loop (`int x_min = *xmin;`,
    // `int half = n / 2;`) is fixed for the whole kernel: a symbol like a
    // parameter (the generated code defines it first).
    if (!p && e->local->kernel_level)
      return Poly::symbol(e->local->name);
    return p;
  }
  case Op::Cast: // an integer widened to 64 bits: the same value
    if (e->type != Type::Int || e->ops[0]->type != Type::Int)
      return std::nullopt;
    return to_poly(e->ops[0]);
  case Op::Neg: {
    auto a = to_poly(e->ops[0]);
    if (!a)
      return std::nullopt;
    return -*a;
  }
  case Op::Shl: { // i << c for a constant c: i * 2^c
    const ExprP& c = e->ops[1];
    if (e->type != Type::Int || c->op != Op::IntConst || c->ival < 0 || c->ival > 40)
      return std::nullopt;
    auto a = to_poly(e->ops[0]);
    if (!a)
      return std::nullopt;
    return *a * Poly::constant(1LL << c->ival);
  }
  case Op::Add:
  case Op::Sub:
  case Op::Mul: {
    if (e->type != Type::Int)
      return std::nullopt;
    auto a = to_poly(e->ops[0]);
    auto b = to_poly(e->ops[1]);
    if (!a || !b)
      return std::nullopt;
    return e->op == Op::Add ? *a + *b : e->op == Op::Sub ? *a - *b : *a * *b;
  }
  case Op::Div: {
    // An integer division that is exact for every value: each coefficient
    // is a multiple of the constant divisor (i / 2 where i = 2 + 2 * t).
    if (e->type != Type::Int)
      return std::nullopt;
    auto a = to_poly(e->ops[0]);
    auto b = to_poly(e->ops[1]);
    if (!a || !b || !b->is_constant() || b->constant_term() == 0)
      return std::nullopt;
    long long d = b->constant_term();
    Poly q;
    for (const auto& [m, c] : a->terms()) {
      if (c % d != 0)
        return std::nullopt;
      q = q + Poly::term(c / d, m);
    }
    return q;
  }
  default:
    return std::nullopt;
  }
  unknown_op("to_poly");
}

// ---- Domains -------------------------------------------------------------

namespace {

// `a - b` as a constant, if it is one: their terms but the constant ones are
// the same (no zero coefficients are stored, and the constant term, of the
// empty monomial, comes first). Builds no polynomial: the domain operations
// call this for every pair of bounds.
std::optional<long long> const_diff(const Poly& a, const Poly& b) {
  auto ia = a.terms().begin(), ib = b.terms().begin();
  const auto ea = a.terms().end(), eb = b.terms().end();
  long long ca = 0, cb = 0;
  if (ia != ea && ia->first.empty())
    ca = (ia++)->second;
  if (ib != eb && ib->first.empty())
    cb = (ib++)->second;
  for (; ia != ea && ib != eb; ++ia, ++ib)
    if (ia->second != ib->second || ia->first != ib->first)
      return std::nullopt;
  if (ia != ea || ib != eb)
    return std::nullopt;
  return ca - cb;
}

bool box_empty(const Box& b) {
  for (const auto& [v, iv] : b.dims)
    for (const auto& lo : iv.lo)
      for (const auto& hi : iv.hi) {
        auto d = const_diff(hi, lo);
        if (d && *d <= 0)
          return true;
      }
  return false;
}

// Keeps the elements of `set` not dominated by another one that differs by a
// constant; `keep_larger` for lower bounds (max), smaller for upper (min).
std::vector<Poly> prune(const std::vector<Poly>& set, bool keep_larger) {
  std::vector<Poly> out;
  for (const auto& p : set) {
    bool dominated = false;
    for (auto it = out.begin(); it != out.end();) {
      auto d = const_diff(p, *it);
      if (!d) {
        ++it;
        continue;
      }
      bool p_wins = keep_larger ? *d > 0 : *d < 0;
      if (p_wins) {
        it = out.erase(it);
      } else {
        dominated = true;
        break;
      }
    }
    if (!dominated)
      out.push_back(p);
  }
  return out;
}

void add_bounds(Interval& into, const Interval& from) {
  into.lo.insert(into.lo.end(), from.lo.begin(), from.lo.end());
  into.hi.insert(into.hi.end(), from.hi.begin(), from.hi.end());
}

Box box_intersect(const Box& a, const Box& b) {
  Box r = a;
  for (const auto& [v, iv] : b.dims)
    add_bounds(r.dims[v], iv);
  return simplify(std::move(r));
}

// box_empty(box_intersect(a, b)) without building the box: pruning a dominated bound never
// hides an empty interval (a pair lo < hi that is empty stays empty with the bound that wins),
// so the pairs of the unpruned bounds decide. Most pieces subtract() intersects are empty.
bool intersection_empty(const Box& a, const Box& b) {
  auto empty_pair = [](const std::vector<Poly>& los, const std::vector<Poly>& his) {
    for (const auto& lo : los)
      for (const auto& hi : his) {
        auto d = const_diff(hi, lo);
        if (d && *d <= 0)
          return true;
      }
    return false;
  };
  for (const auto& [v, ia] : a.dims) {
    auto it = b.dims.find(v);
    if (empty_pair(ia.lo, ia.hi))
      return true;
    if (it != b.dims.end() &&
        (empty_pair(ia.lo, it->second.hi) || empty_pair(it->second.lo, ia.hi)))
      return true;
  }
  for (const auto& [v, ib] : b.dims)
    if (empty_pair(ib.lo, ib.hi))
      return true;
  return false;
}

// v not in [max(lo), min(hi)), as disjoint intervals:
//   v < max(a1..ak)  = U_m { a1..a(m-1) <= v < a_m }
//   v >= max(lo) and v >= min(b1..bk) = U_m { lo, b_m <= v < b1..b(m-1) }
std::vector<Interval> outside(const Interval& iv) {
  std::vector<Interval> out;
  for (size_t m = 0; m < iv.lo.size(); ++m) {
    Interval p;
    p.lo.assign(iv.lo.begin(), iv.lo.begin() + m);
    p.hi.push_back(iv.lo[m]);
    out.push_back(p);
  }
  for (size_t m = 0; m < iv.hi.size(); ++m) {
    Interval p;
    p.lo = iv.lo;
    p.lo.push_back(iv.hi[m]);
    p.hi.assign(iv.hi.begin(), iv.hi.begin() + m);
    out.push_back(p);
  }
  return out;
}

// The complement of a box as disjoint boxes: the first variable outside, or
// the first inside and the second outside, ...
Domain complement(const Box& y) {
  Domain out;
  Box prefix;
  for (const auto& [v, iv] : y.dims) {
    for (const auto& piece : outside(iv)) {
      Box b = prefix;
      b.dims[v] = piece;
      out.push_back(b);
    }
    prefix.dims[v] = iv;
  }
  return out;
}

bool interval_within(const Interval& b, const Interval& y) {
  for (const auto& ylo : y.lo) {
    bool ok = false;
    for (const auto& blo : b.lo) {
      auto d = const_diff(blo, ylo);
      ok = ok || (d && *d >= 0);
    }
    if (!ok)
      return false;
  }
  for (const auto& yhi : y.hi) {
    bool ok = false;
    for (const auto& bhi : b.hi) {
      auto d = const_diff(yhi, bhi);
      ok = ok || (d && *d >= 0);
    }
    if (!ok)
      return false;
  }
  return true;
}

bool intervals_apart(const Interval& a, const Interval& b) {
  auto below = [](const Interval& x, const Interval& y) { // x ends before y starts
    for (const auto& xhi : x.hi)
      for (const auto& ylo : y.lo) {
        auto d = const_diff(ylo, xhi);
        if (d && *d >= 0)
          return true;
      }
    return false;
  };
  return below(a, b) || below(b, a);
}

} // namespace

Box simplify(Box b) {
  for (auto& [v, iv] : b.dims) {
    iv.lo = prune(iv.lo, true);
    iv.hi = prune(iv.hi, false);
  }
  return b;
}

Domain universe() { return {Box{}}; }

Domain intersect(const Domain& a, const Domain& b) {
  Domain out;
  for (const auto& x : a)
    for (const auto& y : b)
      if (!intersection_empty(x, y))
        out.push_back(box_intersect(x, y));
  return out;
}

Domain subtract(const Domain& a, const Domain& b) {
  Domain cur = a;
  for (const auto& y : b)
    cur = intersect(cur, complement(y));
  return cur;
}

Domain unite(const Domain& a, const Domain& b) {
  Domain out = a;
  for (const auto& x : subtract(b, a))
    out.push_back(x);
  return out;
}

Domain shift(const Domain& d, const std::map<std::string, Poly>& delta) {
  Domain out = d;
  for (auto& box : out)
    for (auto& [v, iv] : box.dims) {
      auto it = delta.find(v);
      if (it == delta.end())
        continue;
      for (auto& p : iv.lo)
        p = p + it->second;
      for (auto& p : iv.hi)
        p = p + it->second;
    }
  return out;
}

bool box_inside(const Box& b, const Domain& d) {
  if (box_empty(b))
    return true;
  for (const auto& y : d) {
    bool ok = true;
    for (const auto& [v, iv] : y.dims) {
      auto it = b.dims.find(v);
      if (it == b.dims.end() || !interval_within(it->second, iv)) {
        ok = false;
        break;
      }
    }
    if (ok)
      return true;
  }
  return false;
}

bool box_disjoint(const Box& b, const Domain& d) {
  if (box_empty(b))
    return true;
  for (const auto& y : d) {
    bool apart = false;
    for (const auto& [v, iv] : y.dims) {
      auto it = b.dims.find(v);
      if (it != b.dims.end() && intervals_apart(it->second, iv)) {
        apart = true;
        break;
      }
    }
    if (!apart)
      return false;
  }
  return true;
}

namespace {

// v op B  as a domain (v: a counter's name).
Domain compare_domain(const std::string& v, Op op, const Poly& bound) {
  Box b;
  Interval& iv = b.dims[v];
  switch (op) {
  case Op::Lt:
    iv.hi = {bound};
    break;
  case Op::Le:
    iv.hi = {bound + Poly::constant(1)};
    break;
  case Op::Gt:
    iv.lo = {bound + Poly::constant(1)};
    break;
  case Op::Ge:
    iv.lo = {bound};
    break;
  case Op::Eq:
  case Op::Ne:
    iv.lo = {bound};
    iv.hi = {bound + Poly::constant(1)};
    if (op == Op::Ne)
      return subtract(universe(), {b});
    break;
  default:
    break;
  }
  return {b};
}

} // namespace

std::optional<Domain> condition_domain(const ExprP& c) {
  switch (c->op) {
  case Op::And:
  case Op::Or: {
    auto a = condition_domain(c->ops[0]);
    auto b = condition_domain(c->ops[1]);
    if (!a || !b)
      return std::nullopt;
    return c->op == Op::And ? intersect(*a, *b) : unite(*a, *b);
  }
  case Op::Not: {
    auto a = condition_domain(c->ops[0]);
    if (!a)
      return std::nullopt;
    return subtract(universe(), *a);
  }
  case Op::Lt:
  case Op::Le:
  case Op::Gt:
  case Op::Ge:
  case Op::Eq:
  case Op::Ne: {
    if (c->ops[0]->type != Type::Int || c->ops[1]->type != Type::Int)
      return std::nullopt;
    auto l = to_poly(c->ops[0]);
    auto r = to_poly(c->ops[1]);
    if (!l || !r)
      return std::nullopt;
    return zero_compare_domain(*l - *r, c->op);
  }
  default:
    return std::nullopt;
  }
  unknown_op("condition_domain");
}

std::optional<Domain> zero_compare_domain(const Poly& p, Op op) { // p op 0
  std::optional<Sym> var;
  for (const auto& [m, coef] : p.terms())
    for (const auto& s : m)
      if (s.is_counter()) {
        if (var && *var != s)
          return std::nullopt; // two loop counters: not a box
        var = s;
      }
  if (!var)
    return std::nullopt; // sizes only: a run-time guard
  Poly coef = p.coefficient(*var);
  if (!coef.is_constant() || (coef.constant_term() != 1 && coef.constant_term() != -1))
    return std::nullopt;
  Poly rest = p.without(*var);
  if (coef.constant_term() == 1) // v + rest op 0  <=>  v op -rest
    return compare_domain(var->name, op, -rest);
  return compare_domain(var->name, op_info(op).mirror, rest); // -v + rest op 0 <=> v op' rest
}

namespace {

// The pieces of a binary integer operation `e`: each pair of its operands' pieces (x, y) on
// the domain where both hold, handed to `combine`, which adds what it makes to `out`; where
// `combine` returns false (a pair it cannot split into boxes), nullopt.
template <typename Combine>
std::optional<std::vector<IndexPiece>> pairwise(const ExprP& e, Combine combine) {
  auto a = index_pieces(e->ops[0]);
  auto b = index_pieces(e->ops[1]);
  if (!a || !b)
    return std::nullopt;
  std::vector<IndexPiece> out;
  for (const auto& x : *a)
    for (const auto& y : *b) {
      Domain both = intersect(x.where, y.where);
      if (!both.empty() && !combine(x, y, both, out))
        return std::nullopt;
    }
  return out;
}

} // namespace

std::optional<std::vector<IndexPiece>> index_pieces(const ExprP& e) {
  using Pieces = std::vector<IndexPiece>;
  if (e->type != Type::Int)
    return std::nullopt;
  switch (e->op) {
  case Op::Local: {
    if (e->local->opaque)
      return Pieces{{Poly::symbol(e->local->name), universe()}};
    auto pieces = index_pieces(e->local->def);
    // An integer local set once before every loop (`int x_min = *xmin;`) is
    // fixed for the whole kernel: a symbol, as in to_poly.
    if (!pieces && e->local->kernel_level)
      return Pieces{{Poly::symbol(e->local->name), universe()}};
    return pieces;
  }
  case Op::Select: {
    auto where = condition_domain(e->ops[0]);
    auto a = index_pieces(e->ops[1]);
    auto b = index_pieces(e->ops[2]);
    if (!where || !a || !b)
      return std::nullopt;
    Pieces out;
    for (auto& p : *a) {
      Domain d = intersect(p.where, *where);
      if (!d.empty())
        out.push_back({p.value, d});
    }
    for (auto& p : *b) {
      Domain d = subtract(p.where, *where);
      if (!d.empty())
        out.push_back({p.value, d});
    }
    return out;
  }
  case Op::Call: {
    // std::max / std::min of integers (a clamped neighbour, `u[std::max(i - 1, 0)]`): the
    // choice the generated code makes, dpgen_max(a, b) = a < b ? b : a and dpgen_min(a, b) =
    // b < a ? b : a (either on a tie: the same value), piece by piece of a and b, where each
    // comparison is one of a loop counter (else nullopt: a clamp of sizes against sizes).
    if ((e->name != "max" && e->name != "min") || e->ops.size() != 2)
      return std::nullopt;
    return pairwise(
        e, [&](const IndexPiece& x, const IndexPiece& y, const Domain& both, Pieces& out) {
          auto y_wins =
              zero_compare_domain(e->name == "max" ? x.value - y.value : y.value - x.value, Op::Lt);
          if (!y_wins)
            return false;
          Domain dy = intersect(both, *y_wins), dx = subtract(both, *y_wins);
          if (!dy.empty())
            out.push_back({y.value, dy});
          if (!dx.empty())
            out.push_back({x.value, dx});
          return true;
        });
  }
  case Op::Neg: {
    auto a = index_pieces(e->ops[0]);
    if (!a)
      return std::nullopt;
    for (auto& p : *a)
      p.value = -p.value;
    return a;
  }
  case Op::Add:
  case Op::Sub:
  case Op::Mul:
    return pairwise(e,
                    [&](const IndexPiece& x, const IndexPiece& y, const Domain& both, Pieces& out) {
                      out.push_back({e->op == Op::Add   ? x.value + y.value
                                     : e->op == Op::Sub ? x.value - y.value
                                                        : x.value * y.value,
                                     both});
                      return true;
                    });
  default: {
    auto p = to_poly(e);
    if (!p)
      return std::nullopt;
    return Pieces{{*p, universe()}};
  }
  }
  unknown_op("index_pieces");
}

} // namespace dpgen
