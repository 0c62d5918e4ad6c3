// Lower (phase 2): the body of a DPGEN_KERNEL function, as Clang parsed it,
// becomes kernel IR (ir.hpp): loops, stores under their path conditions, SSA
// locals, inlined helper calls. Every construct outside the subset is
// reported at its location, every statement's error in turn, and the kernel
// is dropped; nothing is guessed. The lowered kernel then goes through the
// output rules (check.hpp). find.cpp hands it the functions to lower.
#include "lower.hpp"
#include "lower_impl.hpp"
#include "print.hpp"

namespace dpgen::lowering {

// An error at `loc` through Clang (which shows the line and any macro
// expansion behind it), ending with its id: "message [dpgen-loop]".
void report_error(ASTContext& ctx, SourceLocation loc, const std::string& msg,
                  const std::string& id) {
  auto& d = ctx.getDiagnostics();
  unsigned diag = d.getCustomDiagID(DiagnosticsEngine::Error, "%0");
  d.Report(loc, diag) << msg + " [" + id + "]";
}

// Reports the errors of the checks (check.cpp) through Clang, at the
// position the IR carries: at the SourceLocation it was made from, so the
// diagnostic shows the source line and any macro expansion as Clang would.
class ClangDiagnostics : public Diagnostics {
public:
  ClangDiagnostics(ASTContext& ctx, SourceLocation fallback) : ctx_(ctx), fallback_(fallback) {}

  void error(const SourcePos& at, const std::string& id, const std::string& message) override {
    report_error(ctx_, location(at), message, id);
  }

private:
  SourceLocation location(const SourcePos& at) const {
    if (at.loc)
      return SourceLocation::getFromRawEncoding(SourceLocation::UIntTy(at.loc));
    // A position made without a location: its file, line and column.
    const auto& sm = ctx_.getSourceManager();
    if (auto f = sm.getFileManager().getOptionalFileRef(at.file)) {
      SourceLocation loc = sm.translateFileLineCol(&f->getFileEntry(), at.line, at.col);
      if (loc.isValid())
        return loc;
    }
    return fallback_;
  }

  ASTContext& ctx_;
  SourceLocation fallback_;
};

bool Lowerer::run(Kernel& out) {
  try {
    sig_.header();
    stmts_.body(fn_->getBody());
    if (failed_)
      return false; // every statement's error is reported; the checks need them all
    // A line buffer that no loop reads after another wrote it (unused, or
    // read back only in the iteration that stored it, where the read is the
    // stored value) needs no hidden array: its stores reach no output.
    auto dead = [&](const std::string& a) {
      return bufs_.is_buffer(a) && !k_.intermediates.count(a);
    };
    std::vector<Nest> kept;
    for (auto& n : k_.nests) {
      size_t had = n.stores.size();
      n.stores.erase(std::remove_if(n.stores.begin(), n.stores.end(),
                                    [&](const Store& st) { return dead(st.array); }),
                     n.stores.end());
      if (n.stores.size() == had || !n.stores.empty())
        kept.push_back(std::move(n)); // (a nest of such stores alone goes)
    }
    k_.nests = std::move(kept);
    for (const auto& h : k_.hidden)
      if (dead(h.name))
        acc_.buffers.erase(h.name);
    k_.hidden.erase(std::remove_if(k_.hidden.begin(), k_.hidden.end(),
                                   [&](const Param& h) { return dead(h.name); }),
                    k_.hidden.end());
    ClangDiagnostics diag(ctx_, fn_->getLocation());
    if (!check_kernel(k_, acc_, diag))
      return false;
  } catch (const Rejected&) {
    return false;
  }
  if (failed_)
    return false;
  collect_names();
  out = std::move(k_);
  return true;
}

// Lowers `s`; on an error (already reported) marks the kernel failed and
// goes on, unless inside a helper or an unrolled loop (whose copies would
// repeat the same error), where the error propagates.
Escape Lowerer::lower_recovering(const Stmt* s) {
  if (!frames_.empty() || unrolling_ > 0)
    return stmts_.lower(s);
  try {
    return stmts_.lower(s);
  } catch (const Rejected&) {
    failed_ = true;
    if (const auto* d = dyn_cast<DeclStmt>(s))
      for (const Decl* decl : d->decls())
        if (const auto* v = dyn_cast<VarDecl>(decl))
          poisoned_.insert(v);
    return Escape::None;
  }
}

// A statement that reads `array` (an output) or updates an element of it
// that this nest stored goes after every nest created since this one that
// stores `array` (a loop that accumulated into it, or wrote it): a new
// segment. Otherwise it would be folded into the earlier statements.
void Lowerer::order_after_later_stores(const std::string& array) {
  auto it = nest_index_.find(cur_key());
  if (it == nest_index_.end())
    return;
  for (size_t i = it->second + 1; i < k_.nests.size(); ++i)
    for (const auto& st : k_.nests[i].stores)
      if (st.array == array) {
        segments_.back() = --next_segment_;
        return;
      }
}

// Where `loc` is (its expansion, for a macro), keeping `loc` itself for
// diagnostics at the position (ClangDiagnostics).
SourcePos Lowerer::pos(SourceLocation loc) const {
  SourcePos out;
  out.loc = loc.getRawEncoding();
  PresumedLoc p = sm_.getPresumedLoc(sm_.getExpansionLoc(loc));
  if (p.isInvalid())
    return out;
  out.file = p.getFilename();
  out.line = p.getLine();
  out.col = p.getColumn();
  return out;
}

// T of a std::vector<T> (any allocator); null for any other type.
// A kernel-level `const std::ptrdiff_t <name>_<suffix> = def;` through which
// generated code reads parameter `name` (its unsigned or enum value): its
// reference.
ExprP Lowerer::integer_copy(const std::string& name, const char* suffix, const ExprP& def) {
  auto l = std::make_shared<LocalVar>();
  l->name = name + "_" + suffix;
  for (int n = 1; is_reserved(l->name) || local_names_.count(l->name); ++n)
    l->name = fmt::format("{}_{}_{}", unprefixed(name), suffix, n);
  l->type_name = "std::ptrdiff_t";
  l->def = def;
  l->id = next_local_id_++;
  l->kernel_level = true;
  l->opaque = true;
  local_names_.insert(l->name);
  k_.kernel_locals.push_back(l);
  return local_ref(l);
}

QualType Lowerer::vector_element(QualType q, const char* which) const {
  const auto* rd = q.getCanonicalType()->getAsCXXRecordDecl();
  const auto* spec = dyn_cast_or_null<ClassTemplateSpecializationDecl>(rd);
  if (!spec || spec->getName() != which || !spec->isInStdNamespace() ||
      spec->getTemplateArgs().size() < 1)
    return QualType();
  return spec->getTemplateArgs()[0].getAsType();
}

// std::array<T, N>: (T, N); nullopt for any other type.
std::optional<std::pair<QualType, uint64_t>> Lowerer::std_array(QualType q) const {
  const auto* rd = q.getNonReferenceType().getCanonicalType()->getAsCXXRecordDecl();
  const auto* spec = dyn_cast_or_null<ClassTemplateSpecializationDecl>(rd);
  if (!spec || spec->getName() != "array" || !spec->isInStdNamespace() ||
      spec->getTemplateArgs().size() != 2 ||
      spec->getTemplateArgs()[1].getKind() != TemplateArgument::Integral)
    return std::nullopt;
  return std::pair{spec->getTemplateArgs()[0].getAsType(),
                   spec->getTemplateArgs()[1].getAsIntegral().getZExtValue()};
}

std::optional<Type> Lowerer::scalar_type(QualType q) const {
  q = q.getCanonicalType().getUnqualifiedType();
  if (q->isBooleanType())
    return Type::Bool;
  if (q->isIntegerType() || q->isEnumeralType())
    return Type::Int;
  if (q->isSpecificBuiltinType(BuiltinType::Float))
    return Type::Float;
  if (q->isSpecificBuiltinType(BuiltinType::Double))
    return Type::Double;
  return std::nullopt;
}

Type Lowerer::type_of(const clang::Expr* e) {
  auto t = scalar_type(e->getType());
  if (!t)
    fail(e->getExprLoc(), fmt::format("expression of type '{}' is outside the kernel subset "
                                      "(only int, float, double and bool values)",
                                      e->getType().getAsString()));
  return *t;
}

// ---- names ---------------------------------------------------------------

ExprP Lowerer::opaque_symbol(const std::string& name, long long value) {
  auto l = std::make_shared<LocalVar>();
  l->name = name;
  l->type_name = "std::ptrdiff_t";
  l->def = int_const(value);
  l->opaque = true;
  l->id = next_local_id_++;
  l->kernel_level = true;
  local_names_.insert(l->name);
  k_.kernel_locals.push_back(l);
  return local_ref(l);
}

// Names a local or a loop counter must not keep (it is renamed <name>_1):
// a parameter, an enclosing counter, a name the signature rule gives an
// adjoint or tangent parameter (<array>_adj, <array>_dot), the prefix
// dpgen_ of generated helpers, or a C++ keyword (a C kernel's `new`: the
// generated code is C++).
bool Lowerer::is_reserved(const std::string& name) const {
  if (k_.find_param(name) || contract_name_of(name) || name.rfind("dpgen_", 0) == 0 ||
      is_cxx_only_keyword(name))
    return true;
  for (const auto& l : loops_)
    if (l->var == name)
      return true;
  return false;
}

// The array parameter whose adjoint or tangent the signature rule names
// `name` (<array>_adj, <array>_dot), or null.
const Param* Lowerer::contract_name_of(const std::string& name) const {
  for (const char* suffix : {"_adj", "_dot"}) {
    size_t n = std::char_traits<char>::length(suffix);
    if (name.size() > n && name.compare(name.size() - n, n, suffix) == 0)
      if (const Param* p = k_.find_param(name.substr(0, name.size() - n));
          p && p->kind != ParamKind::Scalar)
        return p;
  }
  return nullptr;
}

bool Lowerer::is_cxx_only_keyword(const std::string& name) {
  static const std::set<std::string> keywords = {
      "alignas",    "alignof",      "and",       "and_eq",      "asm",
      "bitand",     "bitor",        "bool",      "catch",       "char8_t",
      "char16_t",   "char32_t",     "class",     "compl",       "concept",
      "consteval",  "constexpr",    "constinit", "const_cast",  "co_await",
      "co_return",  "co_yield",     "decltype",  "delete",      "dynamic_cast",
      "explicit",   "export",       "false",     "friend",      "mutable",
      "namespace",  "new",          "noexcept",  "not",         "not_eq",
      "nullptr",    "operator",     "or",        "or_eq",       "private",
      "protected",  "public",       "reinterpret_cast", "requires", "static_assert",
      "static_cast", "template",    "this",      "thread_local", "throw",
      "true",       "try",          "typeid",    "typename",    "using",
      "virtual",    "wchar_t",      "xor",       "xor_eq"};
  return keywords.count(name) > 0;
}

// Every name the generated code takes from the kernel (Kernel::names).
void Lowerer::collect_names() {
  for (const auto& p : k_.params) {
    k_.names.insert(p.name);
    if (p.kind != ParamKind::Scalar) {
      k_.names.insert(p.name + "_adj");
      k_.names.insert(p.name + "_dot");
    }
  }
  k_.names.insert(local_names_.begin(), local_names_.end());
  k_.names.insert(loop_names_.begin(), loop_names_.end());
}

// `e >= 0` wherever this statement runs: its loops run, the counters are
// in range, the conditions on its path hold, unsigned sizes are >= 0.
bool Lowerer::provably_nonneg(const ExprP& e, const std::vector<PathCond>& more) const {
  auto p = to_poly(e);
  if (!p)
    return false;
  Facts f;
  for (const auto& pc : more)
    add_facts_with_counters(pc, f);
  for (const auto& l : loops_) {
    add_nonempty(*l, f);
    add_counter_range(*l, f);
  }
  for (const auto& pc : path_)
    add_facts_with_counters(pc, f);
  for (const auto& [name, v] : signed_views_)
    f.push_back(*to_poly(v));
  // `a != b` (`i == 0 ? ... : i - 1` in its else arm) is a case split:
  // a - b >= 1 or b - a >= 1; the goal must hold in both.
  std::vector<Poly> ne;
  auto collect_ne = [&](const PathCond& pc) {
    const ExprP& c = pc.cond;
    bool is_ne = (c->op == Op::Ne && pc.positive) || (c->op == Op::Eq && !pc.positive);
    if (is_ne && c->ops.size() == 2 && c->ops[0]->type == Type::Int)
      if (auto pa = to_poly(c->ops[0]), pb = to_poly(c->ops[1]); pa && pb)
        ne.push_back(*pa - *pb);
  };
  for (const auto& pc : more)
    collect_ne(pc);
  for (const auto& pc : path_)
    collect_ne(pc);
  if (ne.size() > 3)
    ne.resize(3);
  std::function<bool(size_t, Facts&)> split = [&](size_t k, Facts& facts) {
    if (k == ne.size())
      return prove_nonneg(*p, facts);
    for (const Poly& side : {ne[k] - Poly::constant(1), -ne[k] - Poly::constant(1)}) {
      facts.push_back(side);
      bool ok = split(k + 1, facts);
      facts.pop_back();
      if (!ok)
        return false;
    }
    return true;
  };
  return prove_nonneg(*p, f) || (!ne.empty() && split(0, f));
}

namespace {

// The conditions in `e` that are no conjunction, disjunction or negation: the
// atoms of a truth table, by their text (the same text, the same value).
struct Atoms {
  std::map<std::string, size_t> by_text;
  std::map<const Expr*, size_t> at;
};

void path_atoms(const ExprP& e, Atoms& atoms) {
  if (e->op == Op::And || e->op == Op::Or || e->op == Op::Not) {
    for (const auto& o : e->ops)
      path_atoms(o, atoms);
    return;
  }
  if (!atoms.at.count(e.get()))
    atoms.at[e.get()] = atoms.by_text.emplace(print(e), atoms.by_text.size()).first->second;
}

bool holds(const ExprP& e, const Atoms& atoms, unsigned values) {
  switch (e->op) {
  case Op::And:
    return holds(e->ops[0], atoms, values) && holds(e->ops[1], atoms, values);
  case Op::Or:
    return holds(e->ops[0], atoms, values) || holds(e->ops[1], atoms, values);
  case Op::Not:
    return !holds(e->ops[0], atoms, values);
  default:
    return (values >> atoms.at.at(e.get())) & 1u;
  }
}

} // namespace

// Whether no iteration takes both paths: a pair of opposite conditions, else
// no row of the truth table over the conditions' atoms (each a free boolean,
// which only adds rows) satisfies both, as after an escape nested in an arm
// (`if (i > 2) { if (i > 4) { v[i] = u[i]; continue; } } v[i] = 2 * u[i];`:
// the second store's path is `i > 2 && !(i > 4) || !(i > 2)`).
bool paths_disjoint(const std::vector<PathCond>& a, const std::vector<PathCond>& b) {
  for (const auto& x : a)
    for (const auto& y : b)
      if (x.cond == y.cond && x.positive != y.positive)
        return true;
  if (a.empty() || b.empty())
    return false;
  Atoms atoms;
  for (const auto* path : {&a, &b})
    for (const auto& pc : *path)
      path_atoms(pc.cond, atoms);
  if (atoms.by_text.size() > 12)
    return false;
  for (unsigned values = 0; values < (1u << atoms.by_text.size()); ++values) {
    bool both = true;
    for (const auto* path : {&a, &b})
      for (const auto& pc : *path)
        both = both && holds(pc.cond, atoms, values) == pc.positive;
    if (both)
      return false;
  }
  return true;
}

const Param* Lowerer::scalar_ref_param(const clang::Expr* e) const {
  const auto* r = dyn_cast<DeclRefExpr>(e->IgnoreParenImpCasts());
  if (!r)
    return nullptr;
  auto it = env_.find(dyn_cast<VarDecl>(r->getDecl()));
  if (it == env_.end() || it->second.kind != Binding::ArrayParam || !it->second.param->scalar_ref)
    return nullptr;
  return it->second.param;
}

// What `e` names: a variable or a member of the kernel's object (lower_impl.hpp).
const Binding* Lowerer::bound(const clang::Expr* e) const {
  e = e->IgnoreParenImpCasts();
  if (const auto* r = dyn_cast<DeclRefExpr>(e)) {
    const auto* v = dyn_cast<VarDecl>(r->getDecl());
    if (!v)
      return nullptr;
    if (poisoned_.count(v))
      throw Rejected{};
    auto it = env_.find(v);
    return it == env_.end() ? nullptr : &it->second;
  }
  const auto* m = dyn_cast<MemberExpr>(e);
  const auto* f = m ? dyn_cast<FieldDecl>(m->getMemberDecl()) : nullptr;
  if (!f || !isa<CXXThisExpr>(m->getBase()->IgnoreParenImpCasts()))
    return nullptr;
  if (poisoned_.count(f))
    throw Rejected{};
  auto it = fields_.find(f);
  return it == fields_.end() ? nullptr : &it->second;
}

} // namespace dpgen::lowering

namespace dpgen {

using lowering::Lowerer;
using lowering::report_error;

std::string annotation(const clang::Decl* d) {
  for (const auto* a : d->specific_attrs<clang::AnnotateAttr>()) {
    llvm::StringRef s = a->getAnnotation();
    if (s.starts_with("dpgen."))
      return s.str();
  }
  return "";
}

bool lower_kernel(clang::ASTContext& ctx, const clang::FunctionDecl* fn, Kernel& out) {
  try {
    test_internal_error("lower");
    return Lowerer(ctx, fn).run(out);
  } catch (const std::exception& e) { // a broken invariant: a bug in dpgen, not in the kernel
    report_error(ctx, fn->getLocation(), internal_error_message(fn->getNameAsString(), "lower", e.what()),
                 "dpgen-internal");
    return false;
  }
}

} // namespace dpgen
