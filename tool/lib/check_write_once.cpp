// Check, the write-once rule (check.hpp): each output element is written by
// exactly one iteration of one nest. Within a nest the stores' indices must
// be affine and one-to-one over the loop box (check_store,
// check_one_to_one), and two stores to an output may not meet (the same
// index under disjoint paths, residues, planes, rows or line-buffer elements
// apart, or a last writer the adjoint can name); across nests, what one
// writes the others may not. A part of check.cpp's Checker, over the same
// CheckState (check_impl.hpp).
#include "check_impl.hpp"
#include "ir_walk.hpp"

#include "affine.hpp"
#include "print.hpp"
#include "prove.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <optional>
#include <set>

namespace dpgen::checking {

namespace {

class WriteOnce {
public:
  explicit WriteOnce(CheckState& s) : s_(s), k_(s.k_), a_(s.a_) {}

  // Each output cell is written by exactly one iteration: the write index
  // must be affine and one-to-one over the loop box. Inequalities between
  // sizes that the rule needs are proved from what the kernel says about them
  // (the loops run, its guards); the rest become run-time checks.
  // Returns false where an index is not affine or multiplies counters.
  bool check_outputs() {
    bool affine = true;
    std::set<std::string> not_affine; // outputs with an index the rules below cannot range
    for (const auto& nest : k_.nests) {
      bool nest_affine = true;
      for (const auto& s : nest.stores)
        if (!check_store(nest, s)) {
          nest_affine = false;
          not_affine.insert(s.array);
        }
      affine = affine && nest_affine;
      // Within one loop nest, every store to an output uses the same index
      // (their paths are disjoint), so no two iterations meet; stores that
      // all add ('+=') may go anywhere.
      std::set<const Store*> reported;
      if (!nest.loops.empty() && nest_affine)
        for (size_t a = 0; a < nest.stores.size(); ++a)
          for (size_t b = a + 1; b < nest.stores.size(); ++b) {
            const Store &x = nest.stores[a], &y = nest.stores[b];
            if (reported.count(&y) || x.array != y.array || (x.accumulate && y.accumulate) ||
                exclusive(x.path, y.path) || *to_poly(x.index) == *to_poly(y.index) ||
                residues_differ(*to_poly(x.index), *to_poly(y.index)) ||
                rows_apart(x, nest, y, nest) || buffer_stores_apart(x, nest, y, nest) ||
                (nest.loops.size() == 1 && apart_in_rows(x, nest, y, nest, 1)) ||
                fixed_apart(*to_poly(x.index), *to_poly(y.index)) || planes_apart(nest, x, y) ||
                last_writer(nest, a, b))
              continue;
            fail(y.pos, "dpgen-write-once",
                 fmt::format("output '{}' is written at '{}' here and at '{}' on "
                             "line {} of the same loop: dpgen cannot prove two "
                             "iterations never write the same element (where one "
                             "overwrites the other's element in a later iteration, "
                             "dpgen credits the later writer only when the indices "
                             "differ by a constant step of one counter and the "
                             "overwriting store runs in every iteration)",
                             y.array, print_index(y), print_index(x), x.pos.line));
            reported.insert(&y); // once per store
          }
    }
    // Across loop nests: an element written twice would be overwritten in
    // the forward pass but counted twice in the adjoint. A later '+=' adds to
    // what an earlier store left, which is fine; a later '=' must write other
    // elements than every earlier store.
    struct Ref {
      const Nest* nest;
      const Store* store;
    };
    std::vector<Ref> all;
    for (const auto& n : k_.nests)
      for (const auto& st : n.stores)
        all.push_back({&n, &st});
    std::sort(all.begin(), all.end(),
              [](const Ref& a, const Ref& b) { return a.store->seq < b.store->seq; });
    std::set<const Store*> reported;
    for (size_t a = 0; a < all.size(); ++a)
      for (size_t b = a + 1; b < all.size(); ++b) {
        const Nest &nx = *all[a].nest, &ny = *all[b].nest;
        const Store &x = *all[a].store, &y = *all[b].store;
        if (x.array != y.array || &nx == &ny || reported.count(&y) || not_affine.count(x.array) ||
            exclusive(x.path, y.path) || buffer_stores_apart(x, nx, y, ny))
          continue;
        size_t shared = shared_loops(nx, ny);
        if (y.accumulate) {
          // Sequential nests: the '+=' runs after the whole earlier nest. In
          // nests inside a shared loop, only when both touch an element in the
          // same iteration of the shared loops: the same index, in those
          // counters alone.
          if (shared == 0 || (*to_poly(x.index) == *to_poly(y.index) &&
                              only_counters(*to_poly(x.index), nx, shared)))
            continue;
        }
        if (residues_differ(*to_poly(x.index), *to_poly(y.index)) || rows_apart(x, nx, y, ny) ||
            (shared == 1 && apart_in_rows(x, nx, y, ny, shared)))
          continue;
        Facts facts = pair_facts(nx, x, ny, y);
        auto rx = index_range(x, nx), ry = index_range(y, ny);
        if (rx && ry) {
          // apart: max x < min y, or max y < min x
          Poly one = Poly::constant(1);
          Poly g1 = ry->first - rx->second - one, g2 = rx->first - ry->second - one;
          if (prove_nonneg(g1, facts) || prove_nonneg(g2, facts))
            continue;
          Poly one_ = Poly::constant(1);
          bool overlap = prove_nonneg(-g1 - one_, facts) && prove_nonneg(-g2 - one_, facts);
          if (shared == 0 && !overlap) {
            check_apart(sorted_conds(facts_premises(nx, x, ny, y)), x, y, g1, g2, *rx, *ry);
            continue;
          }
        }
        fail(y.pos, "dpgen-write-once",
             fmt::format("output '{}' is also written on line {} in another loop "
                         "nest, and dpgen cannot prove the two write different "
                         "elements (the adjoint would count an overwritten "
                         "element twice); write each element in one loop, with "
                         "an index branch for the boundary",
                         y.array, x.pos.line));
        reported.insert(&y); // once per store
      }
    return affine;
  }

private:
  // Two stores to a line buffer (check.hpp: Accesses::buffers) in nests
  // inside its row loops: in one row, their elements (the indices as the
  // kernel writes them, each inside the buffer: lowering checks that) lie
  // apart, so they never write the same element.
  bool buffer_stores_apart(const Store& x, const Nest& nx, const Store& y, const Nest& ny) const {
    auto it = a_.buffers.find(x.array);
    if (it == a_.buffers.end() || shared_loops(nx, ny) < it->second.depth)
      return false;
    const auto& b = it->second;
    auto local = [&](const Store& s) {
      Poly p = *to_poly(s.index);
      return b.depth == 0 ? p : p - *to_poly(b.row) * *to_poly(b.length);
    };
    auto rx = index_range(local(x), x.path, nx), ry = index_range(local(y), y.path, ny);
    if (!rx || !ry)
      return false;
    Facts facts = pair_facts(nx, x, ny, y);
    Poly one = Poly::constant(1);
    facts.push_back(*to_poly(b.length) - one); // (a VLA has at least one element)
    return prove_nonneg(ry->first - rx->second - one, facts) ||
           prove_nonneg(rx->first - ry->second - one, facts);
  }

  // Two stores of one nest whose indices differ by a sum of sizes alone
  // (component planes of one flat array, `f[l * (nz + 1) * (nx + 1) + k *
  // (nx + 1) + i]` for constants l = 0..3): they never meet when their index
  // ranges over the loop box lie apart (the plane offset exceeds what the
  // counters reach: k * (nx + 1) + i < (nz + 1) * (nx + 1) for k < nz + 1,
  // i < nx + 1). Proved from the facts where both run; where the sizes decide
  // it (a stride passed as a parameter), a run-time SizeCheck; false where the
  // form does not fit or the ranges overlap for every size. (A constant
  // difference is last_writer's: those stores may meet across iterations.)
  bool planes_apart(const Nest& nest, const Store& x, const Store& y) {
    Poly px = *to_poly(x.index), py = *to_poly(y.index);
    Poly d = py - px;
    if (d.is_constant() || d.mentions_any_counter())
      return false;
    // (a view's layout symbols are no sizes to test: rows_apart's)
    if (max_level_rank(px) > 0 || max_level_rank(py) > 0)
      return false;
    auto rx = index_range(x, nest), ry = index_range(y, nest);
    if (!rx || !ry)
      return false;
    Facts facts = pair_facts(nest, x, nest, y);
    const Poly one = Poly::constant(1);
    // apart: max x < min y, or max y < min x
    Poly g1 = ry->first - rx->second - one, g2 = rx->first - ry->second - one;
    if (prove_nonneg(g1, facts) || prove_nonneg(g2, facts))
      return true;
    if (prove_nonneg(-g1 - one, facts) && prove_nonneg(-g2 - one, facts))
      return false; // they overlap for every size
    check_apart(sorted_conds(facts_premises(nest, x, nest, y)), x, y, g1, g2, *rx, *ry);
    return true;
  }

  // Two fixed elements (no counter: stores pinned to one iteration each,
  // `if (i == 0) e[0] = ...; if (i == n - 1) e[1] = ...;`) a nonzero
  // constant apart never meet.
  static bool fixed_apart(const Poly& x, const Poly& y) {
    Poly d = x - y;
    return !x.mentions_any_counter() && !y.mentions_any_counter() && d.is_constant() &&
           d.constant_term() != 0;
  }

  // Two stores of one nest that meet across iterations, the later writer
  // winning (`K[j] = ...; K[j + 1] = ...;`: K[j + 1] of iteration j is
  // overwritten by K[j'] of iteration j' = j + 1): the earlier instance
  // contributes nothing, so its store gets the condition that no later
  // iteration overwrites it (`!(j + 1 < n)`). Only for indices in one
  // counter with the same constant coefficient and a constant difference,
  // and an overwriting store that runs in every iteration; false (nothing
  // changed) otherwise.
  bool last_writer(const Nest& nest, size_t a, size_t b) {
    Nest& n = const_cast<Nest&>(nest); // (the Kernel is check's to annotate)
    Store &x = n.stores[a], &y = n.stores[b];
    if (x.accumulate || y.accumulate)
      return false;
    auto px = to_poly(x.index), py = to_poly(y.index);
    if (!px || !py)
      return false;
    const Loop* loop = nullptr;
    for (const auto& l : nest.loops)
      if (px->mentions_counter(l.var)) {
        if (loop)
          return false; // (a shift over several counters is not unique)
        loop = &l;
      }
    if (!loop || !to_poly(loop->hi))
      return false;
    Poly c = px->coefficient(Sym::counter(loop->var));
    Poly d = *py - *px;
    if (!c.is_constant() || c.constant_term() == 0 ||
        !(c == py->coefficient(Sym::counter(loop->var))) || !d.is_constant() ||
        d.constant_term() % c.constant_term() != 0)
      return false;
    // x at t + k writes what y wrote at t, and y at t - k what x wrote at t;
    // the one of the two iterations that runs later wins: t + k when the loop
    // counts up and k > 0, when it counts down and k < 0.
    long long k = d.constant_term() / c.constant_term();
    if (k == 0 || !to_poly(loop->lo))
      return false;
    const bool y_dies = (k > 0) != loop->descending;
    Store& dead = y_dies ? y : x;
    const Store& over = y_dies ? x : y;
    // The overwriting store runs wherever the dead one does, one iteration
    // away: its conditions must not depend on the counter and must be the
    // dead store's too (a kernel guard, `if (n < 2) return;`).
    for (const auto& pc : over.path) {
      bool moves = any_node(
          pc.cond, [&](const ExprP& e) { return e->op == Op::LoopVar && e->name == loop->var; });
      bool shared = std::any_of(dead.path.begin(), dead.path.end(), [&](const PathCond& q) {
        return q.cond == pc.cond && q.positive == pc.positive;
      });
      if (moves || !shared)
        return false;
    }
    // The overwriting iteration, from the dead store's t: t + k (y dies) or
    // t - k (x dies); it exists where it is inside the loop's range.
    ExprP t = loop_var(loop->var);
    ExprP later = binary(Op::Add, t, int_const(y_dies ? k : -k));
    ExprP exists =
        loop->descending ? binary(Op::Ge, later, loop->lo) : binary(Op::Lt, later, loop->hi);
    dead.path.push_back({exists, false});
    return true;
  }

  // Store `s` runs in one iteration of loop `var` at most for each value of
  // the counters in `free` (its path pins the counter): `if (i == 0) out[0] =
  // ...` writes its element once.
  static bool pinned(const Store& s, const std::string& var, const std::set<std::string>& free) {
    return std::any_of(s.path.begin(), s.path.end(),
                       [&](const PathCond& pc) { return pins(pc.cond, pc.positive, var, free); });
  }

  // One store's index: affine, each term with one counter at most, moving
  // with every loop around it (unless the store adds, or runs in one
  // iteration of that loop), one-to-one. Returns false where the index is
  // not affine or multiplies counters.
  bool check_store(const Nest& nest, const Store& s) {
    auto p = to_poly(s.index);
    if (!p) {
      bool bits = any_node(s.index, [](const ExprP& x) {
        return x->op == Op::BitOr || (x->op == Op::Shl && x->ops[1]->op != Op::IntConst);
      });
      fail(s.pos, "dpgen-output-index",
           fmt::format("index of output '{}' must be an affine function of the "
                       "loop counters (no conditional or data-dependent writes){}",
                       s.array,
                       bits ? "; `(j << lg) | i` is read as j * n + i only with a "
                              "kernel-level `const int n = 1 << lg;` and loops that "
                              "keep i in [0, n)"
                            : ""));
      return false;
    }
    std::vector<std::pair<Poly, Poly>> dims; // (coefficient, extent)
    std::set<std::string> moving;            // the counters the index moves with
    for (const auto& l : nest.loops)
      if (!(p->coefficient(Sym::counter(l.var)) == Poly()))
        moving.insert(l.var);
    for (const auto& l : nest.loops) {
      Poly c = p->coefficient(Sym::counter(l.var));
      if (c.mentions_any_counter()) {
        fail(s.pos, "dpgen-output-index",
             fmt::format("index of output '{}' multiplies loop counters", s.array));
        return false;
      }
      if (c == Poly()) {
        if (s.accumulate || pinned(s, l.var, moving))
          continue; // a reduction: every iteration adds to the same element
        fail(s.pos, "dpgen-write-once",
             fmt::format("output '{}' is written at the same index by every "
                         "iteration of loop '{}' (a reduction or a loop-carried "
                         "dependence); each element must be written once with "
                         "'=', or summed into with '+='",
                         s.array, l.var));
        return true;
      }
      dims.push_back({c, *to_poly(l.hi) - *to_poly(l.lo)});
    }
    if (auto b = a_.buffers.find(s.array); b != a_.buffers.end() && b->second.depth > 0) {
      // A line buffer: rows apart (each element inside its row, which
      // lowering checks), so one-to-one within a row, over the loops inside
      // the row loops, at the index as the kernel writes it.
      Poly local = *p - *to_poly(b->second.row) * *to_poly(b->second.length);
      dims.clear();
      for (size_t d = b->second.depth; d < nest.loops.size(); ++d) {
        const Loop& l = nest.loops[d];
        Poly c = local.coefficient(Sym::counter(l.var));
        if (!(c == Poly()))
          dims.push_back({c, *to_poly(l.hi) - *to_poly(l.lo)});
      }
    }
    if (!s.accumulate)
      check_one_to_one(nest, s, dims);
    return true;
  }

  // Two indices never meet when every counter coefficient of both is a
  // multiple of some g > 1 and their remaining parts differ by a constant that
  // is not (fine[2 * i] and fine[2 * i + 1]).
  static bool residues_differ(const Poly& x, const Poly& y) {
    long long g = 0;
    Poly rx = x, ry = y;
    for (const Poly* p : {&x, &y})
      for (const auto& [m, coef] : p->terms()) {
        bool counter = false;
        for (const auto& sym : m)
          counter = counter || sym.is_counter();
        if (!counter)
          continue;
        if (m.size() != 1)
          return false; // a counter times a size: no constant modulus
        g = std::gcd(g, coef < 0 ? -coef : coef);
        (p == &x ? rx : ry) = (p == &x ? rx : ry).without(m[0]);
      }
    Poly d = rx - ry;
    return g > 1 && d.is_constant() && d.constant_term() % g != 0;
  }

  // The polynomial mentions no counter but the first `shared` loops of `nest`.
  static bool only_counters(const Poly& p, const Nest& nest, size_t shared) {
    for (size_t i = shared; i < nest.loops.size(); ++i)
      if (p.mentions_counter(nest.loops[i].var))
        return false;
    return true;
  }

  // The element as written in the source: "e[1][i]" for row pointers.
  std::string print_index(const Store& s) const {
    return s.array + subscript(s.index, k_.shape_of(s.array));
  }

  // Row-pointer arrays (ir.hpp: row_symbol): each row is an array of its own,
  // so two stores whose rows (planes, for `double***`) lie apart over their
  // loop boxes never write the same element, whatever their columns
  // (`e[0][i]` and `e[1][i]`; rows [0, ng) and [ng, ny)).
  bool rows_apart(const Store& x, const Nest& nx, const Store& y, const Nest& ny) const {
    int levels = k_.levels_of(x.array);
    if (levels == 0)
      return false;
    Sym outer = Sym::size(levels == 3   ? cube_symbol(x.array)
                          : levels == 2 ? plane_symbol(x.array)
                                        : row_symbol(x.array));
    auto row = [&](const Store& s) { return to_poly(s.index)->coefficient(outer); };
    auto rx = index_range(row(x), x.path, nx), ry = index_range(row(y), y.path, ny);
    if (!rx || !ry)
      return false;
    Facts facts = pair_facts(nx, x, ny, y);
    Poly one = Poly::constant(1);
    return prove_nonneg(ry->first - rx->second - one, facts) ||
           prove_nonneg(rx->first - ry->second - one, facts);
  }

  // Mixed-radix test: with the counters ordered by coefficient, every
  // coefficient exceeds the largest offset the smaller ones can reach:
  //   sum_{smaller} |c| * (extent - 1) < |c_next|.
  // Proved from the facts where the store runs (its loops run, its guards
  // hold); otherwise checked at run time.
  void check_one_to_one(const Nest& nest, const Store& s, std::vector<std::pair<Poly, Poly>> dims) {
    Facts facts;
    for (const auto& l : nest.loops)
      add_nonempty(l, facts);
    for (const auto& pc : s.path)
      add_facts(pc, facts);
    const auto steps = mixed_radix(std::move(dims)); // affine.hpp
    for (size_t i = 0; i < steps.size(); ++i) {
      const Poly &c = steps[i].step, &reach = steps[i].reach;
      // A row (plane) symbol exceeds any offset within a row (plane): the
      // assumption about rows reached through pointers and views' layouts
      // (ir.hpp: row_symbol, Param::view), no run-time check.
      if (i > 0 && level_rank(c) > 0 && max_level_rank(reach) < level_rank(c))
        continue;
      if (i > 0) {
        Poly slack = c - reach - Poly::constant(1); // must be >= 0
        if (!prove_nonneg(slack, facts)) {
          if (prove_nonneg(-slack - Poly::constant(1), facts))
            return fail(s.pos, "dpgen-write-once",
                        fmt::format("output '{}' is written twice per element: index "
                                    "coefficient '{}' against a reach of '{}'",
                                    s.array, c.str(), reach.str()));
          SizeCheck chk;
          chk.premises = sorted_conds(facts_premises(nest, s, nest, s));
          chk.must_hold = {{SizeCond::nonneg(slack)}};
          chk.what = fmt::format("output '{}' is written once per element: its index steps by "
                                 "'{}' where the faster counters reach '{}'",
                                 s.array, c.str(), reach.str());
          chk.pos = s.pos;
          k_.size_checks.push_back(chk);
        }
      }
    }
  }

  // The run-time check that stores x and y, over index ranges rx and ry,
  // write apart: g1 = min y - max x - 1 >= 0 or g2 = min x - max y - 1 >= 0
  // where `premises` hold.
  template <typename Premises, typename Range>
  void check_apart(Premises premises, const Store& x, const Store& y, const Poly& g1,
                   const Poly& g2, const Range& rx, const Range& ry) {
    SizeCheck c;
    c.premises = std::move(premises);
    c.must_hold = {{SizeCond::nonneg(g1), SizeCond::nonneg(g2)}};
    c.what = fmt::format("output '{}' is written by the stores on lines {} and {} at "
                         "elements [{}, {}] and [{}, {}], which must not overlap",
                         y.array, x.pos.line, y.pos.line, rx.first.str(), rx.second.str(),
                         ry.first.str(), ry.second.str());
    c.pos = y.pos;
    k_.size_checks.push_back(c);
  }

  // Condition `c` holds for one value of counter `var` at most: `i == 0`,
  // `i == n - 1`, `2 * t + 1 == k` (an equation linear in `var` with a
  // constant coefficient), or a conjunction with one such part.
  // The rest of the equation may mention only counters in `free` (those
  // that move the store's index: `if (i == j) d[i] = ...` pins j given i),
  // never one that also stays (`if (i == j) tr[0] = ...` runs n times).
  static bool pins(const ExprP& c, bool positive, const std::string& var,
                   const std::set<std::string>& free) {
    if (positive && c->op == Op::And)
      return pins(c->ops[0], true, var, free) || pins(c->ops[1], true, var, free);
    if (!positive && c->op == Op::Or) // !(a || b): !a && !b
      return pins(c->ops[0], false, var, free) || pins(c->ops[1], false, var, free);
    if (!positive && c->op == Op::Not)
      return pins(c->ops[0], true, var, free);
    if (c->op != (positive ? Op::Eq : Op::Ne))
      return false;
    auto a = to_poly(c->ops[0]), b = to_poly(c->ops[1]);
    if (!a || !b) { // `i == n / 2`: the counter against anything free of counters
      auto counter_free = [](const ExprP& x) {
        return !any_node(x, [](const ExprP& y) { return y->op == Op::LoopVar; });
      };
      auto is_var = [&](const ExprP& x) { return x->op == Op::LoopVar && x->name == var; };
      return (is_var(c->ops[0]) && counter_free(c->ops[1])) ||
             (is_var(c->ops[1]) && counter_free(c->ops[0]));
    }
    Poly d = *a - *b;
    Poly coef = d.coefficient(Sym::counter(var));
    if (!coef.is_constant() || coef.constant_term() == 0)
      return false;
    Poly rest = d - coef * Poly::counter(var);
    for (const auto& [m, k] : rest.terms())
      for (const auto& sym : m)
        if (sym.is_counter() && !free.count(sym.name))
          return false;
    return true;
  }

  // The C++ conditions under which a check applies: both stores execute.
  std::vector<SizeCond> facts_premises(const Nest& nx, const Store& x, const Nest& ny,
                                       const Store& y) {
    std::vector<SizeCond> out;
    for (const Nest* n : {&nx, &ny})
      for (const auto& l : n->loops)
        out.push_back(SizeCond::runs(*to_poly(l.lo), *to_poly(l.hi)));
    for (const Store* st : {&x, &y})
      for (const auto& pc : st->path) {
        Facts f;
        add_facts(pc, f);
        for (const auto& p : f)
          out.push_back(SizeCond::nonneg(p));
      }
    return out;
  }

  // Two stores inside one shared loop over j whose indices are c * j + r
  // with the same c (a row of length c, `f[j * nx + 0]`, `f[j * nx + i]` for
  // i in 1..nx-2, `f[j * nx + nx - 1]`): they never write the same element
  // when both remainders stay in [0, c - 1] (rows apart for different j) and
  // their ranges are apart (in one row). What the sizes must satisfy for
  // that and cannot be proved becomes a run-time SizeCheck (nx >= 2 for
  // the two end columns); false where the form does not fit or a condition
  // fails for every size.
  bool apart_in_rows(const Store& x, const Nest& nx, const Store& y, const Nest& ny,
                     size_t shared) {
    // (rows reached through pointers are rows_apart's: their row symbol is
    // no size a run-time check could test)
    if (shared != 1 || nx.loops.empty() || k_.levels_of(x.array) > 0)
      return false;
    Sym j = Sym::counter(nx.loops[0].var);
    Poly px = *to_poly(x.index), py = *to_poly(y.index);
    Poly c = px.coefficient(j);
    if (c == Poly() || !(c == py.coefficient(j)) || c.mentions_any_counter())
      return false;
    // (rows of one element hold remainder 0 alone: two stores apart in such
    // rows never are; `out[i]` and `out[stride + i]` are planes_apart's)
    if (c.is_constant() && (c.constant_term() == 1 || c.constant_term() == -1))
      return false;
    // (a loop counting down by a constant, `b[i]` with `i -= 2`: c * j + r =
    // |c| * (-j) + r, rows of length |c| all the same)
    if (c.is_constant() && c.constant_term() < 0)
      c = -c;
    // (indices a multiple of c apart meet across iterations: last_writer's)
    const Poly d = py - px;
    if (c.is_constant() && d.is_constant() && d.constant_term() % c.constant_term() == 0)
      return false;
    auto rx = index_range(px.without(j), x.path, nx), ry = index_range(py.without(j), y.path, ny);
    if (!rx || !ry)
      return false;
    Facts facts = pair_facts(nx, x, ny, y);
    const Poly one = Poly::constant(1);
    // in the row: r >= 0 and c - 1 - r >= 0, for both
    std::vector<Poly> all = {rx->first, c - one - rx->second, ry->first, c - one - ry->second};
    // apart in a row: one of these >= 0
    Poly g1 = ry->first - rx->second - one, g2 = rx->first - ry->second - one;
    std::vector<std::vector<SizeCond>> must;
    for (const Poly& g : all)
      if (!prove_nonneg(g, facts)) {
        if (prove_nonneg(-g - one, facts))
          return false; // never holds
        must.push_back({SizeCond::nonneg(g)});
      }
    if (!prove_nonneg(g1, facts) && !prove_nonneg(g2, facts)) {
      if (prove_nonneg(-g1 - one, facts) && prove_nonneg(-g2 - one, facts))
        return false;
      must.push_back({SizeCond::nonneg(g1), SizeCond::nonneg(g2)});
    }
    if (!must.empty()) {
      SizeCheck chk;
      chk.premises = sorted_conds(facts_premises(nx, x, ny, y));
      chk.must_hold = must;
      chk.what =
          fmt::format("output '{}' is written by the stores on lines {} and {} at "
                      "elements {} and {} of rows of length {}, which must not overlap",
                      y.array, x.pos.line, y.pos.line, print_index(x), print_index(y), c.str());
      chk.pos = y.pos;
      k_.size_checks.push_back(chk);
    }
    return true;
  }

  CheckState& s_;
  Kernel& k_;
  const Accesses& a_;

  void fail(const SourcePos& at, const char* id, const std::string& msg) { s_.fail(at, id, msg); }
};

} // namespace

bool check_write_once(CheckState& s) { return WriteOnce(s).check_outputs(); }

} // namespace dpgen::checking
