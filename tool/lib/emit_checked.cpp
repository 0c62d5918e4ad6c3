// Emit (phase 6): the checked entry point `<kernel>_adjoint_checked`: the adjoint's
// parameters with each array followed by its element count. It computes, from
// the kernel's loop bounds and index expressions, the range of elements the
// kernel (and so its adjoint) touches in each array, throws
// std::invalid_argument naming the array, the range and the sizes when an
// array is too short (or an index would be negative), and then calls the raw
// adjoint. Where what the kernel touches depends on the data (an index computed
// from values, a read under a condition on values), the range over the loop
// bounds holds it; where that range does not fit, or an index cannot be bounded
// at all, the kernel's loops run once, printed from the IR with checking
// stand-ins for those arrays (dpgen/checked_probe.hpp), and each such index is
// checked before it is used.
#include "emit_checked.hpp"

#include "accesses.hpp"
#include "derive.hpp"
#include "emit_forward.hpp"
#include "emit_util.hpp"
#include "print.hpp"
#include "prove.hpp"
#include "schedule.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <set>

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
  // C++ for the extremes of each access that happens at every iteration of its box
  std::vector<std::string> lows, highs;
  // ... and of those that happen under a condition on the data: what the kernel
  // touches is within them, maybe not all of them
  std::vector<std::string> maybe_lows, maybe_highs;
  bool dependent = false; // an index that cannot be bounded from the loop bounds
};

void add_unique(std::vector<std::string>& v, const std::string& x) {
  if (std::find(v.begin(), v.end(), x) == v.end())
    v.push_back(x);
}

// The range of elements the kernel touches in each array (accesses.hpp): C++
// for the extremes of each access over each box of its iterations.
std::map<std::string, Range> access_ranges(const Kernel& k) {
  std::map<std::string, Range> ranges;
  const Nest none; // (the kernel-level locals' reads, before every loop)
  // Adds the extremes of one access to `r`; false where it cannot be bounded.
  auto add = [&](Range& r, const ArrayAccess& a) {
    auto pieces = index_pieces(a.index);
    if (!pieces)
      return false;
    const Nest& nest = a.nest ? *a.nest : none;
    for (const auto& piece : *pieces)
      for (const auto& box : intersect(a.where, piece.where)) {
        std::string lo = extreme(piece.value, box, nest, false, "0");
        std::string hi = extreme(piece.value, box, nest, true, "-1");
        if (lo.empty() || hi.empty())
          return false;
        add_unique(a.exact ? r.lows : r.maybe_lows, lo);
        add_unique(a.exact ? r.highs : r.maybe_highs, hi);
      }
    return true;
  };
  for (const auto& [array, accesses] : array_accesses(k)) {
    Range& r = ranges[array];
    for (const auto& a : accesses)
      r.dependent = !add(r, a) || r.dependent;
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

namespace {

// Whether the probe can run the kernel's loops: it writes nothing of the caller's, so what
// later loops read back (work arrays, accumulators' sums) it keeps in buffers of its own,
// whose sizes the generator must know (Kernel::extent).
bool can_probe(const Kernel& k) {
  auto sized = [&](const std::string& a) { return k.extent.count(a) > 0; };
  return has_checked_entry(k) &&
         std::all_of(k.intermediates.begin(), k.intermediates.end(), sized) &&
         std::all_of(k.hidden.begin(), k.hidden.end(),
                     [&](const Param& h) { return sized(h.name); });
}

// The arrays whose elements touched depend on the data: the probe checks them where it can
// run, else they are `unchecked`.
std::set<std::string> uncertain_arrays(const Kernel& k, const std::map<std::string, Range>& ranges,
                                       std::vector<std::string>* unchecked) {
  std::set<std::string> probed;
  const bool probe = can_probe(k);
  for (const auto& p : k.params) {
    auto it = ranges.find(p.name);
    if (p.kind == ParamKind::Scalar || p.global || it == ranges.end())
      continue;
    if (!it->second.dependent && it->second.maybe_highs.empty())
      continue;
    if (probe)
      probed.insert(p.name);
    else if (unchecked)
      unchecked->push_back(p.name);
  }
  return probed;
}

// The name of the probe's function (see the top of this file).
std::string probe_name(const Kernel& k) { return k.name + "_probe"; }

// What the probe is given for each of the kernel's parameters, in order: a checking stand-in
// (dpgen/checked_probe.hpp) for an array in `probed`, an output (which the checked entry point
// has as its seed only) or an array of the kernel's own (Kernel::hidden); else the parameter.
struct ProbeArg {
  const Param* p;
  bool stand_in;
  bool hidden = false; // (one of Kernel::hidden)
};
std::vector<ProbeArg> probe_args(const Kernel& k, const std::set<std::string>& probed) {
  std::vector<ProbeArg> out;
  for (const auto& p : k.params)
    if (!p.global)
      out.push_back({&p, p.kind == ParamKind::Out || probed.count(p.name) > 0});
  for (const auto& h : k.hidden)
    out.push_back({&h, true, true});
  return out;
}

// `static void <kernel>_probe(...)`: the kernel's loops printed from its IR (serial), each
// array in `probed`, each output and each array of its own a stand-in, so each index into
// them is checked before it is used and nothing of the caller's is written.
void emit_probe_function(Code& code, const ForwardPlan& plan, const std::set<std::string>& probed) {
  const Kernel& k = *plan.kernel;
  std::vector<std::string> ps;
  for (const auto& [p, stand_in, hidden] : probe_args(k, probed))
    ps.push_back(stand_in ? fmt::format("const dpgen::{}<{}>& {}",
                                        p->kind == ParamKind::Out ? "ProbeOutput" : "ProbeInput",
                                        p->elem_name, p->name)
                 : p->kind == ParamKind::Scalar
                     ? fmt::format("{} {}", p->spelling, p->name)
                     : fmt::format("const {}* {}", p->elem_name, p->name));
  std::vector<std::string> what(probed.begin(), probed.end());
  code.line("// {} run for {}_adjoint_checked where what it touches of {} depends on the data "
            "(dpgen/checked_probe.hpp): each index into {} and into the outputs checked "
            "before it is used, nothing of the caller's written.",
            k.name, k.name, fmt::join(what, ", "), fmt::join(what, ", "));
  code.open(fmt::format("static void {}({})", probe_name(k), fmt::join(ps, ", ")));
  define_kernel_locals(code, k);
  ForwardOptions serial;
  serial.threads = false;
  emit_forward_nests(code, plan, serial, false);
  code.close();
  code.raw("\n");
}

// The call of the probe in the checked entry point, where `needed` (C++) holds.
void emit_probe_call(Code& code, const Kernel& k, const std::set<std::string>& probed,
                     const std::string& needed, const std::string& sizes) {
  const std::string shown = k.fresh("shown"), site = k.fresh("site");
  std::vector<std::string> args;
  std::vector<std::pair<const Param*, std::string>> kept; // (buffers of what later loops read)
  for (const auto& [p, stand_in, hidden] : probe_args(k, probed)) {
    const std::string adj = p->name + "_adj";
    if (!stand_in) {
      args.push_back(p->name);
    } else if (hidden || k.intermediates.count(p->name)) {
      kept.emplace_back(p, k.fresh(p->name + "_kept"));
      const std::string& buf = kept.back().second;
      const std::string seed = hidden ? buf + ".data()" : adj;
      const std::string size = hidden ? buf + ".size()" : size_name(k, adj);
      args.push_back(fmt::format("dpgen::ProbeOutput<{}>({}, {}, {}, {}, {}.data(), {}.size())",
                                 p->elem_name, site, literal(hidden ? p->name : adj), seed, size,
                                 buf, buf));
    } else if (p->kind == ParamKind::Out) {
      args.push_back(fmt::format("dpgen::ProbeOutput<{}>({}, {}, {}, {})", p->elem_name, site,
                                 literal(adj), adj, size_name(k, adj)));
    } else if (p->kind == ParamKind::In) {
      args.push_back(fmt::format("dpgen::ProbeInput<{}>({}, {}, {}, {}, {}, {}, {})", p->elem_name,
                                 site, literal(p->name), p->name, size_name(k, p->name),
                                 literal(adj), adj, size_name(k, adj)));
    } else {
      args.push_back(fmt::format("dpgen::ProbeInput<{}>({}, {}, {}, {})", p->elem_name, site,
                                 literal(p->name), p->name, size_name(k, p->name)));
    }
  }
  std::vector<std::string> what(probed.begin(), probed.end());
  code.line("// {}: what the kernel touches depends on the data. Where the ranges above do not "
            "settle it, its loops run once ({}), writing nothing, with each index into {} and "
            "the outputs checked before it is used.",
            fmt::join(what, ", "), probe_name(k), what.size() == 1 ? "it" : "them");
  code.open(needed == "true" ? std::string() : fmt::format("if ({})", needed));
  code.line("const std::string {} = {};", shown, sizes);
  code.line("const dpgen::ProbeSite {}{{{}, {}}};", site, literal(k.name + "_adjoint_checked"),
            shown);
  for (const auto& [p, buf] : kept)
    code.line("std::vector<{}> {}(static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, {})));",
              p->elem_name, buf, k.extent.at(p->name).code());
  code.line("{}({});", probe_name(k), fmt::join(args, ", "));
  code.close();
}

} // namespace

bool needs_probe(const ForwardPlan& plan) {
  return has_checked_entry(*plan.kernel) &&
         !uncertain_arrays(*plan.kernel, access_ranges(*plan.kernel), nullptr).empty();
}

void emit_checked_entry(Code& code, const ForwardPlan& plan) {
  const Kernel& k = *plan.kernel;
  if (!has_checked_entry(k))
    return;
  const auto ranges = access_ranges(k);
  std::vector<std::string> unchecked;
  const std::set<std::string> probed = uncertain_arrays(k, ranges, &unchecked);
  open_namespaces(code, k);
  if (!probed.empty())
    emit_probe_function(code, plan, probed);
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
  // Whether `array` (its adjoint, where `nullable`, only when given) is too short for
  // `range`, as C++.
  auto short_of = [&](const std::string& array, const std::string& range, bool nullable) {
    const std::string lo = k.fresh(range + "_lo"), hi = k.fresh(range + "_hi");
    return fmt::format("{}{} >= 0 && ({} < 0 || std::size_t({}) >= {})",
                       nullable ? array + " != nullptr && " : "", hi, lo, hi, size_name(k, array));
  };
  auto define_range = [&](const std::string& range, const std::vector<std::string>& lows,
                          const std::vector<std::string>& highs) {
    code.line("const {} {} = std::min<{}>({{{}}});", kCellType, k.fresh(range + "_lo"), kCellType,
              fmt::join(lows, ", "));
    code.line("const {} {} = std::max<{}>({{{}}});", kCellType, k.fresh(range + "_hi"), kCellType,
              fmt::join(highs, ", "));
  };
  // A null adjoint (an inactive input) is not checked.
  auto check = [&](const std::string& array, const std::string& range, bool nullable) {
    const std::string lo = k.fresh(range + "_lo"), hi = k.fresh(range + "_hi");
    code.open(fmt::format("if ({})", short_of(array, range, nullable)));
    code.line("throw std::invalid_argument(std::string(\"{}_adjoint_checked: '{}' has \") + "
              "std::to_string({}) + \" elements, but the kernel touches elements \" + "
              "std::to_string({}) + \" to \" + std::to_string({}) + \" (\" + {} + \")\");",
              k.name, array, size_name(k, array), lo, hi, sizes);
    code.close();
  };
  std::vector<std::string> args, needed;
  for (const auto& p : k.params) {
    if (p.global)
      continue;
    if (p.kind == ParamKind::Scalar) {
      args.push_back(p.name);
      continue;
    }
    auto it = ranges.find(p.name);
    if (it != ranges.end() && !it->second.highs.empty()) {
      const Range& r = it->second;
      std::string range = p.name + "_range";
      define_range(range, r.lows, r.highs);
      if (p.kind != ParamKind::Out)
        check(p.name, range, false);
      if (p.kind != ParamKind::ConstArray)
        check(p.name + "_adj", range, p.kind == ParamKind::In);
    }
    if (probed.count(p.name)) {
      const Range& r = it->second;
      if (r.dependent) {
        needed = {"true"};
      } else if (needed != std::vector<std::string>{"true"}) {
        // (where the range over every iteration fits, what the kernel touches does)
        std::string range = p.name + "_maybe";
        define_range(range, r.maybe_lows, r.maybe_highs);
        if (p.kind != ParamKind::Out)
          needed.push_back("(" + short_of(p.name, range, false) + ")");
        if (p.kind != ParamKind::ConstArray)
          needed.push_back("(" + short_of(p.name + "_adj", range, p.kind == ParamKind::In) + ")");
      }
    }
    if (p.kind == ParamKind::In) {
      args.push_back(p.name);
      args.push_back(p.name + "_adj");
    } else {
      args.push_back(p.kind == ParamKind::Out ? p.name + "_adj" : p.name);
    }
  }
  if (!probed.empty())
    emit_probe_call(code, k, probed, fmt::format("{}", fmt::join(needed, " || ")), sizes);
  code.line("{}_adjoint({});", k.name, fmt::join(args, ", "));
  code.close();
  close_namespaces(code, k);
}

} // namespace dpgen
