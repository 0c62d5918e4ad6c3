// Check's parts (check.cpp: the driver, work and in-place arrays;
// check_write_once.cpp: the write-once rule; check_extents.cpp: the extents
// of the buffers the adjoint needs): the state they report through, and the
// ranges of indices and facts over loop boxes they share.
#pragma once

#include "affine.hpp"
#include "check.hpp"
#include "prove.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace dpgen {

// The rank of a row (1) or plane (2) symbol standing alone in a coefficient
// (ir.hpp: row_symbol); 0 for any other coefficient.
int level_rank(const Poly& c);
// The highest rank of a row or plane symbol in `p` (0: none).
int max_level_rank(const Poly& p);

namespace checking {

// The kernel being checked, what lowering recorded of its accesses, and
// where errors go (ok_ turns false at the first).
class CheckState {
public:
  CheckState(Kernel& k, const Accesses& a, Diagnostics& diag) : k_(k), a_(a), diag_(diag) {}

  Kernel& k_;
  const Accesses& a_;
  Diagnostics& diag_;
  bool ok_ = true;

  bool hidden(const std::string& array) const {
    return std::any_of(k_.hidden.begin(), k_.hidden.end(),
                       [&](const Param& h) { return h.name == array; });
  }

  // A work array as the user knows it: a hidden one is their accumulator.
  std::string work_name(const std::string& array) const {
    for (const auto& h : k_.hidden)
      if (h.name == array) {
        if (a_.buffers.count(array))
          return fmt::format("line buffer '{}'", h.spelling);
        if (h.name.rfind("dpgen_sum_", 0) == 0)
          return fmt::format("the sum in '{}' (read after the loop that adds to it)", h.spelling);
        return fmt::format("the min/max reduction '{}' (read after its loop)", h.spelling);
      }
    return fmt::format("work array '{}' (an output a later loop reads)", array);
  }

  // `id`, the rule broken (printed after the message): dpgen-write-once,
  // dpgen-read-after-write, dpgen-work-array, dpgen-inplace,
  // dpgen-output-index.
  void fail(const SourcePos& at, const char* id, const std::string& msg) {
    diag_.error(at, id, user_names(msg));
    ok_ = false;
  }

  // A message as the user reads it: a line buffer's hidden array named as
  // the kernel names the buffer, an in-place array's new values (its twin
  // `u_new`) as the array.
  std::string user_names(std::string msg) const {
    auto rename = [&](const std::string& from, const std::string& to) {
      for (size_t at = msg.find(from); at != std::string::npos; at = msg.find(from, at)) {
        msg.replace(at, from.size(), to);
        at += to.size();
      }
    };
    for (const auto& [array, b] : a_.buffers)
      for (const auto& [from, to] :
           {std::pair{"output '" + array + "'", "line buffer '" + b.name + "'"},
            std::pair{"work array '" + array + "'", "line buffer '" + b.name + "'"},
            std::pair{"'" + array + "'", "'" + b.name + "'"}})
        rename(from, to);
    for (const auto& p : k_.params)
      if (!p.twin_of.empty()) {
        rename("output '" + p.name + "'", "in-place array '" + p.twin_of + "'");
        rename("'" + p.name + "'", "'" + p.twin_of + "'");
      }
    return msg;
  }

  const Nest* nest_with_key(const std::vector<int>& key) const {
    for (const auto& n : k_.nests)
      if (n.key == key)
        return &n;
    return nullptr;
  }
};

// The write-once rule (check_write_once.cpp): each output element is written
// by exactly one iteration. False where an index is not affine or multiplies
// counters (the rules that need its range are left out then).
bool check_write_once(CheckState& s);

// A condition that has one value for the whole call (check.cpp, with the
// three below).
bool invariant(const ExprP& e);
// Two paths that never both run in one call.
bool exclusive(const std::vector<PathCond>& a, const std::vector<PathCond>& b);
// How many outer loops two nests share (the same `for` statements).
size_t shared_loops(const Nest& a, const Nest& b);
// What holds where two stores run: their loops run, their paths hold.
Facts pair_facts(const Nest& nx, const Store& x, const Nest& ny, const Store& y);

// [min, max] of a store's index over its loop box, when every counter's
// coefficient is a constant (check_extents.cpp, with the three below).
std::optional<std::pair<Poly, Poly>> index_range(const Store& s, const Nest& nest);
// [min, max] of an index over a loop box, when every counter's coefficient
// is a constant. (The sign of a coefficient that is a size, like nx in
// j * nx + i, is proved from the facts where the store runs.)
std::optional<std::pair<Poly, Poly>> index_range(Poly p, const std::vector<PathCond>& path,
                                                 const Nest& nest);
// What holds where a store on `path` in `nest` runs: its loops run, its
// path's conditions hold.
Facts where_runs(const std::vector<PathCond>& path, const Nest& nest);
// index_range's computation under `facts`.
std::optional<std::pair<Poly, Poly>> range_under(Poly p, const Facts& facts, const Nest& nest);

// The extents of the outputs the adjoint keeps in buffers (work arrays,
// in-place arrays, line buffers): Kernel::extent, and the SizeChecks their
// assumptions need (check_extents.cpp).
class Extents {
public:
  explicit Extents(CheckState& s) : s_(s), k_(s.k_), a_(s.a_) {}
  void output_extents();

private:
  CheckState& s_;
  Kernel& k_;
  const Accesses& a_;

  void fail(const SourcePos& at, const char* id, const std::string& msg) { s_.fail(at, id, msg); }
  const Nest* nest_with_key(const std::vector<int>& key) const { return s_.nest_with_key(key); }
  std::string work_name(const std::string& array) const { return s_.work_name(array); }
  bool is_view(const std::string& array) const;
  void view_outputs_located();
  std::optional<std::pair<Poly, Poly>> extent_range(const Poly& p, const std::vector<PathCond>& path,
                                                    const Nest& nest, const SourcePos& pos,
                                                    const std::string& array);
  static Extent::End counted_where_run(const Poly& last, const ExprP& index,
                                       const std::vector<PathCond>& path, const Nest& n);
};

} // namespace checking
} // namespace dpgen
