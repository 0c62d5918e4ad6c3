// Emit (phase 6): the checked entry point `<kernel>_adjoint_checked`: the adjoint's
// parameters with each array followed by its element count. It computes, from
// the kernel's loop bounds and index expressions, the range of elements the
// kernel (and so its adjoint) touches in each array, throws
// std::invalid_argument naming the array, the range and the sizes when an
// array is too short (or an index would be negative), and then calls the raw
// adjoint. Arrays read at data-dependent indices, or under conditions that are
// not index ranges, cannot be bounded this way; the generated comment names
// them and they are not checked.
#include "emit_checked.hpp"

#include "accesses.hpp"
#include "derive.hpp"
#include "emit_util.hpp"
#include "print.hpp"
#include "prove.hpp"
#include "schedule.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace dpgen {

namespace {

// C++ for the smallest (`largest` false) or largest index `p` takes over one
// box of the nest's counters, or "" when a coefficient's sign is unknown. The
// value is a lambda call; an empty box gives no constraint (`fallback`).
std::string extreme(const Poly& p, const Box& box, const Nest& nest, bool largest,
                    const std::string& fallback) {
  Facts facts;
  for (const auto& l : nest.loops)
    add_nonempty(l, facts);
  std::vector<std::string> defs, nonempty;
  for (const auto& l : nest.loops) {
    Poly c = p.coefficient(Sym::counter(l.var));
    Interval iv;
    auto it = box.dims.find(l.var);
    if (it != box.dims.end())
      iv = it->second;
    iv.lo.push_back(*to_poly(l.lo));
    iv.hi.push_back(*to_poly(l.hi));
    std::string lo = print_max(iv.lo, kCellType), hi = print_min(iv.hi, kCellType);
    nonempty.push_back(fmt::format("{} < {}", lo, hi));
    if (c == Poly())
      continue;
    // The end of the counter's range that makes the index extreme: known
    // from the facts, or chosen by the coefficient's sign at run time.
    bool up = prove_nonneg(c, facts), down = prove_nonneg(-c, facts);
    std::string last = "(" + hi + ") - 1";
    std::string at;
    if (up || down)
      at = (up == largest) ? last : lo;
    else
      at = fmt::format("({}) >= 0 ? {} : {}", c.code(), largest ? last : lo, largest ? lo : last);
    defs.push_back(fmt::format("const {} {} = {};", kCellType, l.var, at));
  }
  if (nonempty.empty())
    return p.code(); // no counter: a fixed index (a[0], *xmin)
  std::string cond = fmt::format("{}", fmt::join(nonempty, " && "));
  return fmt::format("[&]() -> {} {{ if (!({})) return {}; {} return {}; }}()", kCellType, cond,
                     fallback, fmt::join(defs, " "), p.code());
}

struct Range {
  std::vector<std::string> lows, highs; // C++ for the extremes of each access
  bool bounded = true;
};

// The range of elements the kernel touches in each array (accesses.hpp): C++
// for the extremes of each access over each box of its iterations; unbounded
// where an access is data-dependent (its index, or a condition it happens
// under).
std::map<std::string, Range> access_ranges(const Kernel& k) {
  std::map<std::string, Range> ranges;
  const Nest none; // (the kernel-level locals' reads, before every loop)
  // Adds the extremes of one access to `r`; false where it cannot be bounded.
  auto add = [&](Range& r, const ArrayAccess& a) {
    auto pieces = index_pieces(a.index);
    if (!a.exact || !pieces)
      return false;
    const Nest& nest = a.nest ? *a.nest : none;
    for (const auto& piece : *pieces)
      for (const auto& box : intersect(a.where, piece.where)) {
        std::string lo = extreme(piece.value, box, nest, false, "0");
        std::string hi = extreme(piece.value, box, nest, true, "-1");
        if (lo.empty() || hi.empty())
          return false;
        // (the same extreme from another access is not repeated)
        if (std::find(r.lows.begin(), r.lows.end(), lo) == r.lows.end())
          r.lows.push_back(lo);
        if (std::find(r.highs.begin(), r.highs.end(), hi) == r.highs.end())
          r.highs.push_back(hi);
      }
    return true;
  };
  for (const auto& [array, accesses] : array_accesses(k)) {
    Range& r = ranges[array];
    r.bounded = std::all_of(accesses.begin(), accesses.end(),
                            [&](const ArrayAccess& a) { return add(r, a); });
  }
  return ranges;
}

// The number of elements of `array` as the checked entry point names it
// (<array>_size, or a fresh name where the kernel has one of that spelling).
std::string size_name(const Kernel& k, const std::string& array) {
  return k.fresh(array + "_size");
}

std::string checked_params(const Kernel& k) {
  std::vector<std::string> ps;
  for (const auto& p : k.params) {
    if (p.global)
      continue;
    std::string n = p.elem_name;
    const std::string adj = p.name + "_adj";
    switch (p.kind) {
    case ParamKind::In:
      ps.push_back(fmt::format("const {}* {}, size_t {}", n, p.name, size_name(k, p.name)));
      ps.push_back(fmt::format("{}* {}, size_t {}", n, adj, size_name(k, adj)));
      break;
    case ParamKind::Out:
      ps.push_back(fmt::format("const {}* {}, size_t {}", n, adj, size_name(k, adj)));
      break;
    case ParamKind::ConstArray:
      ps.push_back(fmt::format("const {}* {}, size_t {}", n, p.name, size_name(k, p.name)));
      break;
    case ParamKind::Scalar:
      ps.push_back(fmt::format("{} {}", p.spelling, p.name));
      break;
    }
  }
  return fmt::format("{}", fmt::join(ps, ", "));
}

} // namespace

bool has_checked_entry(const Kernel& k) {
  // (rows through pointers have no one size to check)
  // (rows through pointers and views have no flat size to check against)
  bool row_pointers = std::any_of(k.params.begin(), k.params.end(),
                                  [](const Param& p) { return p.row_pointers || p.view; });
  return !has_rows(k) && !has_inout(k) && !row_pointers;
}

std::string checked_signature(const Kernel& k) {
  return fmt::format("void {}_adjoint_checked({})", k.name, checked_params(k));
}

void emit_checked_entry(Code& code, const Kernel& k) {
  if (!has_checked_entry(k))
    return;
  auto ranges = access_ranges(k);
  std::vector<std::string> unchecked;
  for (const auto& p : k.params)
    if (p.kind != ParamKind::Scalar && !p.global && ranges.count(p.name) &&
        !ranges[p.name].bounded)
      unchecked.push_back(p.name);
  open_namespaces(code, k);
  code.line("// {}_adjoint with the size of every array, checked against the elements the "
            "kernel touches{}.",
            k.name,
            unchecked.empty() ? ""
                              : fmt::format(" (not checkable: {}, read at data-dependent indices "
                                            "or under data-dependent conditions)",
                                            fmt::join(unchecked, ", ")));
  code.open(checked_signature(k));
  std::vector<std::string> shown;
  for (const auto& p : k.params)
    if (p.kind == ParamKind::Scalar && p.elem == Type::Int && !p.synthetic)
      shown.push_back(shown_value(p));
  std::string sizes = shown.empty() ? "std::string()"
                                    : fmt::format("{}", fmt::join(shown, " + \", \" + "));
  // The integer locals the bounds may use (x_min = *xmin); not the real ones,
  // which would read arrays before their sizes are checked.
  define_kernel_locals(code, k, true);
  // A null adjoint (an inactive input) is not checked.
  auto check = [&](const std::string& array, const std::string& range, bool nullable) {
    const std::string lo = k.fresh(range + "_lo"), hi = k.fresh(range + "_hi");
    const std::string size = size_name(k, array);
    code.open(fmt::format("if ({}{} >= 0 && ({} < 0 || std::size_t({}) >= {}))",
                          nullable ? array + " != nullptr && " : "", hi, lo, hi, size));
    code.line("throw std::invalid_argument(std::string(\"{}_adjoint_checked: '{}' has \") + "
              "std::to_string({}) + \" elements, but the kernel touches elements \" + "
              "std::to_string({}) + \" to \" + std::to_string({}) + \" (\" + {} + \")\");",
              k.name, array, size, lo, hi, sizes);
    code.close();
  };
  std::vector<std::string> args;
  for (const auto& p : k.params) {
    if (p.global)
      continue;
    if (p.kind == ParamKind::Scalar) {
      args.push_back(p.name);
      continue;
    }
    auto it = ranges.find(p.name);
    bool checkable = it != ranges.end() && it->second.bounded && !it->second.highs.empty();
    if (checkable) {
      const Range& r = it->second;
      std::string range = p.name + "_range";
      code.line("const {} {} = std::min<{}>({{{}}});", kCellType, k.fresh(range + "_lo"),
                kCellType, fmt::join(r.lows, ", "));
      code.line("const {} {} = std::max<{}>({{{}}});", kCellType, k.fresh(range + "_hi"),
                kCellType, fmt::join(r.highs, ", "));
      if (p.kind != ParamKind::Out)
        check(p.name, range, false);
      if (p.kind != ParamKind::ConstArray)
        check(p.name + "_adj", range, p.kind == ParamKind::In);
    }
    if (p.kind == ParamKind::In) {
      args.push_back(p.name);
      args.push_back(p.name + "_adj");
    } else {
      args.push_back(p.kind == ParamKind::Out ? p.name + "_adj" : p.name);
    }
  }
  code.line("{}_adjoint({});", k.name, fmt::join(args, ", "));
  code.close();
  close_namespaces(code, k);
}

} // namespace dpgen
