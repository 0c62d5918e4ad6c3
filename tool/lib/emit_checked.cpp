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
#include "ir_walk.hpp"
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

void emit_container_reach_checks(Code& code, const Kernel& k, const std::string& fn) {
  if (std::none_of(k.params.begin(), k.params.end(),
                   [](const Param& p) { return !p.container.empty() && !p.nested; }))
    return;
  const auto ranges = access_ranges(k);
  for (const auto& p : k.params) {
    auto it = ranges.find(p.name);
    if (p.container.empty() || p.nested || p.global || it == ranges.end() ||
        it->second.highs.empty())
      continue;
    const std::string lo = k.fresh(p.name + "_reach_lo"), hi = k.fresh(p.name + "_reach_hi");
    code.line("const {} {} = std::min<{}>({{{}}});", kCellType, lo, kCellType,
              fmt::join(it->second.lows, ", "));
    code.line("const {} {} = std::max<{}>({{{}}});", kCellType, hi, kCellType,
              fmt::join(it->second.highs, ", "));
    const bool tangent = fn.size() > 8 && fn.compare(fn.size() - 8, 8, "_tangent") == 0;
    const std::string shown = p.kind == ParamKind::Out && !tangent ? p.name + "_adj" : p.name;
    code.open(fmt::format("if ({} >= 0 && ({} < 0 || {} >= static_cast<{}>({}_size)))", hi, lo, hi,
                          kCellType, p.name));
    code.line("throw std::invalid_argument(\"{}: '{}' has \" + std::to_string({}_size) + "
              "\" elements, but the kernel touches elements \" + std::to_string({}) + \" to \" "
              "+ std::to_string({}));",
              fn, shown, p.name, lo, hi);
    code.close();
  }
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
    if (p.kind == ParamKind::Scalar || it == ranges.end())
      continue;
    if (!it->second.dependent && it->second.maybe_highs.empty())
      continue;
    // (a global pointer has no size to check against; a global array of known size has a
    // stand-in by its name in the probe, a parameter of the probe function)
    if (probe && (!p.global || (p.global_count >= 0 && p.kind != ParamKind::Out)))
      probed.insert(p.name);
    else if (unchecked)
      unchecked->push_back(p.name);
  }
  return probed;
}

// C++ appended to a message: " (" + <the integer arguments> + ")", or nothing where the kernel
// has none (`sizes` "std::string()").
std::string sizes_tail(const std::string& sizes) {
  return sizes == "std::string()" ? "" : fmt::format(" + \" (\" + {} + \")\"", sizes);
}

// The integer kernel-level locals, which the ranges may use (x_min = *xmin), and the real ones
// they are computed from (`const int m = (int)s;`), not the others, which might read arrays
// before their sizes are checked; each array element one of them reads is checked first,
// against its array's size (`caller`: C++ for the message's start).
void define_checked_int_locals(Code& code, const Kernel& k, const std::string& caller,
                               const std::string& sizes) {
  std::set<const LocalVar*> needed, seen;
  for (const auto& l : k.kernel_locals)
    if (l->def->type == Type::Int) {
      needed.insert(l.get());
      walk(
          l->def,
          [&](const ExprP& x) {
            if (x->op == Op::Local)
              needed.insert(x->local.get());
            return true;
          },
          [](const ExprP&) { return true; }, seen);
    }
  std::set<std::string> checked; // (an element read by two of them: checked once)
  for (const auto& l : k.kernel_locals) {
    if (!needed.count(l.get()))
      continue;
    for (const auto& site : reads_in(l->def)) {
      const Param* p = k.find_param(site.read->name);
      if (!p || p->global || (p->kind != ParamKind::In && p->kind != ParamKind::ConstArray))
        continue;
      const std::string idx = print(site.read->ops[0]), size = size_name(k, p->name);
      std::string cond = fmt::format("({}) < 0 || std::size_t({}) >= {}", idx, idx, size);
      if (!site.conds.empty()) // (read where these hold only)
        cond = fmt::format("({}) && ({})", conjunction(site.conds), cond);
      if (!checked.insert(cond).second)
        continue;
      code.open(fmt::format("if ({})", cond));
      code.line("throw std::invalid_argument(std::string({}) + \": '{}' has \" + "
                "std::to_string({}) + \" elements, but the kernel touches element \" + "
                "std::to_string({}){});",
                caller, p->name, size, idx, sizes_tail(sizes));
      code.close();
    }
    code.line("const {} {} = {};", l->type_name, l->name, print(l->def));
  }
}

// The name of the probe's function (see the top of this file).
std::string probe_name(const Kernel& k) { return k.fresh(k.name + "_probe"); }

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
    if (!p.global || probed.count(p.name))
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
  // (a global's stand-in takes its name: the loops, printed as the kernel's, index it)
  const bool globals = std::any_of(k.params.begin(), k.params.end(), [&](const Param& p) {
    return p.global && probed.count(p.name);
  });
  if (globals) {
    code.raw("#pragma GCC diagnostic push\n");
    code.raw("#pragma GCC diagnostic ignored \"-Wshadow\"\n");
  }
  code.open(fmt::format("static void {}({})", probe_name(k), fmt::join(ps, ", ")));
  define_kernel_locals(code, k);
  ForwardOptions serial;
  serial.threads = false;
  emit_forward_nests(code, plan, serial, false);
  code.close();
  if (globals)
    code.raw("#pragma GCC diagnostic pop\n");
  code.raw("\n");
}

// The arguments of the checked entry point, by name, in order (checked_params).
std::vector<std::string> checked_args(const Kernel& k) {
  std::vector<std::string> out;
  for (const auto& p : k.params) {
    if (p.global)
      continue;
    const std::string adj = p.name + "_adj";
    if (p.kind == ParamKind::Scalar)
      out.push_back(p.name);
    if (p.kind == ParamKind::In || p.kind == ParamKind::ConstArray)
      out.insert(out.end(), {p.name, size_name(k, p.name)});
    if (p.kind == ParamKind::In || p.kind == ParamKind::Out)
      out.insert(out.end(), {adj, size_name(k, adj)});
  }
  return out;
}

std::string caller_name(const Kernel& k) { return k.fresh("caller"); }

// `void <kernel>_check_reach(const char* caller, <the checked entry point's parameters>)`:
// the probe's run on those arrays, its messages starting with `caller`.
void emit_reach_function(Code& code, const Kernel& k, const std::set<std::string>& probed,
                         const std::string& sizes) {
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
      // (an array of the kernel's own by the name the kernel gives it: `buf`, `s`)
      args.push_back(fmt::format("dpgen::ProbeOutput<{}>({}, {}, {}, {}, {}.data(), {}.size())",
                                 p->elem_name, site, literal(hidden ? p->spelling : adj), seed,
                                 size, buf, buf));
    } else if (p->kind == ParamKind::Out) {
      args.push_back(fmt::format("dpgen::ProbeOutput<{}>({}, {}, {}, {})", p->elem_name, site,
                                 literal(adj), adj, size_name(k, adj)));
    } else {
      // (a global array: its type's size, and its adjoint's, the global `<name>_adj`)
      auto size = [&](const std::string& a) {
        return p->global ? std::to_string(p->global_count) : size_name(k, a);
      };
      if (p->kind == ParamKind::In)
        args.push_back(fmt::format("dpgen::ProbeInput<{}>({}, {}, {}, {}, {}, {}, {})",
                                   p->elem_name, site, literal(p->name), p->name, size(p->name),
                                   literal(adj), adj, size(adj)));
      else
        args.push_back(fmt::format("dpgen::ProbeInput<{}>({}, {}, {}, {})", p->elem_name, site,
                                   literal(p->name), p->name, size(p->name)));
    }
  }
  code.line("// {}'s loops run once on these arrays ({}), writing nothing: throws "
            "std::invalid_argument, its message starting with `{}`, at the first index into {} "
            "or an output that is out of range.",
            k.name, probe_name(k), caller_name(k), fmt::join(probed, ", "));
  code.open(reach_signature(k));
  define_checked_int_locals(code, k, caller_name(k), sizes); // (the buffers' sizes may use them)
  code.line("const std::string {} = {};", shown, sizes);
  code.line("const dpgen::ProbeSite {}{{{}, {}}};", site, caller_name(k), shown);
  for (const auto& [p, buf] : kept)
    code.line("std::vector<{}> {}(static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, {})));",
              p->elem_name, buf, k.extent.at(p->name).code());
  code.line("{}({});", probe_name(k), fmt::join(args, ", "));
  code.close();
  code.raw("\n");
}

} // namespace

std::string reach_name(const Kernel& k) { return k.fresh(k.name + "_check_reach"); }

bool needs_probe(const Kernel& k) {
  return has_checked_entry(k) && !uncertain_arrays(k, access_ranges(k), nullptr).empty();
}

std::string reach_signature(const Kernel& k) {
  return fmt::format("void {}(const char* {}, {})", reach_name(k), caller_name(k),
                     checked_params(k));
}

void emit_checked_entry(Code& code, const ForwardPlan& plan) {
  const Kernel& k = *plan.kernel;
  if (!has_checked_entry(k))
    return;
  const auto ranges = access_ranges(k);
  std::vector<std::string> unchecked;
  const std::set<std::string> probed = uncertain_arrays(k, ranges, &unchecked);
  open_namespaces(code, k);
  std::vector<std::string> shown;
  for (const auto& p : k.params)
    if (p.kind == ParamKind::Scalar && p.elem == Type::Int && !p.synthetic)
      shown.push_back(shown_value(p));
  std::string sizes =
      shown.empty() ? "std::string()" : fmt::format("{}", fmt::join(shown, " + \", \" + "));
  if (!probed.empty()) {
    emit_probe_function(code, plan, probed);
    emit_reach_function(code, k, probed, sizes);
  }
  code.line("// {}_adjoint with the size of every array, checked against the elements the "
            "kernel touches{}.",
            k.name,
            unchecked.empty() ? ""
                              : fmt::format(" (not checkable: {}, read at data-dependent indices "
                                            "or under data-dependent conditions)",
                                            fmt::join(unchecked, ", ")));
  code.open(checked_signature(k));
  define_checked_int_locals(code, k, literal(k.name + "_adjoint_checked"), sizes);
  // Whether `array` (its adjoint, where `nullable`, only when given) is too short for
  // `range`, as C++.
  // (a global array's size is its type's: `global_count`)
  auto size_of = [&](const std::string& array) {
    const Param* g = k.find_param(array);
    return g && g->global ? std::to_string(g->global_count) : size_name(k, array);
  };
  auto short_of = [&](const std::string& array, const std::string& range, bool nullable) {
    const std::string lo = k.fresh(range + "_lo"), hi = k.fresh(range + "_hi");
    return fmt::format("{}{} >= 0 && ({} < 0 || std::size_t({}) >= {})",
                       nullable ? array + " != nullptr && " : "", hi, lo, hi, size_of(array));
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
              "std::to_string({}) + \" to \" + std::to_string({}){});",
              k.name, array, size_of(array), lo, hi, sizes_tail(sizes));
    code.close();
  };
  std::vector<std::string> args, needed;
  // Where the probe must run for `p`, a probed array (`needed`, or'ed; "true": always).
  auto need_probe = [&](const Param& p, const Range& r) {
    if (r.dependent) {
      needed = {"true"};
    } else if (needed != std::vector<std::string>{"true"}) {
      // (where the range over every iteration fits, what the kernel touches does)
      std::string range = p.name + "_maybe";
      define_range(range, r.maybe_lows, r.maybe_highs);
      if (p.kind != ParamKind::Out)
        needed.push_back("(" + short_of(p.name, range, false) + ")");
      // (a global's adjoint has the global's size: its own check is the global's)
      if (p.kind != ParamKind::ConstArray && !p.global)
        needed.push_back("(" + short_of(p.name + "_adj", range, p.kind == ParamKind::In) + ")");
    }
  };
  for (const auto& p : k.params) {
    if (p.global) { // what the kernel surely reads of a global array of a known size
      auto it = ranges.find(p.name);
      if (p.global_count >= 0 && it != ranges.end() && !it->second.highs.empty()) {
        define_range(p.name + "_range", it->second.lows, it->second.highs);
        check(p.name, p.name + "_range", false);
      }
      if (probed.count(p.name))
        need_probe(p, it->second);
      continue;
    }
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
    if (probed.count(p.name))
      need_probe(p, it->second);
    if (p.kind == ParamKind::In) {
      args.push_back(p.name);
      args.push_back(p.name + "_adj");
    } else {
      args.push_back(p.kind == ParamKind::Out ? p.name + "_adj" : p.name);
    }
  }
  if (!probed.empty()) {
    std::vector<std::string> what(probed.begin(), probed.end());
    code.line("// {}: what the kernel touches depends on the data. Where the ranges above do "
              "not settle it, its loops run once, writing nothing, with each index into {} and "
              "the outputs checked before it is used.",
              fmt::join(what, ", "), what.size() == 1 ? "it" : "them");
    std::vector<std::string> reach = {literal(k.name + "_adjoint_checked")};
    for (const auto& a : checked_args(k))
      reach.push_back(a);
    const std::string call = fmt::format("{}({});", reach_name(k), fmt::join(reach, ", "));
    if (needed == std::vector<std::string>{"true"}) {
      code.line("{}", call);
    } else {
      code.open(fmt::format("if ({})", fmt::join(needed, " || ")));
      code.line("{}", call);
      code.close();
    }
  }
  code.line("{}_adjoint({});", k.name, fmt::join(args, ", "));
  code.close();
  close_namespaces(code, k);
}

} // namespace dpgen
