// Check (the end of phase 2), the extents part: how far each output the
// adjoint keeps in a buffer reaches (work arrays, in-place arrays, line
// buffers), so the staged adjoint can size its buffers (Kernel::extent), with
// the SizeChecks its assumptions need; a view output is located at run time
// instead (dpgen/view_buffer.hpp), where its stores' conditions allow it.
#include "check_impl.hpp"
#include "ir_walk.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <set>

namespace dpgen::checking {

std::optional<std::pair<Poly, Poly>> index_range(const Store& s, const Nest& nest) {
  return index_range(*to_poly(s.index), s.path, nest);
}

std::optional<std::pair<Poly, Poly>> index_range(Poly p, const std::vector<PathCond>& path,
                                                 const Nest& nest) {
  return range_under(std::move(p), where_runs(path, nest), nest);
}

Facts where_runs(const std::vector<PathCond>& path, const Nest& nest) {
  Facts facts;
  for (const auto& l : nest.loops)
    add_nonempty(l, facts);
  for (const auto& pc : path)
    add_facts(pc, facts);
  return facts;
}

std::optional<std::pair<Poly, Poly>> range_under(Poly p, const Facts& facts, const Nest& nest) {
  Poly lo, hi;
  for (const auto& l : nest.loops) {
    Poly c = p.coefficient(Sym::counter(l.var));
    bool up = prove_nonneg(c, facts);
    if (!up && !prove_nonneg(-c, facts))
      return std::nullopt;
    Poly first = *to_poly(l.lo), last = *to_poly(l.hi) - Poly::constant(1);
    lo = lo + c * (up ? first : last);
    hi = hi + c * (up ? last : first);
    p = p.without(Sym::counter(l.var));
  }
  return std::pair{lo + p, hi + p};
}

// index_range for the buffers of output_extents: where the sign of a
// counter's coefficient is not provable from the facts (a row length nx
// where the loops only say nx >= 2 * d + 1, and d may be negative), it is
// taken as nonnegative and checked on entry (a SizeCheck: the buffer would
// be too small otherwise). Only coefficients of sizes the generated code
// can evaluate (no row or plane symbol of a view or row pointers).
std::optional<std::pair<Poly, Poly>> Extents::extent_range(const Poly& p,
                                                           const std::vector<PathCond>& path,
                                                           const Nest& nest, const SourcePos& pos,
                                                           const std::string& array) {
  if (auto r = index_range(p, path, nest))
    return r;
  const Facts facts = where_runs(path, nest);
  std::vector<Poly> assumed;
  for (const auto& l : nest.loops) {
    Poly c = p.coefficient(Sym::counter(l.var));
    if (prove_nonneg(c, facts) || prove_nonneg(-c, facts))
      continue;
    if (c.mentions_any_counter() || max_level_rank(c) > 0 || !to_poly(l.lo) || !to_poly(l.hi))
      return std::nullopt;
    assumed.push_back(c);
  }
  Facts more = facts;
  for (const auto& c : assumed)
    more.push_back(c);
  auto range = range_under(p, more, nest); // with the assumed signs
  if (!range)
    return std::nullopt;
  for (const auto& c : assumed) {
    SizeCheck chk;
    std::vector<SizeCond> prem;
    for (const auto& l : nest.loops)
      prem.push_back(SizeCond::runs(*to_poly(l.lo), *to_poly(l.hi)));
    for (const auto& pc : path) {
      Facts f;
      add_facts(pc, f);
      for (const auto& q : f)
        prem.push_back(SizeCond::nonneg(q));
    }
    chk.premises = sorted_conds(prem);
    chk.must_hold = {{SizeCond::nonneg(c)}};
    chk.what = fmt::format("the elements of '{}' lie at increasing indices along each loop "
                           "(index coefficient '{}' not negative), which the adjoint's buffer "
                           "for it assumes",
                           array, c.str());
    chk.pos = pos;
    bool dup = false;
    for (const auto& o : k_.size_checks)
      dup = dup || o.same_as(chk);
    if (!dup)
      k_.size_checks.push_back(chk);
  }
  return range;
}

bool Extents::is_view(const std::string& array) const {
  const Param* p = k_.find_param(array);
  return p && p->view;
}

// The staged adjoint finds the elements of a view output (and of its
// reads, for a work array) by running the stores' loops before the forward
// does (emit_staged.cpp: emit_view_cover): each store to a view output must run
// where conditions over what the kernel does not write say, at an index of
// the same.
void Extents::view_outputs_located() {
  std::set<std::string> written;
  for (const auto& n : k_.nests)
    for (const auto& st : n.stores)
      written.insert(st.array);
  for (const auto& h : k_.hidden)
    written.insert(h.name);
  auto reads_written = [&](const ExprP& e) {
    return any_node(e, [&](const ExprP& x) {
      return x->op == Op::Read && written.count(x->name) > 0;
    });
  };
  for (const auto& n : k_.nests)
    for (const auto& st : n.stores) {
      auto reads_view_work = [&](const ExprP& e) {
        return any_node(e, [&](const ExprP& x) {
          return x->op == Op::Read && is_view(x->name) && k_.intermediates.count(x->name) > 0;
        });
      };
      // (a view work array read by the store's own condition: the condition
      // cannot run before the recompute, and its read must be covered too)
      bool touches_view = is_view(st.array) || reads_view_work(st.value);
      for (const auto& pc : st.path)
        touches_view = touches_view || reads_view_work(pc.cond);
      if (!touches_view)
        continue;
      bool bad = reads_written(st.index);
      for (const auto& pc : st.path)
        bad = bad || reads_written(pc.cond);
      if (bad)
        fail(st.pos, "dpgen-work-array",
             fmt::format("this store {} a view the adjoint recomputes into a buffer of its "
                         "own (laid out like the view's seed), under a condition that reads what "
                         "the kernel writes: the adjoint finds the buffer's elements before it "
                         "recomputes them; make the condition read inputs only",
                         is_view(st.array) ? "writes" : "reads"));
    }
}

// One past `last`, the largest index of an access at `index` in nest `n`
// under `path`, counted where the access runs: the loops around it that leave
// its element alone run, its conditions on the sizes hold.
Extent::End Extents::counted_where_run(const Poly& last, const ExprP& index,
                                       const std::vector<PathCond>& path, const Nest& n) {
  Extent::End end{{}, last + Poly::constant(1)};
  auto add = [&](const SizeCond& c) {
    if (std::none_of(end.runs.begin(), end.runs.end(),
                     [&](const SizeCond& o) { return o.code() == c.code(); }))
      end.runs.push_back(c);
  };
  auto pi = to_poly(index);
  for (const auto& l : n.loops)
    if (pi && !pi->mentions_counter(l.var) && to_poly(l.lo) && to_poly(l.hi))
      add(SizeCond::runs(*to_poly(l.lo), *to_poly(l.hi)));
  for (const auto& pc : path) {
    Facts facts;
    add_facts(pc, facts);
    for (const Poly& p : facts)
      if (!p.mentions_any_counter())
        add(SizeCond::nonneg(p));
  }
  return end;
}

// One past the largest index each output's stores reach, for the buffers
// of an adjoint that recomputes the forward kernel (work arrays).
void Extents::output_extents() {
  // A line buffer: a row of its length per iteration of its row loops
  // (lowering proves, or checks on entry, that every element it writes
  // lies in its row, and reads only what was written). The tangent needs
  // it also where no later loop reads the buffer.
  for (const auto& [array, b] : a_.buffers) {
    Extent e;
    e.row_length = *to_poly(b.length);
    for (const auto& x : b.extents)
      e.rows.push_back(*to_poly(x));
    k_.extent[array] = e;
  }
  bool inout =
      std::any_of(k_.params.begin(), k_.params.end(), [](const Param& p) { return p.inout; });
  if (k_.intermediates.empty() && !inout)
    return;
  for (const auto& p : k_.params)
    if (k_.intermediates.count(p.name) && p.row_pointers)
      fail(k_.pos, "dpgen-work-array", fmt::format("work array '{}' (an output a later loop reads) has "
                               "row pointers: the adjoint recomputes work arrays "
                               "into flat buffers; pass it as a flat pointer or "
                               "'double (*{})[N]'",
                               p.name, p.name));
  // A view output is recomputed into a ViewBuffer (dpgen/view_buffer.hpp)
  // laid out like its seed: the elements it covers are found at run time by
  // the stores and reads themselves, before the forward runs, so where they
  // run must not depend on what the kernel writes.
  if (!k_.intermediates.empty())
    view_outputs_located();
  // (a flat std::vector's work arrays are buffers of its size; rows of their own have none)
  bool nested = false;
  for (const auto& p : k_.params)
    if (!k_.intermediates.empty() && p.nested) {
      fail(k_.pos, "dpgen-work-array",
           fmt::format("{} in a kernel with rows of their own ('{}', a {}): pass the arrays "
                       "as flat std::vector or pointers",
                       work_name(*k_.intermediates.begin()), p.name, p.container));
      nested = true;
    }
  if (nested)
    return;
  std::map<std::string, Extent> ends;
  for (const auto& n : k_.nests)
    for (const auto& st : n.stores) {
      if (a_.buffers.count(st.array) || is_view(st.array))
        continue;
      auto r = extent_range(*to_poly(st.index), st.path, n, st.pos, st.array);
      if (!r) {
        fail(st.pos, "dpgen-output-index", fmt::format("cannot bound the indices of output '{}', which the "
                                 "adjoint needs buffers for (a work array or an in-place "
                                 "array)",
                                 st.array));
        continue;
      }
      // A store at an element that stays while a loop around it runs (a
      // sum, a pinned store) reaches it only if that loop runs: an
      // in-place array's seed copy must not read u_adj[0] of an empty one.
      ends[st.array].add(counted_where_run(r->second, st.index, {}, n));
    }
  // A later loop may read a work array beyond what was written (the
  // buffer holds NaN there): the buffer covers the reads too.
  for (const auto& r : a_.work_reads) {
    const Nest* reader = nest_with_key(r.nest_key);
    if (!reader || a_.buffers.count(r.array))
      continue;
    if (!to_poly(r.index)) {
      fail(r.pos, "dpgen-work-array", fmt::format("cannot bound this read of work array '{}', which the adjoint "
                              "recomputes into a buffer",
                              r.array));
      continue;
    }
    if (!is_view(r.array)) { // (a view's buffer covers its reads at run time)
      auto range = extent_range(*to_poly(r.index), r.path, *reader, r.pos, r.array);
      if (!range) {
        fail(r.pos, "dpgen-work-array", fmt::format("cannot bound this read of work array '{}', which the "
                                "adjoint recomputes into a buffer",
                                r.array));
        continue;
      }
      // (a read under a guard on the sizes, `if (n > 1) ... w[1]`, where it runs:
      // the seed copy must not read w_adj[1] of a shorter one)
      ends[r.array].add(counted_where_run(range->second, r.index, r.path, *reader));
    }
    // Provably outside every earlier store's range: an element no loop
    // writes, whose value is the caller's (the adjoint's buffer has NaN).
    // A read that moves over component planes (`f[l * P + k * (nx + 1) +
    // i]` for l = 0..3, each plane written by a store of its own) is
    // tested one plane at a time: for each value of a loop counter with
    // constant bounds (a few values), the read at that value against
    // every store.
    Poly rp = *to_poly(r.index);
    std::vector<Poly> parts = {rp};
    for (const auto& l : reader->loops) {
      auto lo = to_poly(l.lo), hi = to_poly(l.hi);
      Sym v = Sym::counter(l.var);
      Poly c = rp.coefficient(v);
      if (!lo || !hi || !lo->is_constant() || !hi->is_constant() || c == Poly() ||
          c.mentions_any_counter())
        continue;
      long long a = lo->constant_term(), b = hi->constant_term();
      if (b - a < 1 || (b - a) * (long long)parts.size() > 64)
        continue;
      std::vector<Poly> next;
      for (const Poly& q : parts)
        for (long long x = a; x < b; ++x)
          next.push_back(q.without(v) + q.coefficient(v) * Poly::constant(x));
      parts = std::move(next);
    }
    bool unwritten = false, any_store = false;
    for (const Poly& part : parts) {
      auto pr = index_range(part, r.path, *reader);
      if (!pr)
        continue;
      bool outside_all = true;
      for (const auto& n : k_.nests)
        for (const auto& st : n.stores) {
          if (st.array != r.array)
            continue;
          any_store = true;
          auto w = index_range(st, n);
          Facts facts;
          for (const Nest* m : {&n, reader})
            for (const auto& l : m->loops)
              add_nonempty(l, facts);
          Poly one = Poly::constant(1);
          bool outside = w && (prove_nonneg(pr->second - w->second - one, facts) ||
                               prove_nonneg(w->first - pr->first - one, facts));
          outside_all = outside_all && outside;
        }
      unwritten = unwritten || outside_all;
    }
    if (any_store && unwritten)
      fail(r.pos, "dpgen-work-array", fmt::format("reads work array '{}' at elements no earlier loop writes (their "
                              "values are the caller's, which the adjoint cannot recompute); "
                              "write every element a later loop reads",
                              r.array));
  }
  for (auto& [array, e] : ends)
    k_.extent[array] = std::move(e);
}

} // namespace dpgen::checking
