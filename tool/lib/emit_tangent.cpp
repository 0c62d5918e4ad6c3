// Emit tangents (phase 6, --tangent): the forward kernel again, printed from the IR by the
// forward forms' printer (emit_forward.hpp) in the kernel's own loops, with the directional
// derivative of every store next to it (forward mode, a Jacobian-vector product). No index is
// inverted: each iteration computes its own outputs' tangents from the tangents of what it
// reads, so the loops are the kernel's own, parallel where every element is written once.
#include "emit_tangent.hpp"

#include "ir_walk.hpp"

#include "derive.hpp"
#include "emit_checked.hpp"
#include "emit_forward.hpp"
#include "emit_util.hpp"
#include "hoist.hpp"
#include "loop_plan.hpp"
#include "print.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace dpgen {

namespace {

// Everything a tangent kernel needs, computed once per kernel so locals shared
// by several stores get one tangent each.
struct TangentPlan {
  const Kernel* k = nullptr;
  ForwardPlan loops;            // each store with its tangent (ForwardStore::dot, may be zero())
  std::set<std::string> active; // DPGEN_IN arrays and work arrays
  DeriveNames names;
  TangentLocals locals;
};

void names_in(const ExprP& e, std::set<std::string>& out, std::set<const LocalVar*>& seen) {
  walk(
      e, [](const ExprP&) { return true; },
      [&](const ExprP& l) {
        out.insert(l->local->name);
        return true;
      },
      seen);
}

TangentPlan plan_tangent(const Kernel& k) {
  TangentPlan p;
  p.k = &k;
  p.loops = plan_forward(k);
  for (const auto& prm : k.params)
    if (prm.kind == ParamKind::In || k.intermediates.count(prm.name))
      p.active.insert(prm.name);
  for (const auto& h : k.hidden) // work arrays too
    p.active.insert(h.name);
  // Names a tangent local must not take: parameters, their _dot, every local.
  std::set<const LocalVar*> seen;
  p.names.taken = &k.names;
  p.locals.taken = k.names;
  for (const auto& prm : k.params) {
    p.locals.taken.insert(prm.name);
    p.locals.taken.insert(prm.name + "_dot");
  }
  for (const auto& l : k.kernel_locals)
    names_in(local_ref(l), p.locals.taken, seen);
  for (const auto& n : k.nests)
    for (const auto& s : n.stores)
      names_in(s.value, p.locals.taken, seen);
  for (auto& n : p.loops.nests)
    for (auto& s : n.stores)
      s.dot = tangent(s.store->value, p.active, p.names, p.locals);
  peel_forward(p.loops); // (with the tangents: it folds them too)
  // (after every tangent local is named: the hoisted ones take none of them)
  hoist_invariants(p.loops, &p.locals.taken);
  return p;
}

// The kernel's return value, if it has one (Param::returned).
const Param* returned(const Kernel& k) {
  for (const auto& p : k.params)
    if (p.returned)
      return &p;
  return nullptr;
}

// The tangent's parameters (`decl`) or the arguments from the shaped entry
// point to the flat one: each DPGEN_IN array followed by its read-only
// `<name>_dot`, each DPGEN_OUT array followed by its `<name>_dot` result. An
// in-place array's new values go to the array itself.
std::string tangent_list(const Kernel& k, bool shaped, bool decl) {
  std::vector<std::string> ps;
  auto array = [&](const Param& p, bool is_const, const std::string& name) {
    return decl ? array_declaration(p, is_const, name, shaped, k.c_linkage)
                : flat_argument(p, is_const, name);
  };
  for (const auto& p : k.params) {
    if ((decl && shaped && p.synthetic) || !p.twin_of.empty() || p.global)
      continue;
    switch (p.kind) {
    case ParamKind::In:
      ps.push_back(array(p, !p.inout, p.name));
      ps.push_back(array(p, !p.inout, p.name + "_dot"));
      break;
    case ParamKind::Out:
      // (the return value: the shaped entry returns it, from a local)
      if (!(p.returned && decl && shaped))
        ps.push_back(array(p, false, p.name));
      ps.push_back(array(p, false, p.name + "_dot"));
      break;
    case ParamKind::ConstArray:
      ps.push_back(array(p, true, p.name));
      break;
    case ParamKind::Scalar:
      if (decl)
        ps.push_back(fmt::format("{} {}", p.spelling, p.name));
      else // a vector's size: the size() of the vector it follows
        ps.push_back(p.synthetic ? p.name.substr(0, p.name.size() - 5) + ".size()" : p.name);
      break;
    }
  }
  return fmt::format("{}", fmt::join(ps, ", "));
}
std::string tangent_params(const Kernel& k, bool shaped) { return tangent_list(k, shaped, true); }
std::string flat_tangent_arguments(const Kernel& k) { return tangent_list(k, false, false); }

// `std::vector` tangents have their arrays' sizes.
void emit_vector_checks(Code& code, const Kernel& k) {
  emit_vector_size_checks(code, k, k.name + "_tangent", "_dot", [](const Param& p) {
    return p.kind == ParamKind::In || p.kind == ParamKind::Out;
  });
}

void emit_kernel(Code& code, const TangentPlan& tp) {
  const Kernel& k = *tp.k;
  open_namespaces(code, k);
  bool shaped = has_rows(k);
  std::string name = k.name + (shaped ? "_tangent_flat" : "_tangent");
  if (shaped) {
    code.raw("namespace {\n");
    code.line("// Tangent of {} ({}:{}) on flat arrays; {}_tangent below takes them as "
              "declared.",
              k.name, base_name(k.file), k.pos.line, k.name);
  } else {
    code.line("// Tangent of {} ({}:{}).", k.name, base_name(k.file), k.pos.line);
  }
  code.open(fmt::format("void {}({})", name, tangent_params(k, !shaped)));
  define_kernel_locals(code, k);
  // The sums of the kernel's accumulators (Kernel::hidden) and their tangents.
  for (const auto& h : k.hidden) {
    const std::string buf = k.fresh(h.name + "_buf"), dot_buf = k.fresh(h.name + "_dot_buf");
    code.line("std::vector<{}> {}(static_cast<std::size_t>({})), {}({}.size()); // '{}'",
              h.elem_name, buf, k.extent.at(h.name).code(), dot_buf, buf, h.spelling);
    code.line("{}* const {} = {}.data();", h.elem_name, h.name, buf);
    code.line("{}* const {}_dot = {}.data();", h.elem_name, h.name, dot_buf);
  }
  // Tangents of the locals set before every loop (a0 = a[0]: a0_dot = a_dot[0]).
  std::set<int> done;
  std::set<std::string> vars;
  for (const auto& l : tp.locals.locals)
    if (l->kernel_level) {
      std::map<int, LocalP> deps;
      collect(l->def, deps, vars);
      define_locals(code, deps, done);
      code.line("const {} {} = {};", l->type_name, l->name, print(l->def));
    }
  emit_size_checks(code, k, k.name + "_tangent");
  emit_container_reach_checks(code, k, k.name + "_tangent");
  // In-place arrays (DPGEN_INOUT): the IR reads their old values everywhere, also after the
  // iteration's own store to the element (`u[i] = 2 * u[i]; v[i] += u[i];` reads the old u[i]
  // times 2, and an else-branch tests the old u[i]). So the stores go to buffers, each
  // flagging its element, and the flagged elements to the array once every nest has run:
  // nothing is read or written that the kernel does not read or write.
  struct InPlace {
    const Param* array;
    std::string n, values, dots, flags;
  };
  std::vector<InPlace> in_place;
  ForwardOptions options;
  for (const auto& twin : k.params) {
    if (twin.twin_of.empty())
      continue;
    const Param* u = k.find_param(twin.twin_of);
    InPlace b{u, k.fresh(u->name + "_n"), k.fresh(twin.name + "_buf"),
              k.fresh(twin.name + "_dot_buf"), k.fresh(twin.name + "_written")};
    code.line("// '{}' is updated in place: its new values and tangents to buffers first", u->name);
    code.line("const std::ptrdiff_t {} = {};", b.n, k.extent.at(twin.name).code());
    code.line("std::vector<{}> {}(static_cast<std::size_t>({})), {}({}.size());", u->elem_name,
              b.values, b.n, b.dots, b.values);
    code.line("std::vector<unsigned char> {}({}.size()); // the elements stored", b.flags,
              b.values);
    code.line("{}* const {} = {}.data();", u->elem_name, twin.name, b.values);
    code.line("{}* const {}_dot = {}.data();", u->elem_name, twin.name, b.dots);
    options.written[twin.name] = b.flags;
    in_place.push_back(b);
  }
  emit_hoisted(code, tp.loops.hoisted);
  for (size_t n = 0; n < tp.loops.nests.size(); ++n) {
    code.line("// loop nest {}: each store, then its tangent", n + 1);
    emit_forward_nest(code, k, tp.loops.nests[n], true, options);
  }
  for (const auto& b : in_place) {
    const std::string e = k.fresh("element");
    code.open(fmt::format("for (std::size_t {} = 0; {} < {}.size(); ++{})", e, e, b.values, e));
    code.open(fmt::format("if ({}[{}])", b.flags, e));
    code.line("{}[{}] = {}[{}];", b.array->name, e, b.values, e);
    code.line("{}_dot[{}] = {}[{}];", b.array->name, e, b.dots, e);
    code.close();
    code.close();
  }
  code.close();
  if (shaped) {
    code.raw("} // namespace\n\n");
    code.line("// Tangent of {} ({}:{}).", k.name, base_name(k.file), k.pos.line);
    code.open(tangent_signature(k));
    emit_vector_checks(code, k);
    const Param* ret = returned(k);
    if (ret)
      code.line("{} {};", ret->elem_name, ret->name);
    code.line("{}_tangent_flat({});", k.name, flat_tangent_arguments(k));
    if (ret)
      code.line("return {};", ret->name);
    code.close();
  }
  close_namespaces(code, k);
}

} // namespace

std::string tangent_signature(const Kernel& k) {
  return fmt::format("{} {}_tangent({})", k.return_type, k.name, tangent_params(k, true));
}

EmittedFile emit_tangent_file(const std::vector<const Kernel*>& kernels,
                              const std::string& source_name, const std::string& stem) {
  EmittedFile out;
  bool vectors = false, checks = false;
  for (const auto* k : kernels) {
    vectors = vectors || has_vectors(*k);
    checks = checks || has_vectors(*k) || !k->size_checks.empty();
  }
  Code h;
  h.raw(fmt::format(kBanner, source_name));
  h.raw("//\n"
        "// Tangent (forward-mode, Jacobian-vector product) kernels. For a kernel\n"
        "// f(in..., out..., constants...), f_tangent takes the same parameters in order,\n"
        "// each DPGEN_IN array followed by its direction <name>_dot (read only), and each\n"
        "// DPGEN_OUT array followed by <name>_dot, which receives the derivative of that\n"
        "// output along the directions. The outputs themselves are computed too.\n"
        "#pragma once\n\n");
  bool spans = false, std_vectors = false;
  for (const auto* k : kernels) {
    spans = spans || has_spans(*k);
    std_vectors = std_vectors || has_std_vectors(*k);
  }
  h.raw(container_includes(std_vectors, spans));
  h.raw(tag_declarations(kernels));
  h.raw(global_declarations(kernels, "_dot", false));
  std::set<std::string> facades; // template kernels whose primary is declared
  for (const auto* k : kernels) {
    open_namespaces(h, *k);
    h.raw(fmt::format("/// Tangent of {} ({}:{}).\n", k->display_name(), base_name(k->file),
                      k->pos.line));
    if (k->c_linkage)
      h.raw("#ifdef __cplusplus\nextern \"C\" {\n#endif\n");
    h.raw(tangent_signature(*k) + ";\n");
    if (k->c_linkage)
      h.raw("#ifdef __cplusplus\n}\n#endif\n");
    if (!k->template_name.empty()) {
      std::vector<std::string> args; // the tangent's parameters
      for (const auto& p : k->params) {
        if (p.synthetic || !p.twin_of.empty() || p.global)
          continue;
        if (!p.returned)
          args.push_back(p.name);
        if (p.kind == ParamKind::In || p.kind == ParamKind::Out)
          args.push_back(p.name + "_dot");
      }
      bool first = facades.insert(k->template_name).second;
      h.raw(template_facade(*k, first, tangent_signature(generic_kernel(*k)),
                            tangent_signature(*k), "_tangent", args));
    }
    h.raw(member_wrapper(*k, true));
    close_namespaces(h, *k);
    h.raw("\n");
  }
  out.header = formatted(h.str(), stem + "_tangent.hpp");

  Code c;
  c.raw(fmt::format(kBanner, source_name));
  c.raw("//\n"
        "// Forward mode: every store of the kernel followed by its directional\n"
        "// derivative, d out = sum over reads of (d out / d read) * read_dot, in the\n"
        "// kernel's own loops.\n");
  if (std::any_of(kernels.begin(), kernels.end(),
                  [](const Kernel* k) { return !k->member_class.empty(); }))
    c.raw("#define DPGEN_NO_MEMBER_WRAPPERS // (they need the classes, which this file does not "
          "see)\n");
  c.raw(fmt::format("#include \"{}_tangent.hpp\"\n\n", stem));
  c.raw("#include <algorithm>\n#include <cmath>\n#include <cstddef>\n");
  bool hidden = false; // (or in-place arrays: buffers)
  for (const auto* k : kernels)
    hidden = hidden || !k->hidden.empty() || has_inout(*k);
  if (hidden)
    c.raw("#include <vector>\n");
  if (checks)
    c.raw("#include <stdexcept>\n#include <string>\n");
  c.raw("\n");
  if (std::any_of(kernels.begin(), kernels.end(), [](const Kernel* k) { return has_nested(*k); }))
    c.raw("#include \"dpgen/row_pointers.hpp\"\n\n");
  c.raw(global_declarations(kernels, "_dot", true));
  c.raw(kQuietUnused);
  c.raw("namespace {\n"
        "// std::min/std::max by value, the first argument on ties (as in the adjoints).\n"
        "template <typename T> inline T dpgen_min(T a, T b) { return b < a ? b : a; }\n"
        "template <typename T> inline T dpgen_max(T a, T b) { return a < b ? b : a; }\n"
        "} // namespace\n\n");
  for (const auto* k : kernels) {
    TangentPlan tp = plan_tangent(*k);
    emit_kernel(c, tp);
    c.raw("\n");
  }
  out.source = formatted(c.str(), stem + "_tangent.cpp");
  return out;
}

} // namespace dpgen
