// Emit, file level (phase 6): the banner, includes and declarations of the
// generated files of one input file, around the kernels emit.cpp prints.
#include "emit_file.hpp"

#include <set>

#include "emit.hpp"
#include "emit_checked.hpp"
#include "emit_forward.hpp"

#include <algorithm>
#include "emit_util.hpp"

#include <fmt/format.h>

namespace dpgen {

namespace {

// The functions the adjoint files hold for one kernel, each an output form of
// the kernel: where it applies, its declaration in <stem>_adjoint.hpp (inside
// the kernel's extern "C" block where it has one) and its definition.
class KernelForm {
public:
  virtual ~KernelForm() = default;
  virtual bool applies(const Kernel& k) const = 0;
  virtual std::string declaration(const Kernel& k) const = 0;
  virtual void define(Code& c, const LoopPlan& l) const = 0;
};

// <kernel>_adjoint (emit.cpp): the gather-form adjoint.
class AdjointForm : public KernelForm {
public:
  bool applies(const Kernel&) const override { return true; }
  std::string declaration(const Kernel& k) const override { return adjoint_signature(k) + ";\n"; }
  void define(Code& c, const LoopPlan& l) const override { emit_kernel(c, l); }
};

// <kernel>_adjoint_checked (emit_checked.cpp): the adjoint with array sizes.
class CheckedForm : public KernelForm {
public:
  bool applies(const Kernel& k) const override { return has_checked_entry(k); }
  std::string declaration(const Kernel& k) const override {
    std::string out =
        fmt::format("/// The same, each array followed by its number of elements: sizes too small\n"
                    "/// for the elements the kernel touches throw std::invalid_argument.\n"
                    "{};\n",
                    checked_signature(k));
    if (needs_probe(k))
      out +=
          fmt::format("/// Where what the kernel touches depends on the data: its loops run once "
                      "on these\n/// arrays, writing nothing; an index out of range throws "
                      "std::invalid_argument\n/// (its message starting with `caller`).\n{};\n",
                      reach_signature(k));
    return out;
  }
  void define(Code& c, const LoopPlan& l) const override { emit_checked_entry(c, l.forward); }
};

// <kernel>_parallel_forward (emit_forward.cpp): the kernel on every thread.
class ParallelForwardForm : public KernelForm {
public:
  bool applies(const Kernel& k) const override { return has_parallel_forward(k); }
  std::string declaration(const Kernel& k) const override {
    return fmt::format("/// {} on every thread where its loop nests set each element once,\n"
                       "/// printed from its IR (arrays flat): the same values, bit for bit.\n"
                       "{};\n",
                       k.name, parallel_forward_signature(k));
  }
  void define(Code& c, const LoopPlan& l) const override {
    const Kernel& k = *l.adjoint->kernel;
    open_namespaces(c, k);
    emit_parallel_forward(c, l.forward);
    close_namespaces(c, k);
  }
};

} // namespace

EmittedFile emit_file(const std::vector<LoopPlan>& loops, const std::string& source_name,
                      const std::string& stem) {
  EmittedFile out;
  const AdjointForm adjoint;
  const CheckedForm checked;
  const ParallelForwardForm parallel;
  const std::vector<const KernelForm*> forms = {&adjoint, &checked, &parallel};
  std::vector<const AdjointPlan*> plans;
  for (const auto& l : loops)
    plans.push_back(l.adjoint);
  Code h;
  h.raw(fmt::format(kBanner, source_name));
  h.raw("//\n"
        "// Reverse-mode (vector-Jacobian product) kernels. For a kernel\n"
        "// f(in..., out..., constants...), f_adjoint takes the same parameters in order,\n"
        "// each DPGEN_IN array followed by its <name>_adj, which is accumulated with +=,\n"
        "// and each DPGEN_OUT array replaced by its read-only seed <name>_adj.\n"
        "#pragma once\n\n"
        "#include <stddef.h> // size_t, for the checked entry points (C and C++)\n\n");
  bool vectors = false, spans = false;
  for (const auto& p : plans) {
    vectors = vectors || has_std_vectors(*p->kernel);
    spans = spans || has_spans(*p->kernel);
  }
  h.raw(container_includes(vectors, spans));
  std::vector<const Kernel*> all;
  for (const auto& p : plans)
    all.push_back(p->kernel);
  h.raw(tag_declarations(all));
  h.raw(global_declarations(all, "_adj", false));
  std::set<std::string> facades; // template kernels whose primary is declared
  for (const auto& p : plans) {
    open_namespaces(h, *p->kernel);
    h.raw(fmt::format("/// Adjoint of {} ({}:{}).\n", p->kernel->display_name(),
                      base_name(p->kernel->file),
                      p->kernel->pos.line));
    if (p->kernel->c_linkage) // a C kernel: callable from C
      h.raw("#ifdef __cplusplus\nextern \"C\" {\n#endif\n");
    for (const KernelForm* form : forms)
      if (form->applies(*p->kernel))
        h.raw(form->declaration(*p->kernel));
    if (p->kernel->c_linkage)
      h.raw("#ifdef __cplusplus\n}\n#endif\n");
    const Kernel& k = *p->kernel;
    if (!k.template_name.empty()) {
      std::vector<std::string> args; // the adjoint's parameters (the signature rule)
      for (const auto& prm : k.params) {
        if (prm.synthetic || !prm.twin_of.empty() || prm.global)
          continue;
        if (prm.kind == ParamKind::In || prm.kind == ParamKind::ConstArray ||
            prm.kind == ParamKind::Scalar)
          args.push_back(prm.name);
        if (prm.kind == ParamKind::In || prm.kind == ParamKind::Out)
          args.push_back(prm.name + "_adj");
      }
      bool first = facades.insert(k.template_name).second;
      h.raw(template_facade(k, first, adjoint_signature(generic_kernel(k)), adjoint_signature(k),
                            "_adjoint", args));
    }
    h.raw(member_wrapper(k, false));
    close_namespaces(h, k);
    h.raw("\n");
  }
  out.header = formatted(h.str(), stem + "_adjoint.hpp");

  // The forward kernels' declarations, so a caller includes them instead of
  // writing them by hand.
  Code d;
  d.raw(fmt::format(kBanner, source_name));
  d.raw("//\n// Declarations of the forward kernels, as the kernel file defines them.\n"
        "#pragma once\n\n");
  d.raw(container_includes(vectors, spans));
  d.raw(tag_declarations(all));
  for (const auto& p : plans) {
    const Kernel& k = *p->kernel;
    if (!k.template_name.empty()) {
      d.raw(fmt::format("// {}{}: a template kernel, declared by {} (not here).\n\n",
                        k.template_name, k.template_args, base_name(k.file)));
      continue;
    }
    open_namespaces(d, k);
    d.raw(fmt::format("/// {}:{}.\n", base_name(k.file), k.pos.line));
    std::vector<std::string> ps, flat;
    for (const auto& prm : k.params) {
      if (prm.synthetic || !prm.twin_of.empty() || prm.returned || prm.global)
        continue;
      ps.push_back(prm.inout ? fmt::format("{}* {}", prm.elem_name, prm.name) : prm.declaration);
      bool is_const = prm.kind == ParamKind::In ? !prm.inout : prm.kind == ParamKind::ConstArray;
      flat.push_back(
          prm.kind == ParamKind::Scalar
              ? fmt::format("{} {}", prm.spelling, prm.name)
              : fmt::format("{}{}* {}", is_const ? "const " : "", prm.elem_name, prm.name));
    }
    if (k.c_linkage) {
      // C's variable-length rows and restrict are not C++: from C++ the same
      // function is declared with flat pointers (the same ABI).
      d.raw(fmt::format("#ifdef __cplusplus\nextern \"C\" {} {}({});\n#else\n", k.return_type,
                        k.name, fmt::join(flat, ", ")));
      d.raw(fmt::format("{} {}({});\n#endif\n", k.return_type, k.name, fmt::join(ps, ", ")));
    } else {
      d.raw(fmt::format("{} {}({});\n", k.return_type, k.name, fmt::join(ps, ", ")));
    }
    close_namespaces(d, k);
    d.raw("\n");
  }
  out.kernels = formatted(d.str(), stem + "_kernels.hpp");

  Code c;
  c.raw(fmt::format(kBanner, source_name));
  c.raw("//\n"
        "// Gather form: each adjoint cell is written by exactly one loop iteration, which\n"
        "// sums the contributions of every forward iteration that read that cell, each\n"
        "// recomputed from the primal inputs (no tape). Interior cells run a branch-free\n"
        "// loop; edge cells check each term's iteration domain. Sums start at -0.0, the\n"
        "// identity of +: each is its first term exactly.\n");
  if (std::any_of(plans.begin(), plans.end(),
                  [](const auto& p) { return !p->kernel->member_class.empty(); }))
    c.raw("#define DPGEN_NO_MEMBER_WRAPPERS // (they need the classes, which this file does not "
          "see)\n");
  c.raw(fmt::format("#include \"{}_adjoint.hpp\"\n\n", stem));
  c.raw("#include <algorithm>\n#include <cmath>\n#include <cstddef>\n#include <limits>\n");
  bool checks = false;
  for (const auto& p : plans)
    checks = checks || !p->kernel->size_checks.empty() || has_vectors(*p->kernel);
  c.raw("#include <stdexcept>\n#include <string>\n"); // the checked entry points
  bool staged = false;
  for (const auto& p : plans)
    staged = staged || !p->kernel->intermediates.empty();
  for (const auto& p : plans)
    staged = staged || has_inout(*p->kernel);
  if (staged)
    c.raw("#include <vector>\n");
  c.raw("\n");
  // a staged kernel's view outputs live in buffers laid out like their seeds
  bool view_buffers = false;
  for (const auto& p : plans)
    for (const auto& a : p->kernel->params)
      view_buffers = view_buffers || (a.view && a.kind == ParamKind::Out &&
                                      !p->kernel->intermediates.empty());
  if (view_buffers)
    c.raw("#include \"dpgen/view_buffer.hpp\"\n\n");
  if (std::any_of(loops.begin(), loops.end(),
                  [](const LoopPlan& l) { return needs_probe(*l.forward.kernel); }))
    c.raw("#include \"dpgen/checked_probe.hpp\"\n\n");
  if (std::any_of(plans.begin(), plans.end(), [](const auto& p) { return has_nested(*p->kernel); }))
    c.raw("#include \"dpgen/row_pointers.hpp\"\n\n");
  c.raw(global_declarations(all, "_adj", true));
  c.raw(kQuietUnused);
  c.raw("#if defined(__GNUC__) && !defined(__clang__)\n"
        "// Cell ranges are clamped at run time (std::max/std::min), which GCC cannot see\n"
        "// through when it bounds a loop's trip count: its overflow warning is spurious, and so\n"
        "// are its out-of-bounds warnings on a buffer sized max(0, n) read at an edge cell.\n"
        "#pragma GCC diagnostic ignored \"-Waggressive-loop-optimizations\"\n"
        "#pragma GCC diagnostic ignored \"-Warray-bounds\"\n"
        "#endif\n\n");
  c.raw(fmt::format("namespace {{\n{}}} // namespace\n\n", kMinMaxHelpers));
  for (const auto& l : loops)
    for (const KernelForm* form : forms)
      if (form->applies(*l.adjoint->kernel)) {
        form->define(c, l);
        c.raw("\n");
      }
  out.source = formatted(c.str(), stem + "_adjoint.cpp");
  return out;
}

} // namespace dpgen
