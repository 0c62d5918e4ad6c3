// The accesses of every array (accesses.hpp).
#include "accesses.hpp"

#include "derive.hpp"
#include "prove.hpp"

namespace dpgen {

namespace {

// The reads of `e` (derive.hpp: reads_in), each where the store happens and
// the conditions of the conditional expressions around it hold; inexact
// where one of those is not an index range.
void add_reads(std::map<std::string, std::vector<ArrayAccess>>& out, const ExprP& e,
               const Nest* nest, const Domain& where, bool exact) {
  for (const auto& site : reads_in(e)) {
    Domain d = where;
    bool ex = exact;
    for (const auto& pc : site.conds) {
      auto cd = condition_domain(pc.cond);
      if (!cd) {
        ex = false;
        continue;
      }
      d = pc.positive ? intersect(d, *cd) : subtract(d, *cd);
    }
    if (!d.empty())
      out[site.read->name].push_back({site.read->ops[0], nest, d, ex});
  }
}

} // namespace

std::map<std::string, std::vector<ArrayAccess>> array_accesses(const Kernel& k) {
  std::map<std::string, std::vector<ArrayAccess>> out;
  for (const auto& nest : k.nests)
    for (const auto& st : nest.stores) {
      std::vector<PathCond> guards; // (conditions that are not index ranges)
      const Domain where = store_domain(nest, st, guards);
      const bool exact = guards.empty();
      if (where.empty())
        continue;
      out[st.array].push_back({st.index, &nest, where, exact});
      add_reads(out, st.value, &nest, where, exact);
      add_reads(out, st.index, &nest, where, exact);
      for (const auto& pc : st.path)
        add_reads(out, pc.cond, &nest, where, exact);
    }
  // Reads before every loop (a0 = a[0], x_min = *xmin) always happen.
  const Nest none;
  std::vector<PathCond> no_guards;
  const Domain top = store_domain(none, Store{}, no_guards); // (one point)
  for (const auto& l : k.kernel_locals)
    add_reads(out, l->def, nullptr, top, true);
  return out;
}

} // namespace dpgen
