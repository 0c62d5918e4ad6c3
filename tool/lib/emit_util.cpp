// Shared by the emitters: see emit_util.hpp.
#include "emit_util.hpp"

#include <set>

#include "ir_walk.hpp"

#include "print.hpp"

#include <clang/Format/Format.h>
#include <clang/Tooling/Core/Replacement.h>

#include <algorithm>

namespace dpgen {



void collect(const ExprP& e, std::map<int, LocalP>& locals, std::set<std::string>& vars) {
  std::set<const LocalVar*> seen;
  walk(
      e,
      [&](const ExprP& x) {
        if (x->op == Op::LoopVar)
          vars.insert(x->name);
        return true;
      },
      [&](const ExprP& l) { // kernel-level locals are defined once, at the top
        if (l->local->kernel_level || locals.count(l->local->id))
          return false;
        locals[l->local->id] = l->local;
        return true;
      },
      seen);
}


std::string cond_text(const PathCond& pc) {
  return pc.positive ? print_conjunct(pc.cond) : "!(" + print(pc.cond) + ")";
}


// Emits `const T name = def;` for each local in `locals` not yet in `done`.
void define_locals(Code& code, const std::map<int, LocalP>& locals, std::set<int>& done) {
  for (const auto& [id, l] : locals)
    if (done.insert(id).second)
      code.line("const {} {} = {};", l->type_name, l->name, print(l->def));
}

void threaded_loop(Code& code, const std::string& parallel, const std::string& header,
                   const std::string& body) {
  code.open(fmt::format("if ({})", parallel));
  code.line("#pragma omp parallel for");
  code.line("{}", header);
  code.line("  {}", body);
  code.chain("else");
  code.line("{}", header);
  code.line("  {}", body);
  code.close();
}

void define_kernel_locals(Code& code, const Kernel& k, bool ints_only) {
  for (const auto& l : k.kernel_locals)
    if (!ints_only || l->def->type == Type::Int)
      code.line("const {} {} = {};", l->type_name, l->name, print(l->def));
}

std::string conjunction(const std::vector<PathCond>& conds) {
  if (conds.size() == 1 && conds[0].positive) // (alone: no parentheses needed)
    return print(conds[0].cond);
  std::vector<std::string> parts;
  for (const auto& pc : conds)
    parts.push_back(cond_text(pc));
  return fmt::format("{}", fmt::join(parts, " && "));
}


// Comments name the kernel file without its directory, so generated files do
// not depend on where the tree was checked out.
std::string base_name(const std::string& path) {
  auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// A C++ string literal holding `s`.
std::string literal(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\')
      out += '\\';
    out += c;
  }
  return out + "\"";
}

// `"n = " + std::to_string(n)` for integer parameter `p` in a message (an
// enum, which std::to_string does not take, as its integer).
std::string shown_value(const Param& p) {
  return p.enum_value
             ? fmt::format("\"{} = \" + std::to_string(static_cast<long long>({}))", p.name, p.name)
             : fmt::format("\"{} = \" + std::to_string({})", p.name, p.name);
}

// The write-once rules dpgen could not prove for all sizes, checked on entry:
// sizes that break one would make the adjoint wrong, so they stop it with a
// message naming the rule, the kernel line and the sizes.
void emit_size_checks(Code& code, const Kernel& k, const std::string& fn_name) {
  std::vector<std::string> shown;
  for (const auto& p : k.params)
    if (p.kind == ParamKind::Scalar && p.elem == Type::Int && !p.global)
      shown.push_back(shown_value(p));
  std::string sizes = shown.empty() ? "\"\""
                                    : fmt::format("{}", fmt::join(shown, " + \", \" + "));
  for (const auto& c : k.size_checks) {
    code.line("// Run-time check (not provable from the kernel alone): {}.", c.what);
    // (printed with the live RenameScope's names)
    const std::string premises = join_code(c.premises, " && ");
    code.open(fmt::format("if ({}{}!({}))", premises, premises.empty() ? "" : " && ",
                          c.must_hold_code()));
    bool tangent = fn_name.size() > 8 && fn_name.compare(fn_name.size() - 8, 8, "_tangent") == 0;
    std::string msg = fmt::format("{}:{}: {}: these sizes break the rule that {}, so the "
                                  "{} would be wrong (",
                                  base_name(c.pos.file), c.pos.line, fn_name, c.what,
                                  tangent ? "tangent" : "adjoint");
    code.line("throw std::invalid_argument(std::string({}) + {} + \")\");", literal(msg), sizes);
    code.close();
  }
}


// Arrays of rows or std::vectors: the user-facing entry point takes them as
// declared and calls a flat twin.
bool has_rows(const Kernel& k) {
  return std::any_of(k.params.begin(), k.params.end(), [](const Param& p) {
    return p.kind != ParamKind::Scalar &&
           (!p.rows.empty() || !p.container.empty() || p.scalar_ref);
  });
}

bool has_nested(const Kernel& k) {
  return std::any_of(k.params.begin(), k.params.end(), [](const Param& p) { return p.nested; });
}

bool has_inout(const Kernel& k) {
  return std::any_of(k.params.begin(), k.params.end(), [](const Param& p) { return p.inout; });
}

bool has_vectors(const Kernel& k) {
  return std::any_of(k.params.begin(), k.params.end(),
                     [](const Param& p) { return !p.container.empty(); });
}

std::string container_includes(bool vectors, bool spans) {
  return std::string(vectors ? "#include <vector>\n" : "") + (spans ? "#include <span>\n" : "") +
         (vectors || spans ? "\n" : "");
}

bool has_std_vectors(const Kernel& k) {
  return std::any_of(k.params.begin(), k.params.end(),
                     [](const Param& p) { return !p.container.empty() && !p.span; });
}

bool has_spans(const Kernel& k) {
  return std::any_of(k.params.begin(), k.params.end(), [](const Param& p) { return p.span; });
}


std::string global_declarations(const std::vector<const Kernel*>& kernels,
                                const std::string& suffix, bool source) {
  std::set<std::string> seen;
  std::string out;
  auto in_namespaces = [](const Param& g, const std::string& decl) {
    std::string s = decl;
    for (auto it = g.global_namespaces.rbegin(); it != g.global_namespaces.rend(); ++it)
      s = fmt::format("namespace {} {{ {} }}", *it, s);
    return s + "\n";
  };
  auto using_decl = [](const Param& g, const std::string& name) {
    if (g.global_namespaces.empty())
      return std::string();
    return fmt::format("using {}::{};\n", fmt::join(g.global_namespaces, "::"), name);
  };
  for (const Kernel* k : kernels)
    for (const auto& g : k->params) {
      if (!g.global || !seen.insert(g.name).second)
        continue;
      const std::string d = g.name + suffix;
      if (source) {
        out += in_namespaces(g, g.global_declaration) + using_decl(g, g.name);
        if (g.kind == ParamKind::In)
          out += in_namespaces(g, fmt::format("{}* {} = nullptr;", g.elem_name, d)) +
                 using_decl(g, d);
      } else if (g.kind == ParamKind::In) {
        out += in_namespaces(g, fmt::format("extern {}* {};", g.elem_name, d));
      }
    }
  if (out.empty())
    return out;
  return (source ? std::string("// The globals the kernels read (and the ") +
                       (suffix == "_adj" ? "adjoint" : "tangent") +
                       " pointers of those marked DPGEN_IN).\n"
                 : std::string(suffix == "_adj" ? "// The adjoint" : "// The tangent") +
                       " of each global marked DPGEN_IN: point it at storage of the global's "
                       "size before the call (null: not computed).\n") +
         out + "\n";
}

std::string tag_declarations(const std::vector<const Kernel*>& kernels) {
  std::set<std::string> seen;
  std::string tags, types;
  for (const Kernel* k : kernels) {
    for (const auto& p : k->params)
      if (!p.tag_declaration.empty() && seen.insert(p.tag_declaration).second)
        (p.tag ? tags : types) += p.tag_declaration + "\n";
    for (const auto& d : k->declarations)
      if (seen.insert(d).second)
        tags += d + "\n";
  }
  std::string out;
  if (!types.empty()) // views and objects: their classes, as the kernel file includes them
    out += "// The kernels' view and object classes, as the kernel file includes them.\n" +
           types + "\n";
  if (!tags.empty())
    out += "// The kernels' tag types (a declaration is enough).\n" + tags + "\n";
  return out;
}

Kernel generic_kernel(const Kernel& k) {
  Kernel g = k;
  g.name = k.template_name;
  for (auto& p : g.params) {
    if (p.kind == ParamKind::Scalar) {
      auto it = k.generic_scalars.find(p.name);
      if (it != k.generic_scalars.end())
        p.spelling = it->second;
    } else if (auto it = k.generic_types.find(p.name); it != k.generic_types.end()) {
      p.elem_name = it->second;
    }
  }
  return g;
}

std::string template_facade(const Kernel& k, bool first, const std::string& generic_signature,
                            const std::string& signature, const std::string& suffix,
                            const std::vector<std::string>& args) {
  std::string out;
  const std::string generated = k.name + suffix, public_name = k.template_name + suffix;
  if (first)
    out += fmt::format("/// {}{}: the template kernel {}'s, one explicit specialization per "
                       "instantiation the kernel file makes.\n{} {};\n",
                       public_name, "", k.template_name, k.template_head, generic_signature);
  std::string sig = signature;
  size_t at = sig.find(generated + "(");
  if (at == std::string::npos)
    throw std::logic_error("internal error: template_facade: no " + generated + " in " + sig);
  sig.replace(at, generated.size(), public_name + k.template_args);
  bool returns = sig.rfind("void ", 0) != 0;
  out += fmt::format("template <> inline {} {{ {}{}({}); }}\n", sig, returns ? "return " : "",
                     generated, fmt::join(args, ", "));
  return out;
}

void open_namespaces(Code& c, const Kernel& k) {
  for (const auto& ns : k.namespaces)
    c.raw(fmt::format("namespace {} {{\n", ns));
}
void close_namespaces(Code& c, const Kernel& k) {
  for (auto it = k.namespaces.rbegin(); it != k.namespaces.rend(); ++it)
    c.raw(fmt::format("}} // namespace {}\n", *it));
}


// clang-format (LLVM style, 100 columns) over the generated text, so long
// expressions wrap the way a person would wrap them.
std::string formatted(const std::string& code, const std::string& name) {
  clang::format::FormatStyle style = clang::format::getLLVMStyle();
  style.ColumnLimit = 100;
  style.SortIncludes = clang::format::FormatStyle::SI_Never;
  style.PointerAlignment = clang::format::FormatStyle::PAS_Left;
  auto repl = clang::format::reformat(style, code, {clang::tooling::Range(0, code.size())}, name);
  auto out = clang::tooling::applyAllReplacements(code, repl);
  if (!out) {
    llvm::consumeError(out.takeError());
    return code;
  }
  return *out;
}



std::string array_declaration(const Param& p, bool is_const, const std::string& name, bool shaped,
                              bool c_language) {
  std::string c = is_const ? "const " : "";
  if (p.view) // an array view: the kernel's type, or the same view of non-const elements
    return fmt::format("{} {}", view_declared_type(p, is_const), name);
  if (shaped && p.nested) // std::vector<std::vector<double>>& a
    return fmt::format("{}{}& {}", c, p.container, name);
  if (p.plane_pointers) // `double*** a`: `const double* const* const* a` (C: `double** const* a`)
    return c_language ? fmt::format("{}** const* {}", p.elem_name, name)
                      : fmt::format("{}{}* const* const* {}", c, p.elem_name, name);
  if (p.row_pointers) // `double** a` passes as `const double* const* a` / `double* const* a_adj`
    return fmt::format("{}{}* const* {}", c_language ? "" : c, p.elem_name, name);
  if (shaped && !p.rows.empty())
    return fmt::format("{}{} (*{}){}", c, p.elem_name, name, p.rows);
  if (shaped && p.span)
    return fmt::format("std::span<{}{}> {}", c, p.elem_name, name);
  if (shaped && !p.container.empty())
    return fmt::format("{}{}& {}", c, p.container, name);
  if (shaped && p.scalar_ref) // a seed by value, an adjoint or tangent by reference
    return is_const ? fmt::format("{} {}", p.elem_name, name)
                    : fmt::format("{}& {}", p.elem_name, name);
  return fmt::format("{}{}* {}", c, p.elem_name, name);
}

// Rows of a multi-dimensional array are contiguous: the first element's
// address is the flat array.
std::string flat_argument(const Param& p, bool is_const, const std::string& name) {
  if (p.view)
    return name;
  if (p.nested) // each row's data(), in a vector that lives as long as the call
    return fmt::format("dpgen::row_pointers({}).data()", name);
  if (!p.container.empty())
    return name + ".data()";
  if (p.scalar_ref)
    return "&" + name;
  if (p.rows.empty())
    return name;
  return fmt::format("reinterpret_cast<{}{}*>({})", is_const ? "const " : "", p.elem_name, name);
}

void emit_vector_size_checks(Code& code, const Kernel& k, const std::string& fn,
                             const std::string& suffix, bool (*wanted)(const Param&)) {
  for (const auto& p : k.params)
    if (!p.container.empty() && wanted(p)) {
      if (p.nested) { // (row by row: dpgen/row_pointers.hpp)
        code.line("dpgen::check_same_rows(\"{}\", \"{}{}\", {}{}, \"{}\", {});", fn, p.name, suffix,
                  p.name, suffix, p.name, p.name);
        continue;
      }
      code.open(fmt::format("if ({}{}.size() != {}.size())", p.name, suffix, p.name));
      code.line("throw std::invalid_argument(\"{}: {}{} has \" + "
                "std::to_string({}{}.size()) + \" elements but {} has \" + "
                "std::to_string({}.size()));",
                fn, p.name, suffix, p.name, suffix, p.name, p.name);
      code.close();
    }
}

namespace {
// The tag type naming member `m` of class `cls` for dpgen_member_of.
std::string access_tag(const std::string& cls, const std::string& m) {
  std::string t = cls + "_" + m;
  for (char& ch : t)
    if (ch == ':')
      ch = '_';
  return "dpgen_access::" + t;
}
} // namespace

std::string member_wrapper(const Kernel& k, bool tangent) {
  if (k.member_class.empty())
    return "";
  const std::string suffix = tangent ? "_dot" : "_adj";
  std::string out = "#ifndef DPGEN_NO_MEMBER_WRAPPERS\n";
  // Member pointers, private members too (an explicit instantiation may name
  // any member; dpgen_member_of(tag) then returns its pointer).
  out += "#ifndef DPGEN_ACCESS_DEFINED\n#define DPGEN_ACCESS_DEFINED\n"
         "namespace dpgen_access {\n"
         "template <class Tag, typename Tag::type M> struct Member {\n"
         "  friend typename Tag::type dpgen_member_of(Tag) { return M; }\n"
         "};\n"
         "} // namespace dpgen_access\n#endif\n";
  std::string cls = k.member_class;
  for (const Param& p : k.params) {
    if (!p.member || p.synthetic || !p.twin_of.empty() || p.global)
      continue; // (an in-place member's new values, u_new, are no member)
    std::string tag = access_tag(cls, p.name);
    std::string guard = "DPGEN_ACCESS_" + tag.substr(std::string("dpgen_access::").size());
    std::string type = p.view ? p.view_type : p.spelling;
    while (!type.empty() && (type.back() == '&' || type.back() == ' '))
      type.pop_back(); // (a member is an object, not a reference)
    out += fmt::format("#ifndef {0}\n#define {0}\nnamespace dpgen_access {{\n"
                       "struct {1} {{\n  using type = {2} {3}::*;\n"
                       "  friend type dpgen_member_of({1});\n}};\n"
                       "template struct Member<{1}, &{3}::{4}>;\n"
                       "}} // namespace dpgen_access\n#endif\n",
                       guard, tag.substr(std::string("dpgen_access::").size()), type, cls,
                       p.name);
  }
  // the wrapper's parameters: the method's by the rule, then the members'
  // adjoints (tangents); the call: the members from self, in the order of
  // the generated function's parameters
  std::vector<std::string> params = {fmt::format("const {}& self", cls)}, members, call;
  auto member_value = [&](const Param& p) {
    return fmt::format("self.*dpgen_member_of({}{{}})", access_tag(cls, p.name));
  };
  for (const Param& p : k.params) {
    if (p.synthetic || !p.twin_of.empty() || p.global)
      continue;
    const bool array = p.kind == ParamKind::In || p.kind == ParamKind::Out;
    std::string decl_in, decl_d;
    if (array) {
      // adjoint: an input's is accumulated, an output's is its seed; tangent:
      // an input's direction is read, an output's written
      // (an in-place array's tangent is updated in place)
      bool d_const = tangent ? p.kind == ParamKind::In && !p.inout : p.kind == ParamKind::Out;
      decl_d = array_declaration(p, d_const, p.name + suffix, true, false);
    }
    std::vector<std::string>& list = p.member ? members : params;
    if (p.member) {
      if (p.kind == ParamKind::In || p.kind == ParamKind::ConstArray ||
          p.kind == ParamKind::Scalar || (tangent && p.kind == ParamKind::Out))
        call.push_back(member_value(p));
    } else {
      if (p.kind == ParamKind::In || p.kind == ParamKind::ConstArray ||
          p.kind == ParamKind::Scalar || (tangent && p.kind == ParamKind::Out)) {
        params.push_back(p.kind == ParamKind::Scalar
                             ? fmt::format("{} {}", p.spelling, p.name)
                             : array_declaration(p, !(tangent && p.kind == ParamKind::Out),
                                                 p.name, true, false));
        call.push_back(p.name);
      }
    }
    if (array) {
      list.push_back(decl_d);
      call.push_back(p.name + suffix);
    }
  }
  params.insert(params.end(), members.begin(), members.end());
  const std::string fn = k.name.substr(0, k.name.size() - std::string("_members").size()) +
                         (tangent ? "_tangent" : "_adjoint");
  out += fmt::format("/// {} of {}: the members it reads come from `self`; the adjoints of its\n"
                     "/// annotated members follow the method's parameters, in declaration order.\n",
                     tangent ? "Tangent" : "Adjoint", k.display_name());
  out += fmt::format("inline void {}({}) {{\n  {}{}({});\n}}\n", fn, fmt::join(params, ", "),
                     k.name, tangent ? "_tangent" : "_adjoint", fmt::join(call, ", "));
  out += "#endif\n";
  return out;
}

} // namespace dpgen
