// Lowering, the globals (lower_globals.hpp): the file-scope variables a
// kernel reads, as Params bound like parameters (read-only ones are the
// kernel's constants; a DPGEN_IN array is differentiated through
// `<name>_adj`).
#include "lower_impl.hpp"

#include "print.hpp"

#include <algorithm>
#include <functional>

namespace dpgen::lowering {

void Globals::lower(const Stmt* body) {
  std::vector<const VarDecl*> found;
  std::function<void(const Stmt*)> scan = [&](const Stmt* s) {
    if (!s)
      return;
    if (const auto* r = dyn_cast<DeclRefExpr>(s))
      if (const auto* v = dyn_cast<VarDecl>(r->getDecl());
          v && v->hasGlobalStorage() && !v->isStaticLocal() && !L.global_decls_.count(v->getNameAsString()) &&
          std::find(found.begin(), found.end(), v) == found.end())
        found.push_back(v);
    for (const Stmt* c : s->children())
      scan(c);
  };
  scan(body);
  PrintingPolicy policy(L.ctx_.getLangOpts());
  policy.SuppressTagKeyword = true;
  policy.Bool = true;
  for (const VarDecl* v : found) {
    std::string ann = annotation(v);
    QualType q = v->getType();
    bool is_const = q.isConstQualified();
    bool array = q->isPointerType() || q->isConstantArrayType();
    // A constant scalar with a known value is a constant (decl_ref); one
    // whose value is not known stays an error there.
    if (is_const && !array && ann.empty())
      continue;
    Param g;
    g.name = v->getNameAsString();
    g.global = true;
    for (const DeclContext* dc = v->getDeclContext(); dc; dc = dc->getParent())
      if (const auto* ns = dyn_cast<NamespaceDecl>(dc))
        g.global_namespaces.insert(g.global_namespaces.begin(), ns->getNameAsString());
    QualType elem = q->isPointerType() ? q->getPointeeType()
                    : array ? QualType(q->getArrayElementTypeNoTypeQual(), 0)
                            : q;
    auto t = L.scalar_type(elem.getUnqualifiedType());
    if (!t || elem->isPointerType() || elem->isArrayType()) {
      L.error(v->getLocation(), fmt::format("global '{}' of type '{}' is outside the kernel "
                                          "subset (a scalar, a pointer to numbers or a "
                                          "one-dimensional array)",
                                          g.name, q.getAsString(policy)),
            "dpgen-global");
      continue;
    }
    g.elem = *t;
    g.elem_name = Lowerer::spelled(elem.getUnqualifiedType());
    g.spelling = g.elem_name;
    if (ann == "dpgen.in") {
      if (!array || !is_real(*t) || elem.isConstQualified()) {
        L.error(v->getLocation(), fmt::format("DPGEN_IN global '{}' must be a pointer to or an "
                                            "array of non-const float or double",
                                            g.name),
              "dpgen-global");
        continue;
      }
      g.kind = ParamKind::In;
    } else if (!ann.empty()) {
      L.error(v->getLocation(), fmt::format("global '{}' is marked {}; a global is read only: "
                                          "unmarked (a constant) or DPGEN_IN (differentiated)",
                                          g.name, ann == "dpgen.out" ? "DPGEN_OUT" : ann),
            "dpgen-global");
      continue;
    } else {
      g.kind = array ? ParamKind::ConstArray : ParamKind::Scalar;
    }
    if (const auto* ca = L.ctx_.getAsConstantArrayType(q))
      g.global_count = static_cast<long long>(ca->getSize().getZExtValue());
    std::string decl;
    llvm::raw_string_ostream os(decl);
    q.print(os, policy, g.name);
    decl = os.str();
    if (is_const && array) {
      // A constant table (constexpr double w[3] = {...}) has internal
      // linkage: the generated files hold a copy of its values.
      const APValue* val = v->evaluateValue();
      if (!val || !val->isArray()) {
        L.error(v->getLocation(), fmt::format("constant global array '{}' has no value dpgen "
                                            "can read (initialise it with constants)",
                                            g.name),
              "dpgen-global");
        continue;
      }
      std::vector<std::string> vals;
      for (unsigned i = 0; i < val->getArraySize(); ++i) {
        const APValue& e = i < val->getArrayInitializedElts() ? val->getArrayInitializedElt(i)
                                                              : val->getArrayFiller();
        vals.push_back(e.isFloat() ? real_literal(e.getFloat().convertToDouble(), Type::Double)
                                   : std::to_string(e.getInt().getSExtValue()));
      }
      g.global_declaration = fmt::format("static {} = {{{}}};", decl, fmt::join(vals, ", "));
    } else {
      if (v->getStorageClass() == SC_Static || v->isInAnonymousNamespace()) {
        L.error(v->getLocation(), fmt::format("global '{}' is static: the generated files, "
                                            "another translation unit, cannot read it; give it "
                                            "external linkage or pass it as a parameter",
                                            g.name),
              "dpgen-global");
        continue;
      }
      g.global_declaration = "extern " + decl + ";";
    }
    g.declaration = decl;
    for (const auto& other : L.k_.params)
      if (other.name == g.name)
        L.error(v->getLocation(), fmt::format("global '{}' has the name of a parameter", g.name),
              "dpgen-global");
    L.global_decls_[g.name] = v;
    L.k_.params.push_back(g);
  }
}

} // namespace dpgen::lowering
