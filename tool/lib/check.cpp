// Check (the end of phase 2): the output rules of check.hpp, proved on the
// lowered loop nests and stores. Every violation is reported, once per store
// or read, at the SourcePos it concerns, and the kernel is dropped.
#include "check.hpp"
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

namespace dpgen {

namespace checking {

// A condition that has one value for the whole call: parameters, integer
// constants and kernel-level locals computed from them (no counter, no
// array element).
bool invariant(const ExprP& e) {
  return !any_node(e, [](const ExprP& x) {
    return x->op == Op::LoopVar || x->op == Op::Read ||
           (x->op == Op::Local && !x->local->kernel_level);
  });
}

// Two paths that never both run in one call: one holds an invariant
// condition the other denies (the arms of `if (predict == 0) ... else ...`),
// or both hold `x == a` and `x == b` for different constants a and b (an
// `if (dir == X_DIR) ... else if (dir == Y_DIR)` chain, or two such ifs).
// The output rules hold for each arm alone: an arm that does not run writes
// nothing.
bool exclusive(const std::vector<PathCond>& a, const std::vector<PathCond>& b) {
  for (const auto& x : a)
    for (const auto& y : b) {
      if (!invariant(x.cond) || !invariant(y.cond))
        continue;
      if (x.positive != y.positive && same(x.cond, y.cond))
        return true;
      // `flag != 0` against `flag == 0`: one holds where the other fails
      auto equality = [](const PathCond& pc) -> std::optional<bool> {
        if (pc.cond->op == Op::Eq)
          return pc.positive;
        if (pc.cond->op == Op::Ne)
          return !pc.positive;
        return std::nullopt;
      };
      auto ex = equality(x), ey = equality(y);
      if (ex && ey && *ex != *ey && same(x.cond->ops[0], y.cond->ops[0]) &&
          same(x.cond->ops[1], y.cond->ops[1]))
        return true;
      if (x.positive && y.positive && x.cond->op == Op::Eq && y.cond->op == Op::Eq)
        for (int i = 0; i < 2; ++i)
          for (int j = 0; j < 2; ++j) {
            const ExprP &cx = x.cond->ops[1 - i], &cy = y.cond->ops[1 - j];
            if (same(x.cond->ops[i], y.cond->ops[j]) && cx->op == Op::IntConst &&
                cy->op == Op::IntConst && cx->ival != cy->ival)
              return true;
          }
    }
  return false;
}

// How many outer loops two nests share (the same `for` statements).
size_t shared_loops(const Nest& a, const Nest& b) {
  size_t n = 0;
  while (n < a.key.size() && n < b.key.size() && a.key[n] == b.key[n])
    ++n;
  return n;
}

// What holds where two stores run: their loops run, their paths hold.
Facts pair_facts(const Nest& nx, const Store& x, const Nest& ny, const Store& y) {
  Facts facts;
  for (const Nest* n : {&nx, &ny})
    for (const auto& l : n->loops)
      add_nonempty(l, facts);
  for (const Store* st : {&x, &y})
    for (const auto& pc : st->path)
      add_facts(pc, facts);
  return facts;
}

} // namespace checking

namespace {

using namespace checking;

class Checker : public CheckState {
public:
  Checker(Kernel& k, const Accesses& a, Diagnostics& diag) : CheckState(k, a, diag) {}

  // Every rule in turn, each reporting every violation it finds (one per
  // store or read). Where an output index is not affine, or multiplies
  // counters, the rules that need its range (the rest of the write-once
  // rule, the extents) are left out.
  bool run() {
    check_intermediates();
    check_inout();
    if (check_write_once(*this))
      Extents(*this).output_extents(); // check_extents.cpp
    for (auto& c : k_.size_checks)
      c.what = user_names(c.what);
    return ok_;
  }

private:
  // An in-place array is read, where it is also written, only at the element
  // its iteration writes (anything else reads a value another iteration may
  // have updated: Gauss-Seidel), and never after a loop that wrote it.
  void check_inout() {
    // Where an in-place array is written decides which seeds pass through;
    // the adjoint's entry evaluates that before anything is recomputed, so
    // the condition may not read what the kernel computes (a sum, a work
    // array) in an earlier loop.
    for (const auto& p : k_.params) {
      if (!p.inout)
        continue;
      const std::string twin = p.name + "_new";
      for (const auto& n : k_.nests)
        for (const auto& st : n.stores) {
          if (st.array != twin)
            continue;
          for (const auto& pc : st.path) {
            const Expr* computed = nullptr;
            any_node(pc.cond, [&](const ExprP& x) {
              if (x->op == Op::Read && (hidden(x->name) || k_.intermediates.count(x->name)))
                computed = x.get();
              return computed != nullptr;
            });
            if (!computed)
              continue;
            fail(st.pos, "dpgen-inplace",
                 fmt::format("in-place array '{}' is updated under a condition on {}, which "
                             "the kernel computes in an earlier loop: the adjoint decides which "
                             "elements pass through before it recomputes that; write the new "
                             "values to a separate DPGEN_OUT array, or make the update "
                             "unconditional (a select of the two values)",
                             p.name, work_name(computed->name)));
            break;
          }
        }
    }
    for (const auto& r : a_.inout_reads)
      for (const auto& s : a_.inout_stores) { // the first store it conflicts with
        if (s.array != r.array)
          continue;
        size_t shared = 0;
        while (shared < s.nest_key.size() && shared < r.nest_key.size() &&
               s.nest_key[shared] == r.nest_key[shared])
          ++shared;
        bool same_nest = s.nest_key == r.nest_key;
        auto ps = to_poly(s.index), pr = to_poly(r.index);
        bool same_cell = ps && pr && *ps == *pr;
        if ((same_nest && !same_cell) || (!same_nest && (shared > 0 || r.seq > s.seq))) {
          fail(r.pos, "dpgen-inplace", fmt::format("in-place array '{}' is read here at an element another "
                                  "iteration or loop may already have updated: a value carried "
                                  "through the array (Gauss-Seidel, an in-place stencil) is "
                                  "outside the kernel subset; read only the element each "
                                  "iteration writes, or write the new values to a separate "
                                  "DPGEN_OUT array",
                                  r.array));
          break;
        }
      }
  }

  // An intermediate is written before it is read, by nests that do not share
  // a loop with the nests that read it (a buffer refilled per row would hold
  // only the last row when the adjoint recomputes it), and no nest both
  // writes it and reads it.
  void check_intermediates() {
    // A work array's first store must set it: starting from '+=' adds to the
    // caller's contents, which the adjoint cannot recompute.
    for (const auto& w : k_.intermediates) {
      const Store* first = nullptr;
      for (const auto& n : k_.nests)
        for (const auto& st : n.stores)
          if (st.array == w && (!first || st.seq < first->seq))
            first = &st;
      if (first && first->accumulate)
        fail(first->pos, "dpgen-work-array", fmt::format("work array '{}' (read by a later loop) is first written "
                                     "with '+=': it adds to the caller's contents, which the "
                                     "adjoint cannot recompute; set it with '=' first",
                                     w));
    }
    // A work array read outside every loop into a local would be needed by
    // every nest's adjoint; only stores outside loops may read it directly.
    for (const auto& [array_name, at] : a_.kernel_level_work_reads)
      for (const auto& l : k_.kernel_locals) {
        const std::string& array = array_name; // (a lambda captures no structured binding in C++17)
        if (any_node(l->def,
                     [&](const ExprP& x) { return x->op == Op::Read && x->name == array; })) {
          fail(at, "dpgen-work-array", fmt::format("a local outside every loop reads work array '{}'; use the "
                               "element directly in the store, or read it inside a loop",
                               array));
          break;
        }
      }
    for (const auto& r : a_.work_reads)
      check_work_read(r);
  }

  // One read of a work array against the stores to it: the first rule it
  // breaks.
  void check_work_read(const Access& r) {
    for (const auto& n : k_.nests)
      for (const auto& st : n.stores) {
        if (st.array != r.array || exclusive(r.path, st.path))
          continue;
        size_t shared = 0;
        while (shared < n.key.size() && shared < r.nest_key.size() &&
               n.key[shared] == r.nest_key[shared])
          ++shared;
        if (st.seq >= r.seq && n.key == r.nest_key && r.index && same_index(r.index, st.index)) {
          // Read after a loop wrote the array, then written again at the
          // same element: an element holding two values in turn
          // (`s[0] += ...` in a loop, then `s[0] = sqrt(s[0])`).
          const Store* before = nullptr;
          for (const auto& m : k_.nests)
            for (const auto& e : m.stores)
              if (e.array == r.array && e.seq < r.seq && (!before || e.seq > before->seq))
                before = &e;
          if (before)
            return fail(r.pos, "dpgen-read-after-write", fmt::format("output '{}' is read here after line {} wrote it, "
                                           "and written again on line {}: an output holds one "
                                           "value per element, and the adjoint cannot tell the "
                                           "two apart; put the first value in a DPGEN_OUT work "
                                           "array of its own (`sum[0] += ...;` then "
                                           "`{}[0] = f(sum[0]);`)",
                                           r.array, before->pos.line, st.pos.line, r.array));
        }
        if (st.seq >= r.seq || n.key == r.nest_key)
          return fail(r.pos, "dpgen-read-after-write", fmt::format("output '{}' is read here and written on line {}, in "
                                         "the same loop or later: a value carried from one "
                                         "iteration to the next through an output (a "
                                         "recurrence, like a prefix sum, or an in-place "
                                         "update) is outside the kernel subset; write the new "
                                         "values to another array",
                                         r.array, st.pos.line));
        // (an accumulator's hidden array has an element per iteration of the
        // shared loops: recomputing it once for the whole kernel is right)
        if (shared > 0 && !hidden(r.array))
          return fail(r.pos, "dpgen-work-array", fmt::format("work array '{}' is written (line {}) and read inside "
                                         "the same outer loop: dpgen recomputes work arrays "
                                         "once for the whole kernel; write it in a loop nest of "
                                         "its own, or use a local array",
                                         r.array, st.pos.line));
      }
  }
};

} // namespace

int level_rank(const Poly& c) {
  if (c.terms().size() != 1)
    return 0;
  const auto& [m, k] = *c.terms().begin();
  if (m.size() != 1 || (k != 1 && k != -1) || m[0].is_counter())
    return 0;
  return level_of_symbol(m[0].name);
}

int max_level_rank(const Poly& p) {
  int rank = 0;
  for (const auto& [m, k] : p.terms())
    for (const Sym& s : m)
      if (!s.is_counter())
        rank = std::max(rank, level_rank(Poly::of(s)));
  return rank;
}

bool same_index(const ExprP& a, const ExprP& b) {
  auto pa = to_poly(a), pb = to_poly(b);
  return pa && pb ? *pa == *pb : same(a, b);
}

bool check_kernel(Kernel& k, const Accesses& accesses, Diagnostics& diag) {
  return Checker(k, accesses, diag).run();
}

} // namespace dpgen
