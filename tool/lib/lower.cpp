// Lower (phase 2): the body of a DPGEN_KERNEL function, as Clang parsed it,
// becomes kernel IR (ir.hpp): loops, stores under their path conditions, SSA
// locals, inlined helper calls. Every construct outside the subset is
// reported at its location, every statement's error in turn, and the kernel
// is dropped; nothing is guessed. The lowered kernel then goes through the
// output rules (check.hpp). find.cpp hands it the functions to lower.
#include "lower.hpp"

#include "check.hpp"
#include "ir_walk.hpp"
#include "ops.hpp"

#include "affine.hpp"
#include "prove.hpp"

#include <clang/AST/ASTContext.h>
#include <clang/AST/Attr.h>
#include <clang/AST/Expr.h>
#include <clang/AST/ExprCXX.h>
#include <clang/AST/ParentMapContext.h>
#include <clang/AST/Stmt.h>
#include <clang/AST/StmtCXX.h>
#include <clang/AST/StmtOpenMP.h>
#include <clang/Basic/FileManager.h>
#include <clang/Basic/SourceManager.h>
#include <clang/Lex/Lexer.h>
#include <fmt/format.h>
#include <llvm/Support/raw_ostream.h>

#include <functional>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>

namespace dpgen {

namespace {

using namespace clang;

// What a name in the kernel body refers to.
struct Binding {
  enum Kind { ScalarParam, ArrayParam, LoopVar, Value, LocalArray, Lambda } kind;
  // Lambda: the closure's class, and the value each variable captured by copy
  // had when the lambda was made (a call checks it has not changed since).
  const clang::CXXRecordDecl* closure = nullptr;
  std::vector<std::pair<const clang::VarDecl*, std::optional<ExprP>>> captured;
  std::vector<std::pair<const clang::VarDecl*, std::vector<std::optional<ExprP>>>>
      captured_arrays; // local arrays captured by copy: their elements then
  std::optional<ExprP> value;              // Value: current SSA value (none: uninitialised)
  std::vector<std::optional<ExprP>> elems; // LocalArray: each element's value (none: unset)
  Type elem = Type::Double; // LocalArray: element type
  const Param* param = nullptr;
  bool kernel_level = false; // Value defined outside every loop
  // Value: a helper's pointer parameter bound to a caller's local (`&f`),
  // used only as `*p`; the binding holds the local's value.
  bool deref_only = false;
};

// An error at `loc` through Clang (which shows the line and any macro
// expansion behind it), ending with its id: "message [dpgen-loop]".
void report_error(ASTContext& ctx, SourceLocation loc, const std::string& msg,
                  const std::string& id) {
  auto& d = ctx.getDiagnostics();
  unsigned diag = d.getCustomDiagID(DiagnosticsEngine::Error, "%0");
  d.Report(loc, diag) << msg + " [" + id + "]";
}

// Thrown to abandon a kernel after its diagnostic has been reported.
struct Rejected {};

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

enum class Escape { None, Always };

class Lowerer {
public:
  Lowerer(ASTContext& ctx, const FunctionDecl* fn) : ctx_(ctx), sm_(ctx.getSourceManager()), fn_(fn) {}

  bool run(Kernel& out) {
    try {
      header();
      body(fn_->getBody());
      if (failed_)
        return false; // every statement's error is reported; the checks need them all
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

  // Errors in one statement do not stop the lowering of the next ones, so a
  // run reports every error of a kernel. A variable whose declaration failed
  // is poisoned: its uses are not reported again.
  bool failed_ = false;
  std::set<const VarDecl*> poisoned_;

  // Lowers `s`; on an error (already reported) marks the kernel failed and
  // goes on, unless inside a helper or an unrolled loop (whose copies would
  // repeat the same error), where the error propagates.
  Escape lower_recovering(const Stmt* s) {
    if (!frames_.empty() || unrolling_ > 0)
      return lower(s);
    try {
      return lower(s);
    } catch (const Rejected&) {
      failed_ = true;
      if (const auto* d = dyn_cast<DeclStmt>(s))
        for (const Decl* decl : d->decls())
          if (const auto* v = dyn_cast<VarDecl>(decl))
            poisoned_.insert(v);
      return Escape::None;
    }
  }

private:
  ASTContext& ctx_;
  SourceManager& sm_;
  const FunctionDecl* fn_;
  Kernel k_;
  std::map<const VarDecl*, Binding> env_;
  std::vector<PathCond> path_;
  std::vector<std::shared_ptr<Loop>> loops_;
  // Each `for` statement lowered gets its own number; a nest is keyed by the
  // numbers of the loops around it, so two nests never share an entry even
  // when they reuse counter names (or a freed Loop's address).
  std::vector<int> loop_ids_;
  int next_loop_id_ = 0;
  // Straight-line code after a loop that stored an output, and that reads or
  // rewrites what the loop stored, runs after the loop: it opens a new
  // segment, a nest of its own at the same depth (negative numbers, one per
  // depth, the last entry of a nest's key).
  std::vector<int> segments_{-1};
  int next_segment_ = -1;
  std::vector<int> cur_key() const {
    std::vector<int> k = loop_ids_;
    k.push_back(segments_.back());
    return k;
  }
  // A statement that reads `array` (an output) or updates an element of it
  // that this nest stored goes after every nest created since this one that
  // stores `array` (a loop that accumulated into it, or wrote it): a new
  // segment. Otherwise it would be folded into the earlier statements.
  void order_after_later_stores(const std::string& array) {
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
  std::map<std::vector<int>, size_t> nest_index_;
  std::map<std::string, ExprP> row_lengths_; // row-pointer array -> its row symbol
  std::map<std::string, ExprP> plane_lengths_; // double*** array -> its plane symbol
  std::map<std::string, ExprP> signed_views_; // unsigned scalar parameter -> its signed copy
  ExprP scalar_param(const std::string& name, Type t) {
    auto it = signed_views_.find(name);
    return it != signed_views_.end() ? it->second : param(name, t);
  }
  std::set<std::string> local_names_;
  std::set<std::string> loop_names_; // every counter name the generated code uses
  // Why a variable has no value here, where that is more than "not yet set".
  std::map<const VarDecl*, std::string> why_unset_;
  int next_local_id_ = 0;

  // ---- diagnostics -------------------------------------------------------

  // An error that does not stop the lowering (the others are reported too).
  // Every diagnostic ends with its id, clang-tidy style ("[dpgen-loop]"): the
  // rule of the kernel subset it is about, which tests match instead of the
  // sentence. The ids: dpgen-signature (parameters and annotations),
  // dpgen-name (names the generated code needs), dpgen-loop (loop headers),
  // dpgen-call (math functions and helpers), dpgen-lambda, and
  // dpgen-unsupported (any other construct outside the subset); the output
  // rules have theirs (check.cpp).
  void error(SourceLocation loc, const std::string& msg, const char* id = "dpgen-unsupported") {
    report_error(ctx_, loc, msg, id);
    failed_ = true;
  }

  [[noreturn]] void fail(SourceLocation loc, const std::string& msg,
                         const char* id = "dpgen-unsupported") {
    error(loc, msg, id);
    throw Rejected{};
  }

  // Where `loc` is (its expansion, for a macro), keeping `loc` itself for
  // diagnostics at the position (ClangDiagnostics).
  SourcePos pos(SourceLocation loc) const {
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

  std::string text(const Stmt* s) const {
    return Lexer::getSourceText(CharSourceRange::getTokenRange(s->getSourceRange()), sm_,
                                ctx_.getLangOpts())
        .str();
  }

  // ---- types ---------------------------------------------------------------

  // T of a std::vector<T> (any allocator); null for any other type.
  QualType vector_element(QualType q, const char* which = "vector") const {
    const auto* rd = q.getCanonicalType()->getAsCXXRecordDecl();
    const auto* spec = dyn_cast_or_null<ClassTemplateSpecializationDecl>(rd);
    if (!spec || spec->getName() != which || !spec->isInStdNamespace() ||
        spec->getTemplateArgs().size() < 1)
      return QualType();
    return spec->getTemplateArgs()[0].getAsType();
  }

  // std::array<T, N>: (T, N); nullopt for any other type.
  std::optional<std::pair<QualType, uint64_t>> std_array(QualType q) const {
    const auto* rd = q.getNonReferenceType().getCanonicalType()->getAsCXXRecordDecl();
    const auto* spec = dyn_cast_or_null<ClassTemplateSpecializationDecl>(rd);
    if (!spec || spec->getName() != "array" || !spec->isInStdNamespace() ||
        spec->getTemplateArgs().size() != 2 ||
        spec->getTemplateArgs()[1].getKind() != TemplateArgument::Integral)
      return std::nullopt;
    return std::pair{spec->getTemplateArgs()[0].getAsType(),
                     spec->getTemplateArgs()[1].getAsIntegral().getZExtValue()};
  }

  // A type as the generated code spells it: canonical, so a typedef of the
  // user's (`FLOAT`, `real_t`) or a library alias (`size_t`) never appears in
  // a generated file that does not declare it.
  static std::string spelled(QualType q, bool keep_const = false) {
    QualType c = q.getCanonicalType();
    if (!keep_const)
      c = c.getUnqualifiedType();
    return c.getAsString();
  }

  std::optional<Type> scalar_type(QualType q) const {
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

  Type type_of(const clang::Expr* e) {
    auto t = scalar_type(e->getType());
    if (!t)
      fail(e->getExprLoc(), fmt::format("expression of type '{}' is outside the kernel subset "
                                        "(only int, float, double and bool values)",
                                        e->getType().getAsString()));
    return *t;
  }

  // ---- the function header -----------------------------------------------

  void header() {
    if (isa<CXXMethodDecl>(fn_))
      fail(fn_->getLocation(), "a DPGEN_KERNEL must be a free function, not a member function", "dpgen-signature");
    if (fn_->isTemplated() || fn_->getTemplatedKind() != FunctionDecl::TK_NonTemplate)
      fail(fn_->getLocation(), "a DPGEN_KERNEL must not be a template; write one kernel per "
                               "element type", "dpgen-signature");
    if (!fn_->getReturnType()->isVoidType())
      fail(fn_->getLocation(), "a DPGEN_KERNEL must return void; results go to DPGEN_OUT arrays", "dpgen-signature");
    if (fn_->isVariadic())
      fail(fn_->getLocation(), "a DPGEN_KERNEL must not be variadic", "dpgen-signature");

    k_.name = fn_->getNameAsString();
    k_.pos = pos(fn_->getLocation());
    for (const DeclContext* dc = fn_->getDeclContext(); dc; dc = dc->getParent())
      if (const auto* ns = dyn_cast<NamespaceDecl>(dc))
        k_.namespaces.insert(k_.namespaces.begin(), ns->getNameAsString());

    bool any_in = false, any_out = false;
    // One parameter; an error in it is reported, the parameter poisoned (its
    // uses are not reported again) and the rest of the kernel still lowered,
    // so one run reports every error of the file.
    auto parameter = [&](const ParmVarDecl* p) {
      Param out;
      out.name = p->getNameAsString();
      if (out.name.empty())
        fail(p->getLocation(), "every kernel parameter needs a name", "dpgen-signature");
      std::string ann = annotation(p);
      QualType q = p->getType();
      std::optional<Param> size_param;
      std::optional<Param> inout_twin;
      // std::span<T> u (by value; C++20), with the element's constness.
      QualType span_elem = q->isReferenceType() ? QualType() : vector_element(q, "span");
      if (q->isReferenceType() || !span_elem.isNull()) {
        QualType elem = !span_elem.isNull() ? span_elem : vector_element(q.getNonReferenceType());
        if (elem.isNull())
          fail(p->getLocation(), fmt::format("parameter '{}' is a reference; pass scalars by value, "
                                             "and arrays as pointers, std::vector<T>& or "
                                             "std::span<T>",
                                             out.name), "dpgen-signature");
        // std::vector<T>& u (or std::span<T> u): elements u[i], size u.size();
        // the generated entry point takes the vectors (spans), its flat twin
        // u.data() and u.size().
        bool is_const = !span_elem.isNull() ? elem.isConstQualified()
                                            : q.getNonReferenceType().isConstQualified();
        elem = elem.getUnqualifiedType();
        out.span = !span_elem.isNull();
        auto et = scalar_type(elem);
        if (!et || *et == Type::Bool)
          fail(p->getLocation(), fmt::format("parameter '{}' holds '{}'; arrays must hold "
                                             "float, double or an integer type",
                                             out.name, elem.getAsString()), "dpgen-signature");
        out.elem = *et;
        out.elem_name = spelled(elem);
        out.container = fmt::format(out.span ? "std::span<{}>" : "std::vector<{}>", out.elem_name);
        if (ann == "dpgen.inout")
          fail(p->getLocation(), fmt::format("DPGEN_INOUT parameter '{}' must be a flat pointer "
                                             "to non-const float or double (pass {}.data())",
                                             out.name, out.name), "dpgen-signature");
        if (ann == "dpgen.in" || ann == "dpgen.out") {
          if (!is_real(*et))
            fail(p->getLocation(), fmt::format("{} parameter '{}' must hold float or double",
                                               ann == "dpgen.in" ? "DPGEN_IN" : "DPGEN_OUT",
                                               out.name), "dpgen-signature");
          if (ann == "dpgen.out" && is_const)
            fail(p->getLocation(), fmt::format("DPGEN_OUT parameter '{}' is const", out.name), "dpgen-signature");
          out.kind = ann == "dpgen.in" ? ParamKind::In : ParamKind::Out;
          (ann == "dpgen.in" ? any_in : any_out) = true;
        } else {
          if (!is_const)
            fail(p->getLocation(), fmt::format("unmarked parameter '{}' is a non-const reference: "
                                               "mark it DPGEN_OUT, or make it const",
                                               out.name), "dpgen-signature");
          out.kind = ParamKind::ConstArray;
        }
        Param sz;
        sz.name = out.name + "_size";
        sz.kind = ParamKind::Scalar;
        sz.elem = Type::Int;
        sz.elem_name = sz.spelling = "unsigned long";
        sz.synthetic = true;
        sz.is_unsigned = true;
        size_param = sz;
      } else if (q->isPointerType()) {
        QualType elem = q->getPointeeType();
        // Rows of a multi-dimensional array: double (*a)[64], double a[][64],
        // or, in C, double a[n][n] (a variable-length row: flat in the
        // generated signature).
        bool const_rows = elem.isConstQualified();
        while (const clang::ArrayType* at = ctx_.getAsArrayType(elem)) {
          if (const auto* c = dyn_cast<ConstantArrayType>(at))
            out.rows += fmt::format("[{}]", c->getSize().getZExtValue());
          else if (!isa<VariableArrayType>(at))
            fail(p->getLocation(), fmt::format("parameter '{}' has an array type outside the "
                                               "kernel subset",
                                               out.name), "dpgen-signature");
          elem = at->getElementType();
          const_rows = const_rows || elem.isConstQualified();
        }
        if (const_rows)
          elem.addConst();
        if (elem->isPointerType() && out.rows.empty()) {
          // double** a, const double* const* a: rows through pointers, each
          // row an array of its own (documented assumption).
          elem = elem->getPointeeType();
          if (elem->isPointerType()) { // double*** a: planes of rows
            elem = elem->getPointeeType();
            out.plane_pointers = true;
          }
          if (elem->isPointerType() || ctx_.getAsArrayType(elem))
            fail(p->getLocation(),
                 fmt::format("parameter '{}' ('{}') has more than two levels of row pointers: "
                             "pass 'double** {}' (a[j][i]), 'double*** {}' (a[k][j][i]) or a "
                             "flat pointer indexed {}[(k * ny + j) * nx + i]",
                             out.name, q.getAsString(), out.name, out.name, out.name), "dpgen-signature");
          if (ann == "dpgen.inout")
            fail(p->getLocation(), fmt::format("DPGEN_INOUT parameter '{}' must be a flat "
                                               "pointer to non-const float or double",
                                               out.name), "dpgen-signature");
          out.row_pointers = true;
        } else if (elem->isPointerType()) {
          fail(p->getLocation(), fmt::format("parameter '{}' ('{}') mixes fixed-length rows and "
                                             "row pointers, outside the kernel subset",
                                             out.name, q.getAsString()), "dpgen-signature");
        }
        auto et = scalar_type(elem);
        if (!et || *et == Type::Bool)
          fail(p->getLocation(), fmt::format("parameter '{}' points to '{}'; arrays must hold "
                                             "float, double or an integer type",
                                             out.name, elem.getAsString()), "dpgen-signature");
        out.elem = *et;
        out.elem_name = spelled(elem);
        if (ann == "dpgen.in") {
          if (!is_real(*et))
            fail(p->getLocation(), fmt::format("DPGEN_IN parameter '{}' must point to float or "
                                               "double, not '{}'",
                                               out.name, elem.getAsString()), "dpgen-signature");
          out.kind = ParamKind::In;
          any_in = true;
        } else if (ann == "dpgen.inout") {
          if (!is_real(*et) || elem.isConstQualified() || !out.rows.empty())
            fail(p->getLocation(), fmt::format("DPGEN_INOUT parameter '{}' must be a flat pointer "
                                               "to non-const float or double",
                                               out.name), "dpgen-signature");
          out.kind = ParamKind::In;
          out.inout = true;
          any_in = any_out = true;
          Param twin;
          twin.name = out.name + "_new";
          twin.kind = ParamKind::Out;
          twin.elem = *et;
          twin.elem_name = out.elem_name;
          twin.twin_of = out.name;
          twin.declaration = twin.spelling = fmt::format("{}* {}", out.elem_name, twin.name);
          inout_twin = twin;
        } else if (ann == "dpgen.out") {
          if (!is_real(*et))
            fail(p->getLocation(), fmt::format("DPGEN_OUT parameter '{}' must point to float or "
                                               "double, not '{}'",
                                               out.name, elem.getAsString()), "dpgen-signature");
          if (elem.isConstQualified())
            fail(p->getLocation(), fmt::format("DPGEN_OUT parameter '{}' points to const", out.name), "dpgen-signature");
          out.kind = ParamKind::Out;
          any_out = true;
        } else {
          out.kind = ParamKind::ConstArray;
        }
      } else {
        auto t = scalar_type(q);
        if (!t)
          fail(p->getLocation(), fmt::format("parameter '{}' has type '{}', outside the kernel "
                                             "subset",
                                             out.name, q.getAsString()), "dpgen-signature");
        if (!ann.empty() && ann != "dpgen.const")
          fail(p->getLocation(), fmt::format("'{}' is a scalar: DPGEN_IN/DPGEN_OUT mark pointer "
                                             "parameters (pass a one-element array to "
                                             "differentiate a scalar)",
                                             out.name), "dpgen-signature");
        out.kind = ParamKind::Scalar;
        out.elem = *t;
        out.elem_name = spelled(q);
        out.is_unsigned = *t == Type::Int && q->isUnsignedIntegerType();
      }
      out.spelling = spelled(p->getType(), /*keep_const=*/true);
      {
        std::string decl;
        llvm::raw_string_ostream os(decl);
        PrintingPolicy policy(ctx_.getLangOpts());
        policy.SuppressTagKeyword = true;
        p->getType().getCanonicalType().print(os, policy, out.name);
        out.declaration = os.str();
      }
      k_.params.push_back(out);
      if (inout_twin) {
        for (const auto& other : k_.params)
          if (other.name == inout_twin->name)
            fail(p->getLocation(), fmt::format("parameter '{}' clashes with the name dpgen uses "
                                               "for the new values of in-place array '{}'",
                                               other.name, out.name), "dpgen-signature");
        k_.params.push_back(*inout_twin);
        inout_twin.reset();
      }
      if (size_param) {
        for (const auto& other : k_.params)
          if (other.name == size_param->name)
            fail(p->getLocation(), fmt::format("parameter '{}' clashes with the size dpgen passes "
                                               "for vector '{}'",
                                               other.name, out.name), "dpgen-signature");
        k_.params.push_back(*size_param);
      }
    };
    bool params_ok = true;
    for (const ParmVarDecl* p : fn_->parameters()) {
      try {
        parameter(p);
      } catch (const Rejected&) {
        failed_ = true;
        params_ok = false;
        poisoned_.insert(p);
      }
    }
    check_parameter_names();
    // (no DPGEN_IN or DPGEN_OUT may only mean that one was rejected)
    if (!any_in && params_ok)
      fail(fn_->getLocation(), fmt::format("kernel '{}' has no DPGEN_IN parameter: there is "
                                           "nothing to differentiate",
                                           k_.name), "dpgen-signature");
    if (!any_out && params_ok)
      fail(fn_->getLocation(), fmt::format("kernel '{}' has no DPGEN_OUT parameter", k_.name), "dpgen-signature");
    // Row-pointer arrays: a[j][i] is the flat j * R + i for a row length R
    // that is larger than any column (a symbol; its value in the generated
    // code, kRowSymbolValue, is only ever compared, never used as an address).
    auto opaque_symbol = [&](const std::string& name, long long value) {
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
    };
    for (const auto& p : k_.params)
      if (p.row_pointers) {
        row_lengths_[p.name] = opaque_symbol(
            row_symbol(p.name), p.plane_pointers ? kPlaneRowSymbolValue : kRowSymbolValue);
        if (p.plane_pointers)
          plane_lengths_[p.name] = opaque_symbol(plane_symbol(p.name), kPlaneSymbolValue);
      }
    // Unsigned integer parameters (`unsigned n`, `size_t n`, a vector's
    // size) are read through a signed 64-bit copy defined first in every
    // generated function (`const std::ptrdiff_t n_signed = n;`): index
    // arithmetic in the adjoint goes below zero (`-n + 1`, `i = c_i + n - 1`),
    // which unsigned arithmetic would wrap to huge values.
    for (const auto& p : k_.params)
      if (p.kind == ParamKind::Scalar && p.elem == Type::Int && p.is_unsigned) {
        auto l = std::make_shared<LocalVar>();
        l->name = p.name + "_signed";
        for (int n = 1; is_reserved(l->name) || local_names_.count(l->name); ++n)
          l->name = fmt::format("{}_signed_{}", unprefixed(p.name), n);
        l->type_name = "std::ptrdiff_t";
        l->def = param(p.name, Type::Int);
        l->id = next_local_id_++;
        l->kernel_level = true;
        l->opaque = true;
        local_names_.insert(l->name);
        k_.kernel_locals.push_back(l);
        signed_views_[p.name] = local_ref(l);
      }
    k_.hidden.reserve(kMaxAccumulators); // (start_accumulator: pointers stay valid)
    // Bind parameters (after the vector is complete, so pointers stay valid).
    // By name: a rejected parameter has no Param (and is poisoned).
    for (const auto& p : k_.params) {
      if (p.synthetic || !p.twin_of.empty())
        continue;
      Binding b;
      b.kind = p.kind == ParamKind::Scalar ? Binding::ScalarParam : Binding::ArrayParam;
      b.param = &p;
      for (const ParmVarDecl* decl : fn_->parameters())
        if (decl->getNameAsString() == p.name && !poisoned_.count(decl))
          env_[decl] = b;
    }
    // Mixed precision between inputs and outputs is almost always a mistake.
    std::optional<Type> real;
    for (const auto& p : k_.params)
      if (p.kind == ParamKind::In || p.kind == ParamKind::Out) {
        if (real && *real != p.elem)
          fail(fn_->getLocation(), fmt::format("kernel '{}' mixes float and double arrays "
                                               "('{}' is {}); use one precision for all "
                                               "DPGEN_IN and DPGEN_OUT arrays",
                                               k_.name, p.name, type_spelling(p.elem)), "dpgen-signature");
        real = p.elem;
      }
  }

  // ---- statements ----------------------------------------------------------

  void body(const Stmt* s) {
    if (!s)
      fail(fn_->getLocation(), "kernel has no body");
    if (s->getBeginLoc().isMacroID()) {
      std::string macro =
          Lexer::getImmediateMacroName(s->getBeginLoc(), sm_, ctx_.getLangOpts()).str();
      fail(sm_.getExpansionLoc(s->getBeginLoc()),
           fmt::format("the body of kernel '{}' comes from macro '{}': write the loops out, so "
                       "diagnostics and the generated code can point at them",
                       k_.name, macro));
    }
    if (lower(s) == Escape::Always && !loops_.empty())
      fail(s->getBeginLoc(), "unreachable");
  }

  Escape lower(const Stmt* s) {
    if (const auto* c = dyn_cast<CompoundStmt>(s)) {
      for (const Stmt* child : c->body()) {
        if (lower_recovering(child) == Escape::Always) {
          if (child != c->body_back())
            fail(c->body_back()->getBeginLoc(), "statement after 'continue'/'return' is never "
                                                "executed");
          return Escape::Always;
        }
      }
      return Escape::None;
    }
    if (isa<NullStmt>(s))
      return Escape::None;
    // `#pragma omp parallel for` (parsed with -fopenmp): the loop it wraps.
    if (const auto* omp = dyn_cast<OMPExecutableDirective>(s)) {
      if (!omp->hasAssociatedStmt())
        fail(s->getBeginLoc(), "this OpenMP directive is outside the kernel subset");
      return lower(omp->getInnermostCapturedStmt()->getCapturedStmt());
    }
    if (const auto* d = dyn_cast<DeclStmt>(s)) {
      for (const Decl* decl : d->decls())
        declare(decl);
      return Escape::None;
    }
    if (const auto* f = dyn_cast<ForStmt>(s)) {
      for_loop(f);
      return Escape::None;
    }
    if (const auto* i = dyn_cast<IfStmt>(s))
      return if_stmt(i);
    if (isa<ContinueStmt>(s)) {
      if (unrolling_ > 0)
        fail(s->getBeginLoc(), "'continue' in a small constant loop that dpgen unrolls (it "
                               "reads or writes a local array, or sums into a variable); use "
                               "an if/else");
      if (loops_.empty())
        fail(s->getBeginLoc(), "'continue' outside a loop");
      return Escape::Always;
    }
    if (const auto* r = dyn_cast<ReturnStmt>(s)) {
      if (!frames_.empty() && loops_.size() == frames_.back().loop_depth) {
        // `return v;` in a helper being inlined: v where this path holds.
        if (frames_.back().is_void) {
          // (an early return would have to undo the out-parameters' later
          // assignments on its path)
          if (path_.size() > frames_.back().path_depth)
            fail(s->getBeginLoc(), fmt::format("'return' inside a branch of void helper '{}': "
                                               "assign the out-parameters in if/else instead",
                                               frames_.back().fn->getNameAsString()));
          return Escape::Always;
        }
        if (!r->getRetValue())
          fail(s->getBeginLoc(), "a helper called from a kernel must return a value");
        // The value first: it may inline further helpers, which grows frames_.
        ExprP v = expr(r->getRetValue());
        InlineFrame& fr = frames_.back();
        v = cast(v, fr.ret);
        fr.returns.push_back(
            {std::vector<PathCond>(path_.begin() + long(fr.path_depth), path_.end()), v});
        return Escape::Always;
      }
      if (!loops_.empty() || unrolling_ > 0)
        fail(s->getBeginLoc(), "'return' inside a loop is outside the kernel subset; use "
                               "'continue' or an if/else");
      if (r->getRetValue())
        fail(s->getBeginLoc(), "a kernel returns nothing");
      return Escape::Always;
    }
    if (const auto* e = dyn_cast<clang::Expr>(s)) {
      expr_stmt(e);
      return Escape::None;
    }
    if (isa<WhileStmt>(s) || isa<DoStmt>(s))
      fail(s->getBeginLoc(), "while/do loops are outside the kernel subset: write a for loop "
                             "with an integer counter and bounds that depend on parameters only");
    if (isa<GotoStmt>(s) || isa<IndirectGotoStmt>(s) || isa<LabelStmt>(s))
      fail(s->getBeginLoc(), "'goto' is outside the kernel subset");
    if (isa<BreakStmt>(s))
      fail(s->getBeginLoc(), "'break' is outside the kernel subset: loop bounds must fix the "
                             "iteration space");
    if (isa<SwitchStmt>(s))
      fail(s->getBeginLoc(), "'switch' is outside the kernel subset; use if/else on indices");
    if (isa<CXXForRangeStmt>(s))
      fail(s->getBeginLoc(), "range-based for is outside the kernel subset; use an integer "
                             "counter");
    fail(s->getBeginLoc(), fmt::format("statement '{}' is outside the kernel subset",
                                       s->getStmtClassName()));
  }

  // `if (c) A else B`; a branch ending in continue/return puts the negated
  // condition on the path of everything that follows.
  Escape if_stmt(const IfStmt* s) {
    if (s->getInit() || s->getConditionVariable())
      fail(s->getBeginLoc(), "if with an initializer or a declaration is outside the subset");
    ExprP c = cond(s->getCond());
    size_t depth = path_.size();
    auto env_before = env_;
    int first_local = next_local_id_;

    path_.push_back({c, true});
    Escape then_e = lower_recovering(s->getThen());
    path_.resize(depth);
    auto env_then = env_;
    int after_then = next_local_id_;

    env_ = env_before;
    Escape else_e = Escape::None;
    if (s->getElse()) {
      path_.push_back({c, false});
      else_e = lower_recovering(s->getElse());
      path_.resize(depth);
    }
    auto env_else = env_;
    int after_else = next_local_id_;

    // Merge values assigned in the branches: v = c ? v_then : v_else. A
    // branch that escaped contributes nothing to what follows.
    auto merge = [&](const VarDecl* decl, std::optional<ExprP> t,
                     std::optional<ExprP> e) -> std::optional<ExprP> {
      if (then_e == Escape::Always)
        t = e;
      if (else_e == Escape::Always)
        e = t;
      if (t == e)
        return t;
      if (!t || !e)
        return std::nullopt; // assigned in one branch only: uninitialised after
      // Values made inside a branch are inlined into the select, so nothing
      // of a branch is evaluated where the branch does not run.
      ExprP then_value = inline_locals(*t, first_local, after_then);
      ExprP else_value = inline_locals(*e, after_then, after_else);
      return make_local(decl->getNameAsString(), decl, select(c, then_value, else_value));
    };
    for (auto& [decl, b] : env_) {
      if (b.kind == Binding::Value) {
        b.value = merge(decl, env_then[decl].value, env_else[decl].value);
      } else if (b.kind == Binding::LocalArray) {
        const auto& te = env_then[decl].elems;
        const auto& ee = env_else[decl].elems;
        for (size_t i = 0; i < b.elems.size() && i < te.size() && i < ee.size(); ++i)
          b.elems[i] = merge(decl, te[i], ee[i]);
      }
    }
    if (then_e == Escape::Always && else_e == Escape::Always)
      return Escape::Always;
    if (then_e == Escape::Always)
      path_.push_back({c, false});
    if (else_e == Escape::Always)
      path_.push_back({c, true});
    // `if (n < 3) return;` in the kernel itself, outside every loop and
    // helper: a guard of the whole kernel (it is also on every later path).
    if ((then_e == Escape::Always || else_e == Escape::Always) && loops_.empty() &&
        frames_.empty())
      k_.guards.push_back(path_.back());
    return Escape::None;
  }

  ExprP inline_locals(const ExprP& e, int from, int to) {
    if (!e)
      throw std::logic_error("internal error: lower: a null expression to inline");
    if (e->op == Op::Local) {
      if (e->local->id >= from && e->local->id < to)
        return inline_locals(e->local->def, from, to);
      return e;
    }
    return map_operands(e, [&](const ExprP& o) { return inline_locals(o, from, to); });
  }

  ExprP make_local(const std::string& base, const VarDecl* decl, ExprP def) {
    auto l = std::make_shared<LocalVar>();
    std::string name = base;
    for (int n = 1; local_names_.count(name) || loop_names_.count(name) || is_reserved(name); ++n)
      name = fmt::format("{}_{}", unprefixed(base), n);
    local_names_.insert(name);
    l->name = name;
    l->def = def;
    l->id = next_local_id_++;
    // (a value computed from an accumulator's sum, `double norm = sqrt(s);`,
    // is needed only where that sum is: not a kernel-level local)
    l->kernel_level = loops_.empty() && !any_node(def, [&](const ExprP& x) {
      return x->op == Op::Read && is_hidden(x->name);
    });
    if (def->type == Type::Int) {
      // Integers become std::ptrdiff_t in the generated code (see emit.cpp:
      // index arithmetic that vectorizes and never wraps, also for unsigned
      // locals such as `size_t k = n - 1 - i;` that later go negative in the
      // adjoint's index algebra); wider types keep their own.
      QualType t = decl ? decl->getType().getNonReferenceType().getUnqualifiedType() : ctx_.IntTy;
      bool widen = !t->isIntegerType() || ctx_.getTypeSize(t) <= 64;
      l->type_name = widen ? "std::ptrdiff_t" : spelled(t);
    }
    else
      l->type_name = type_spelling(def->type);
    if (l->kernel_level)
      k_.kernel_locals.push_back(l);
    return local_ref(l);
  }

  std::string unset_message(const VarDecl* v, const char* plain) const {
    auto it = why_unset_.find(v);
    if (it != why_unset_.end())
      return it->second;
    return fmt::format("'{}' {}", v->getNameAsString(), plain);
  }

  // The stem of a renamed name: without the reserved prefix dpgen_ (a user's
  // local `dpgen_x` becomes `user_x_1`; appending alone never leaves the
  // prefix, and the renaming would not end).
  static std::string unprefixed(const std::string& base) {
    return base.rfind("dpgen_", 0) == 0 ? "user_" + base.substr(6) : base;
  }

  // Names a local or a loop counter must not keep (it is renamed <name>_1):
  // a parameter, an enclosing counter, a name the signature rule gives an
  // adjoint or tangent parameter (<array>_adj, <array>_dot), the prefix
  // dpgen_ of generated helpers, or a C++ keyword (a C kernel's `new`: the
  // generated code is C++).
  bool is_reserved(const std::string& name) const {
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
  const Param* contract_name_of(const std::string& name) const {
    for (const char* suffix : {"_adj", "_dot"}) {
      size_t n = std::char_traits<char>::length(suffix);
      if (name.size() > n && name.compare(name.size() - n, n, suffix) == 0)
        if (const Param* p = k_.find_param(name.substr(0, name.size() - n));
            p && p->kind != ParamKind::Scalar)
          return p;
    }
    return nullptr;
  }

  static bool is_cxx_only_keyword(const std::string& name) {
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

  // The parameters keep their names in every generated function, so a name
  // the generated code needs for something else is an error: the adjoint or
  // tangent of another parameter (<array>_adj, <array>_dot), the size dpgen
  // passes for a vector, the prefix dpgen_, a C++ keyword.
  void check_parameter_names() {
    for (const ParmVarDecl* decl : fn_->parameters()) {
      std::string name = decl->getNameAsString();
      if (const Param* a = contract_name_of(name))
        error(decl->getLocation(),
              fmt::format("parameter '{}' has the name that the generated {} gives the {} of "
                          "array '{}'; rename it",
                          name, name.back() == 'j' ? "adjoint" : "tangent",
                          name.back() == 'j' ? "adjoint" : "tangent", a->name), "dpgen-name");
      else if (name.rfind("dpgen_", 0) == 0)
        error(decl->getLocation(), fmt::format("parameter '{}': names starting with 'dpgen_' "
                                               "are reserved for generated code; rename it",
                                               name), "dpgen-name");
      else if (is_cxx_only_keyword(name))
        error(decl->getLocation(), fmt::format("parameter '{}' is a C++ keyword, and the "
                                               "generated adjoint is C++; rename it",
                                               name), "dpgen-name");
    }
    for (const auto& p : k_.params)
      if (p.synthetic)
        for (const auto& other : k_.params)
          if (!other.synthetic && other.name == p.name)
            for (const ParmVarDecl* decl : fn_->parameters())
              if (decl->getNameAsString() == p.name)
                error(decl->getLocation(),
                      fmt::format("parameter '{}' clashes with the size dpgen passes for vector "
                                  "'{}'; rename it",
                                  p.name, p.name.substr(0, p.name.size() - 5)), "dpgen-name");
  }

  // Every name the generated code takes from the kernel (Kernel::names).
  void collect_names() {
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

  void declare(const Decl* d) {
    const auto* v = dyn_cast<VarDecl>(d);
    if (!v)
      fail(d->getLocation(), "only variable declarations are allowed in a kernel");
    if (v->isStaticLocal() || v->hasGlobalStorage())
      fail(v->getLocation(), fmt::format("static variable '{}' is global state, outside the "
                                         "kernel subset",
                                         v->getNameAsString()));
    if (const auto* at = ctx_.getAsConstantArrayType(v->getType())) {
      declare_array(v, at);
      return;
    }
    if (const auto* rd = v->getType().getNonReferenceType()->getAsCXXRecordDecl();
        rd && rd->isLambda()) {
      declare_lambda(v, rd);
      return;
    }
    if (auto sa = std_array(v->getType())) { // a coefficient table, a small buffer
      declare_array(v, ctx_.getAsConstantArrayType(
                           ctx_.getConstantArrayType(sa->first, llvm::APInt(64, sa->second),
                                                     nullptr, ArraySizeModifier::Normal, 0)));
      return;
    }
    auto t = scalar_type(v->getType());
    if (!t || v->getType()->isReferenceType())
      fail(v->getLocation(), fmt::format("local '{}' of type '{}' is outside the kernel subset "
                                         "(int, float, double or bool values, and small arrays "
                                         "of them)",
                                         v->getNameAsString(), v->getType().getAsString()));
    Binding b;
    b.kind = Binding::Value;
    b.kernel_level = loops_.empty();
    if (const clang::Expr* init = v->getInit()) {
      ExprP e = expr(init);
      b.value = make_local(v->getNameAsString(), v, cast(e, *t));
    }
    env_[v] = b;
  }

  // A small local array (`double w[3] = {...}`, a line buffer `double v[5]`):
  // each element is a local value, indexed by constants (counters of small
  // constant loops count as constants: those loops are unrolled).
  void declare_array(const VarDecl* v, const ConstantArrayType* at) {
    auto t = scalar_type(at->getElementType());
    uint64_t n = at->getSize().getZExtValue();
    if (!t || ctx_.getAsArrayType(at->getElementType()))
      fail(v->getLocation(), fmt::format("local array '{}' of type '{}' is outside the kernel "
                                         "subset (one-dimensional arrays of int, float or "
                                         "double)",
                                         v->getNameAsString(), v->getType().getAsString()));
    if (n > 64)
      fail(v->getLocation(), fmt::format("local array '{}' has {} elements; dpgen keeps local "
                                         "arrays of up to 64 elements in registers",
                                         v->getNameAsString(), n));
    Binding b;
    b.kind = Binding::LocalArray;
    b.elem = *t;
    b.elems.assign(n, std::nullopt);
    const clang::Expr* init = v->getInit();
    if (const auto* ctor = dyn_cast_or_null<CXXConstructExpr>(init);
        ctor && ctor->getNumArgs() == 0 && !ctor->requiresZeroInitialization())
      init = nullptr; // `std::array<double, 3> d;`: no values yet
    if (init) {
      const auto* list = dyn_cast<InitListExpr>(init->IgnoreImplicit());
      // std::array<T, N> a = {...}: the list of its one member, the C array
      bool all_zero = false; // `std::array<double, 3> d{};`
      if (list && std_array(v->getType()) && list->getNumInits() == 1) {
        if (const auto* inner = dyn_cast<InitListExpr>(list->getInit(0)->IgnoreImplicit()))
          list = inner;
        else if (isa<ImplicitValueInitExpr>(list->getInit(0)))
          all_zero = true;
      }
      if (!list)
        fail(init->getBeginLoc(), "a local array is initialised with a braced list");
      for (unsigned i = 0; !all_zero && i < list->getNumInits() && i < n; ++i)
        b.elems[i] = isa<ImplicitValueInitExpr>(list->getInit(i))
                         ? cast(int_const(0), *t)
                         : make_local(fmt::format("{}_{}", v->getNameAsString(), i), nullptr,
                                      cast(expr(list->getInit(i)), *t));
      // Elements the list leaves out are zero, as in C.
      for (uint64_t i = all_zero ? 0 : list->getNumInits(); i < n; ++i)
        b.elems[i] = cast(int_const(0), *t);
    }
    env_[v] = b;
  }

  // `auto f = [&](int i) { ... };`: called later, inlined like a helper. A
  // variable captured by copy must still have the value it had here when the
  // lambda is called; init-captures and `this` are outside the subset.
  void declare_lambda(const VarDecl* v, const CXXRecordDecl* rd) {
    const clang::Expr* init = v->getInit();
    const auto* le = init ? dyn_cast<LambdaExpr>(init->IgnoreImplicit()) : nullptr;
    if (!le)
      fail(v->getLocation(), fmt::format("lambda '{}' must be initialised with a lambda "
                                         "expression",
                                         v->getNameAsString()), "dpgen-lambda");
    Binding b;
    b.kind = Binding::Lambda;
    b.closure = rd;
    for (const LambdaCapture& c : le->captures()) {
      if (!c.capturesVariable() || le->isInitCapture(&c))
        fail(c.getLocation(), fmt::format("lambda '{}' captures something other than the "
                                          "kernel's variables (this, or an init-capture)",
                                          v->getNameAsString()), "dpgen-lambda");
      if (c.getCaptureKind() != LCK_ByCopy)
        continue;
      const auto* cv = dyn_cast<VarDecl>(c.getCapturedVar());
      auto it = cv ? env_.find(cv) : env_.end();
      if (it != env_.end() && it->second.kind == Binding::Value)
        b.captured.push_back({cv, it->second.value});
      if (it != env_.end() && it->second.kind == Binding::LocalArray)
        b.captured_arrays.push_back({cv, it->second.elems});
    }
    env_[v] = b;
  }

  // The element of a local array that `idx` names: it must be a constant.
  size_t local_index(const clang::Expr* idx_expr, const VarDecl* v, size_t n) {
    ExprP idx = expr(idx_expr);
    auto p = to_poly(idx);
    if (!p || !p->is_constant())
      fail(idx_expr->getBeginLoc(),
           fmt::format("index of local array '{}' must be a constant (or the counter of a small "
                       "loop with constant bounds, which dpgen unrolls)",
                       v->getNameAsString()));
    long long k = p->constant_term();
    if (k < 0 || k >= static_cast<long long>(n))
      fail(idx_expr->getBeginLoc(), fmt::format("index {} is outside local array '{}' of {} "
                                                "elements",
                                                k, v->getNameAsString(), n));
    return static_cast<size_t>(k);
  }

  // `a[k]` of a local array: its binding and element, if that is what `e` is.
  std::optional<std::pair<const VarDecl*, size_t>> local_element(const clang::Expr* e) {
    if (const auto* oc = dyn_cast<CXXOperatorCallExpr>(e->IgnoreParens());
        oc && oc->getOperator() == OO_Subscript && oc->getNumArgs() == 2) {
      // t[m] of a std::array local
      const auto* ref = dyn_cast<DeclRefExpr>(oc->getArg(0)->IgnoreParenImpCasts());
      const auto* v = ref ? dyn_cast<VarDecl>(ref->getDecl()) : nullptr;
      auto it = v ? env_.find(v) : env_.end();
      if (it == env_.end() || it->second.kind != Binding::LocalArray)
        return std::nullopt;
      return std::pair{v, local_index(oc->getArg(1), v, it->second.elems.size())};
    }
    const auto* sub = dyn_cast<ArraySubscriptExpr>(e->IgnoreParens());
    if (!sub)
      return std::nullopt;
    const auto* ref = dyn_cast<DeclRefExpr>(sub->getBase()->IgnoreParenImpCasts());
    const auto* v = ref ? dyn_cast<VarDecl>(ref->getDecl()) : nullptr;
    auto it = v ? env_.find(v) : env_.end();
    if (it == env_.end() || it->second.kind != Binding::LocalArray)
      return std::nullopt;
    return std::pair{v, local_index(sub->getIdx(), v, it->second.elems.size())};
  }

  // A loop with constant bounds and at most 16 iterations that touches a
  // local array or assigns a variable declared outside it (`s += w[m] *
  // a[i + m]`) is unrolled: its counter is a constant in each copy.
  int unrolling_ = 0;
  bool should_unroll(const ForStmt* f, long long lo, long long hi) {
    if (hi - lo > 16 || hi <= lo)
      return false;
    bool touches = false;
    std::function<void(const Stmt*)> scan = [&](const Stmt* s) {
      if (!s)
        return;
      if (const auto* r = dyn_cast<DeclRefExpr>(s))
        if (const auto* v = dyn_cast<VarDecl>(r->getDecl()); v && env_.count(v) &&
                                                              env_[v].kind == Binding::LocalArray)
          touches = true;
      for (const Stmt* c : s->children())
        scan(c);
    };
    scan(f->getBody());
    std::set<const VarDecl*> assigned;
    assigned_vars(f->getBody(), assigned);
    for (const VarDecl* v : assigned)
      if (env_.count(v) && env_[v].kind == Binding::Value)
        touches = true;
    return touches;
  }

  void for_loop(const ForStmt* f) {
    if (!frames_.empty())
      fail(f->getBeginLoc(), fmt::format("a loop in helper '{}': helpers called from a kernel "
                                         "compute a value without loops; write the loop in the "
                                         "kernel",
                                         frames_.back().fn->getNameAsString()), "dpgen-loop");
    // init: `int i = lo` or, C89 style, `i = lo` for a counter declared earlier.
    const VarDecl* var = nullptr;
    const clang::Expr* init = nullptr;
    if (const auto* ds = dyn_cast_or_null<DeclStmt>(f->getInit())) {
      if (!ds->isSingleDecl())
        fail(f->getBeginLoc(), "a kernel loop declares one counter: 'for (int i = lo; i < hi; "
                               "++i)'", "dpgen-loop");
      var = dyn_cast<VarDecl>(ds->getSingleDecl());
      if (!var || !var->getInit())
        fail(f->getBeginLoc(), "loop counter needs an initial value", "dpgen-loop");
      init = var->getInit();
    } else if (const auto* a = init_assignment(f); a) {
      const auto* r = dyn_cast<DeclRefExpr>(a->getLHS()->IgnoreParenImpCasts());
      var = r ? dyn_cast<VarDecl>(r->getDecl()) : nullptr;
      auto it = var ? env_.find(var) : env_.end();
      if (!var || it == env_.end() || it->second.kind != Binding::Value)
        fail(a->getLHS()->getBeginLoc(), "the loop counter must be a local variable of the "
                                         "kernel: 'for (i = lo; i < hi; ++i)'", "dpgen-loop");
      init = a->getRHS();
    } else {
      fail(f->getBeginLoc(), "a kernel loop must set its counter: 'for (int i = lo; i < hi; ++i)' "
                             "or, with 'int i;' declared earlier, 'for (i = lo; i < hi; ++i)'", "dpgen-loop");
    }
    QualType vt = var->getType().getCanonicalType();
    if (!vt->isIntegerType() || vt->isBooleanType())
      fail(var->getLocation(), fmt::format("loop counter '{}' must have an integer type",
                                           var->getNameAsString()), "dpgen-loop");
    in_loop_bounds_ = true; // (reset below, also when lowering them fails)
    struct Reset {
      bool& flag;
      ~Reset() { flag = false; }
    } reset{in_loop_bounds_};
    ExprP init_value = expr(init);
    // cond: `i < hi`, `i <= hi`, `i >= lo`, `i > lo`; also `i + 1 < n` or
    // `n > i`: any comparison whose sides differ by +-i plus a bound.
    // (a bound such as std::min(n, i + w + 1) binds temporaries to const
    // references: the condition comes wrapped in ExprWithCleanups)
    const clang::Expr* cond_expr = f->getCond();
    if (const auto* cleanups = dyn_cast_or_null<ExprWithCleanups>(cond_expr))
      cond_expr = cleanups->getSubExpr();
    const auto* c = dyn_cast_or_null<BinaryOperator>(cond_expr);
    BinaryOperatorKind cond_op = c ? c->getOpcode() : BO_Comma;
    // `for (unsigned i = n; i-- > lo;)`, the way to count an unsigned counter
    // down: the body sees i = n - 1, ..., lo.
    bool post_decrement = false;
    if (c && cond_op == BO_GT && !f->getInc())
      if (const auto* u = dyn_cast<UnaryOperator>(c->getLHS()->IgnoreParenImpCasts());
          u && u->getOpcode() == UO_PostDec)
        if (const auto* r = dyn_cast<DeclRefExpr>(u->getSubExpr()->IgnoreParenImpCasts());
            r && r->getDecl() == var)
          post_decrement = true;
    ExprP bound = post_decrement                    ? expr(c->getRHS())
                  : c && c->isRelationalOp() ? loop_bound(c, var, cond_op)
                                             : nullptr;
    in_loop_bounds_ = false;
    if (!bound)
      fail(f->getCond() ? f->getCond()->getBeginLoc() : f->getBeginLoc(),
           fmt::format("loop condition must compare the counter '{}' with a bound: "
                       "'{} < hi'",
                       var->getNameAsString(), var->getNameAsString()), "dpgen-loop");
    // inc: ++i, i++, i += 1 (or the decrements for a loop that counts down)
    int step = post_decrement ? -1 : loop_step(f->getInc(), var);
    if (step == 0)
      fail(f->getInc() ? f->getInc()->getBeginLoc() : f->getBeginLoc(),
           "loop increment must be ++i, i++ or i += s for a constant s (or --i for a loop "
           "counting down)", "dpgen-loop");
    if (step < -1)
      fail(f->getInc()->getBeginLoc(), "a loop counting down steps by 1; count a strided loop up", "dpgen-loop");
    ExprP lo, hi;
    ExprP one = int_const(1);
    switch (cond_op) {
    case BO_LT:
      lo = init_value, hi = bound;
      break;
    case BO_LE:
      lo = init_value, hi = binary(Op::Add, bound, one);
      break;
    case BO_GT:
      if (post_decrement)
        lo = bound, hi = init_value;
      else
        lo = binary(Op::Add, bound, one), hi = binary(Op::Add, init_value, one);
      break;
    case BO_GE:
      lo = bound, hi = binary(Op::Add, init_value, one);
      break;
    default:
      fail(c->getOperatorLoc(), "loop condition must be <, <=, > or >=", "dpgen-loop");
    }
    if ((step > 0) != (cond_op == BO_LT || cond_op == BO_LE))
      fail(f->getInc()->getBeginLoc(), "loop direction does not match its condition", "dpgen-loop");
    // Counting an unsigned counter down is safe when the counter stays above
    // zero: `i > b` (b >= 0), or `i >= b` with b >= 1; `i >= 0` wraps.
    bool stays_positive = cond_op == BO_GT ||
                          (cond_op == BO_GE && provably_nonneg(binary(Op::Sub, bound, int_const(1))));
    if (vt->isUnsignedIntegerType() && step < 0 && !post_decrement && !stays_positive)
      fail(f->getInc()->getBeginLoc(),
           fmt::format("unsigned counter '{}' counts down: its bound check wraps around at 0; "
                       "count up, use a signed counter, or write 'for ({} = n; {}-- > 0;)'",
                       var->getNameAsString(), var->getNameAsString(), var->getNameAsString()), "dpgen-loop");
    // A strided loop whose start moves with outer counters (red-black:
    // `for (i = 1 + (j + 1) % 2; i < nx - 1; i += 2)`, or `i = j; ...; i += 2`)
    // runs as a unit-step loop from the smallest start over the outer ranges,
    // its body under `i >= start && (i - start) % step == 0`: the same
    // iterations, with a box the rules and the gather can range over.
    ExprP parity_start; // the moving start, and the original step
    int parity_step = 0;
    if (step > 1 && any_node(lo, [](const ExprP& x) { return x->op == Op::LoopVar; }))
      if (auto least = smallest(lo)) {
        parity_start = lo;
        parity_step = step;
        lo = *least;
        step = 1;
      }
    // Triangular nests (`for (j = 0; j <= i; ++j)`, `for (j = i + 1; j < n;
    // ++j)`, `j < std::min(n, i + 3)`): a bound affine in outer counters, with
    // constant coefficients, becomes its extreme over the outer loops' ranges
    // and the bound itself a condition on the body's path (`j < i + 1`), so
    // the box stays rectangular and the iterations are the same. In a min
    // (upper) or max (lower) bound each such term is treated so; the others
    // stay in the bound.
    std::vector<std::pair<ExprP, bool>> triangle; // (original bound, is the upper one)
    for (ExprP* b : {&lo, &hi}) {
      const bool upper = b == &hi;
      if (!any_node(*b, [](const ExprP& x) { return x->op == Op::LoopVar; }))
        continue;
      if (!upper && step != 1 && step != -1)
        continue; // (a strided loop's start fixes its parity: not moved)
      std::vector<ExprP> terms;
      std::function<void(const ExprP&)> flatten = [&](const ExprP& x) {
        const char* fn = upper ? "min" : "max";
        if (x->op == Op::Call && x->name == fn) {
          for (const auto& a : x->ops)
            flatten(a);
        } else if ((x->op == Op::Add || x->op == Op::Sub) && x->ops[1]->op == Op::IntConst &&
                   x->ops[0]->op == Op::Call && x->ops[0]->name == fn) {
          // `j <= std::min(n - 1, i + 1)`: min(a, b) + 1 is min(a + 1, b + 1)
          for (const auto& a : x->ops[0]->ops)
            flatten(binary(x->op, a, x->ops[1]));
        } else {
          terms.push_back(x);
        }
      };
      flatten(*b);
      std::vector<ExprP> hulled;
      std::vector<std::pair<ExprP, bool>> sides;
      bool ok = true;
      for (const auto& t : terms) {
        auto p = to_poly(t);
        if (!p || !p->mentions_any_counter()) {
          hulled.push_back(t);
          continue;
        }
        auto h = hull(t, *p, upper);
        if (!h) {
          ok = false;
          break;
        }
        hulled.push_back(*h);
        sides.push_back({t, upper});
      }
      if (!ok || sides.empty())
        continue; // reported below
      triangle.insert(triangle.end(), sides.begin(), sides.end());
      *b = hulled.size() == 1 ? hulled[0] : call(upper ? "min" : "max", hulled, Type::Int);
    }
    // A bound that is not a polynomial but depends on the sizes only
    // (`i < n / 2`, `i < (n + 1) / 2`) is fixed for the whole kernel: a
    // symbol, like `int half = n / 2;` set before the loops.
    for (ExprP* b : {&lo, &hi})
      if (!to_poly(*b) && !any_node(*b, [](const ExprP& x) {
            return x->op == Op::LoopVar || x->op == Op::Read || is_real(x->type);
          })) {
        auto l = std::make_shared<LocalVar>();
        l->name = var->getNameAsString() + (b == &lo ? "_lo" : "_hi");
        for (int n = 1; is_reserved(l->name) || local_names_.count(l->name); ++n)
          l->name = fmt::format("{}_{}_{}", unprefixed(var->getNameAsString()),
                                b == &lo ? "lo" : "hi", n);
        local_names_.insert(l->name);
        l->type_name = "std::ptrdiff_t";
        l->def = *b;
        l->id = next_local_id_++;
        l->kernel_level = true;
        k_.kernel_locals.push_back(l);
        *b = local_ref(l);
      }
    for (const auto& [what, e, loc] :
         {std::tuple{"lower", lo, init->getBeginLoc()},
          std::tuple{"upper", hi, c->getRHS()->getBeginLoc()}}) {
      auto p = to_poly(e);
      if (!p)
        fail(loc, fmt::format("{} bound of loop '{}' must be a polynomial in the integer "
                              "parameters",
                              what, var->getNameAsString()), "dpgen-loop");
      for (const auto& [m, coef] : p->terms())
        for (const auto& s : m)
          if (s.is_counter())
            fail(loc, fmt::format("{} bound of loop '{}' depends on loop '{}' in a way dpgen "
                                  "cannot make rectangular: a bound may move with outer "
                                  "counters by constant multiples (j <= i, j < i + 3, "
                                  "std::min(n, i + w + 1), a strided start 1 + (j + 1) % 2)",
                                  what, var->getNameAsString(), s.name), "dpgen-loop");
    }
    {
      auto plo = to_poly(lo), phi = to_poly(hi);
      if (plo->is_constant() && phi->is_constant() && triangle.empty() && !parity_start &&
          should_unroll(f, plo->constant_term(), phi->constant_term())) {
        check_not_assigned(f->getBody(), var);
        auto saved = env_.count(var) ? std::optional<Binding>(env_[var]) : std::nullopt;
        size_t depth = path_.size();
        ++unrolling_;
        // every step-th value from lo up (i += s), or each from hi - 1 down
        const long long stride = step > 0 ? step : 1;
        for (long long k = plo->constant_term(); k < phi->constant_term(); k += stride) {
          long long v = step > 0 ? k : plo->constant_term() + phi->constant_term() - 1 - k;
          Binding b;
          b.kind = Binding::Value;
          b.value = int_const(v);
          env_[var] = b;
          try {
            lower(f->getBody());
          } catch (const Rejected&) {
            --unrolling_;
            path_.resize(depth);
            throw;
          }
          path_.resize(depth);
        }
        --unrolling_;
        if (saved) {
          env_[var] = *saved;
          env_[var].value = std::nullopt;
          why_unset_[var] = fmt::format("loop counter '{}' is read after its loop; use the loop "
                                        "bound instead",
                                        var->getNameAsString());
        } else {
          env_.erase(var);
        }
        return;
      }
    }
    if (loops_.size() == 3)
      fail(f->getBeginLoc(), "loops nest at most 3 deep in the kernel subset", "dpgen-loop");

    auto loop = std::make_shared<Loop>();
    // The counter keeps its name unless that would collide with a parameter,
    // a local or an enclosing counter in the generated code.
    std::string base = var->getNameAsString() + (step > 1 ? "_step" : "");
    loop->var = base;
    for (int n = 1; is_reserved(loop->var) || local_names_.count(loop->var); ++n)
      loop->var = fmt::format("{}_{}", unprefixed(base), n);
    loop_names_.insert(loop->var);
    loop->type_name = spelled(var->getType());
    loop->lo = lo;
    loop->hi = hi;
    ExprP counter = loop_var(loop->var);
    if (step > 1) {
      // for (i = lo; i < hi; i += s): the loop runs over the steps t in
      // [0, (hi - lo + s - 1) / s) and i = lo + s * t.
      auto trips = std::make_shared<LocalVar>();
      trips->name = loop->var + "_count";
      for (int n = 1; local_names_.count(trips->name) || is_reserved(trips->name); ++n)
        trips->name = fmt::format("{}_count_{}", unprefixed(loop->var), n);
      local_names_.insert(trips->name);
      trips->type_name = "std::ptrdiff_t";
      trips->def = binary(Op::Div, binary(Op::Add, binary(Op::Sub, hi, lo), int_const(step - 1)),
                          int_const(step));
      trips->id = next_local_id_++;
      trips->kernel_level = true;
      k_.kernel_locals.push_back(trips);
      loop->lo = int_const(0);
      loop->hi = local_ref(trips);
      counter = binary(Op::Add, lo, binary(Op::Mul, int_const(step), counter));
    }

    check_not_assigned(f->getBody(), var);
    size_t depth = path_.size();
    auto env_before = env_;
    auto why_before = why_unset_;
    Binding b;
    b.kind = Binding::LoopVar;
    b.value = counter;
    env_[var] = b;
    // Variables declared outside the loop and assigned in it (OpenMP
    // `private` temporaries) start each iteration without a value: a read
    // before the iteration's own assignment would be a value carried over
    // from the previous iteration.
    std::set<const VarDecl*> assigned;
    assigned_vars(f->getBody(), assigned);
    // Scalar accumulators of this loop (`s += f(...)`, `s` read only after
    // the loop): a hidden work array each (start_accumulator).
    std::vector<const VarDecl*> accumulating;
    for (const VarDecl* v : assigned)
      if (frames_.empty() && unrolling_ == 0 && is_accumulator(f->getBody(), v) &&
          start_accumulator(v, f->getForLoc()))
        accumulating.push_back(v);
    for (const VarDecl* v : assigned) {
      auto it = env_.find(v);
      if (it == env_.end() ||
          (it->second.kind != Binding::Value && it->second.kind != Binding::LocalArray))
        continue;
      it->second.value = std::nullopt;
      for (auto& el : it->second.elems)
        el = std::nullopt;
      if (accumulators_.count(v)) {
        why_unset_[v] = fmt::format("'{}' accumulates in this loop ('+='): its sum is known "
                                    "after the loop, read it there",
                                    v->getNameAsString());
        continue;
      }
      why_unset_[v] = fmt::format(
          "'{}' is declared outside the loop and assigned inside it, and read here before it is "
          "assigned in this iteration: a value carried from one iteration to the next (a "
          "recurrence, or a running sum read inside its loop) is outside the kernel subset; "
          "assign it before each use in the iteration, or only add to it in the loop "
          "(`s += ...`) and read the sum after the loop",
          v->getNameAsString());
    }
    // (after the accumulators' initial stores, which are outside the loop)
    for (const auto& [bound_at, upper] : triangle) // the triangle's side(s)
      path_.push_back({binary(upper ? Op::Lt : Op::Ge, counter, bound_at), true});
    if (parity_start) { // the strided loop's own iterations
      path_.push_back({binary(Op::Ge, counter, parity_start), true});
      path_.push_back({binary(Op::Eq,
                              binary(Op::Rem, binary(Op::Sub, counter, parity_start),
                                     int_const(parity_step)),
                              int_const(0)),
                       true});
    }
    loops_.push_back(loop);
    loop_ids_.push_back(next_loop_id_++);
    segments_.push_back(--next_segment_);
    Escape e = lower_recovering(f->getBody());
    (void)e; // a body ending in continue is fine
    loops_.pop_back();
    loop_ids_.pop_back();
    segments_.pop_back();
    path_.resize(depth);
    env_ = env_before;
    why_unset_ = why_before;
    // After the loop, a variable it assigned holds what the last iteration
    // left there: outside the subset; an accumulator holds its sum.
    for (const VarDecl* v : assigned) {
      if (std::find(accumulating.begin(), accumulating.end(), v) != accumulating.end()) {
        finish_accumulator(v, f->getEndLoc());
        continue;
      }
      auto it = env_.find(v);
      if (it == env_.end() ||
          (it->second.kind != Binding::Value && it->second.kind != Binding::LocalArray))
        continue;
      it->second.value = std::nullopt;
      for (auto& el : it->second.elems)
        el = std::nullopt;
      why_unset_[v] = fmt::format("'{}' is read after the loop that assigns it: its value there "
                                  "is the last iteration's, outside the kernel subset",
                                  v->getNameAsString());
    }
    if (const auto* d = dyn_cast_or_null<DeclStmt>(f->getInit()); !d) {
      // A C89 counter is not a value after its loop either.
      env_[var].value = std::nullopt;
      why_unset_[var] = fmt::format("loop counter '{}' is read after its loop; use the loop "
                                    "bound instead",
                                    var->getNameAsString());
    }
  }

  // The bound of a loop condition as `counter op bound` (op returned in `op`):
  // `i < n`, `i + 1 < n` (i < n - 1), `n > i` (i < n). Null when the sides do
  // not differ by exactly +-counter plus something free of the counter.
  ExprP loop_bound(const BinaryOperator* c, const VarDecl* var, BinaryOperatorKind& op) {
    const auto* lhs = dyn_cast<DeclRefExpr>(c->getLHS()->IgnoreParenImpCasts());
    if (lhs && lhs->getDecl() == var)
      return expr(c->getRHS());
    // The counter is bound to a placeholder counter while the sides are
    // lowered, named apart from every counter already named.
    std::string placeholder = "dpgen_counter";
    for (int n = 1; loop_names_.count(placeholder); ++n)
      placeholder = fmt::format("dpgen_counter_{}", n);
    auto saved = env_.find(var) != env_.end() ? std::optional<Binding>(env_[var]) : std::nullopt;
    Binding b;
    b.kind = Binding::LoopVar;
    b.value = loop_var(placeholder);
    env_[var] = b;
    ExprP l = expr(c->getLHS()), r = expr(c->getRHS());
    if (saved)
      env_[var] = *saved;
    else
      env_.erase(var);
    auto pl = to_poly(l), pr = to_poly(r);
    if (!pl || !pr)
      return nullptr;
    Poly d = *pl - *pr; // condition: d op 0
    Poly k = d.coefficient(Sym::counter(placeholder));
    Poly rest = d.without(Sym::counter(placeholder));
    if (!k.is_constant() || (k.constant_term() != 1 && k.constant_term() != -1) ||
        rest.mentions_any_counter())
      return nullptr;
    op = c->getOpcode();
    if (k.constant_term() == -1) { // -i + rest op 0  <=>  i (flipped op) rest
      switch (op) {
      case BO_LT: op = BO_GT; break;
      case BO_LE: op = BO_GE; break;
      case BO_GT: op = BO_LT; break;
      case BO_GE: op = BO_LE; break;
      default: break;
      }
      return poly_expr(rest);
    }
    return poly_expr(-rest); // i + rest op 0  <=>  i op -rest
  }

  // An integer expression for a polynomial over parameters and kernel-level
  // locals (symbols resolve to what they name).
  ExprP poly_expr(const Poly& p) {
    ExprP sum;
    for (const auto& [m, coef] : p.terms()) {
      ExprP term = int_const(coef);
      for (const auto& sym : m)
        term = binary(Op::Mul, term, symbol_expr(sym));
      sum = sum ? binary(Op::Add, sum, term) : term;
    }
    return sum ? sum : int_const(0);
  }
  ExprP symbol_expr(const Sym& sym) {
    if (sym.is_counter())
      throw std::logic_error("lower: a loop counter in a size: " + sym.name);
    if (const Param* p = k_.find_param(sym.name))
      return param(p->name, p->elem);
    for (const auto& l : k_.kernel_locals)
      if (l->name == sym.name)
        return local_ref(l);
    throw std::logic_error("lower: unknown symbol " + sym.name);
  }

  // The `i = lo` of a C89-style loop, if that is its init statement.
  static const BinaryOperator* init_assignment(const ForStmt* f) {
    const auto* e = dyn_cast_or_null<clang::Expr>(f->getInit());
    const auto* a = e ? dyn_cast<BinaryOperator>(e->IgnoreParens()) : nullptr;
    return a && a->getOpcode() == BO_Assign ? a : nullptr;
  }

  // Every local variable assigned (=, op=, ++, --) somewhere in `s`.
  // The extreme (the largest if `upper`, else the smallest) of loop bound `e`
  // (`p` as a polynomial) over the enclosing loops' ranges: each outer counter
  // replaced by its first or last value, by the sign of its coefficient. Null
  // where a coefficient is not a constant.
  std::optional<ExprP> hull(const ExprP& e, const Poly& p, bool upper) const {
    std::map<std::string, ExprP> at;
    for (const auto& l : loops_) {
      Poly c = p.coefficient(Sym::counter(l->var));
      if (c == Poly())
        continue;
      if (!c.is_constant() || !to_poly(l->lo) || !to_poly(l->hi) ||
          to_poly(l->lo)->mentions_any_counter() || to_poly(l->hi)->mentions_any_counter())
        return std::nullopt;
      bool last = (c.constant_term() > 0) == upper;
      at[l->var] = last ? binary(Op::Sub, l->hi, int_const(1)) : l->lo;
    }
    std::function<ExprP(const ExprP&)> sub = [&](const ExprP& x) -> ExprP {
      if (x->op == Op::LoopVar)
        if (auto it = at.find(x->name); it != at.end())
          return it->second;
      if (x->op == Op::Local) // an integer local of the counters: its definition
        if (any_node(x, [](const ExprP& y) { return y->op == Op::LoopVar; }))
          return sub(x->local->def);
      return map_operands(x, sub);
    };
    ExprP out = sub(e);
    auto q = to_poly(out);
    if (!q || q->mentions_any_counter())
      return std::nullopt;
    return out;
  }

  // A lower bound of integer `e` over the enclosing loops that depends on the
  // sizes only: `e` itself where it mentions no counter, the hull of an
  // affine part, 0 for `x % m` with a constant m > 0 and x >= 0 (C's
  // remainder of a non-negative value), sums of those. Null otherwise.
  std::optional<ExprP> smallest(const ExprP& e) const {
    if (!any_node(e, [](const ExprP& x) { return x->op == Op::LoopVar; }))
      return e;
    if (auto p = to_poly(e))
      return hull(e, *p, false);
    if (e->op == Op::Add) {
      auto a = smallest(e->ops[0]), b = smallest(e->ops[1]);
      if (a && b)
        return binary(Op::Add, *a, *b);
      return std::nullopt;
    }
    if (e->op == Op::Rem && e->ops[1]->op == Op::IntConst && e->ops[1]->ival > 0 &&
        provably_nonneg(e->ops[0]))
      return int_const(0);
    if (e->op == Op::Local)
      return smallest(e->local->def);
    return std::nullopt;
  }

  // ---- scalar accumulators ------------------------------------------------
  //
  // `double s = 0; for (...) s += f(a[i]); out[0] = g(s);` and per-row sums:
  // `s` becomes a hidden work array H (Kernel::hidden) with one element per
  // iteration of the loops around the accumulating loop: `H[c] = <s before
  // the loop>` there, `H[c] += f(...)` in the loop, and `s` after the loop is
  // the work-array read H[c]. The output rules, the staged adjoint (which
  // recomputes H) and the tangent then treat it like any work array.

  static constexpr size_t kMaxAccumulators = 32;
  bool is_hidden(const std::string& array) const {
    return std::any_of(k_.hidden.begin(), k_.hidden.end(),
                       [&](const Param& h) { return h.name == array; });
  }
  struct Accumulator {
    std::string array; // the hidden array
    ExprP index;       // its element: the outer loops' iteration, mixed radix
  };
  std::map<const VarDecl*, Accumulator> accumulators_;

  // The term `e` of `v = v + e`, `v = v - e` (negate set) or `v = e + v`,
  // where `e` does not mention v; null for any other form.
  static const clang::Expr* accumulated_term(const clang::Expr* rhs, const VarDecl* v,
                                             bool& negate) {
    const auto* b = dyn_cast<BinaryOperator>(rhs->IgnoreParenImpCasts());
    if (!b || (b->getOpcode() != BO_Add && b->getOpcode() != BO_Sub))
      return nullptr;
    auto is_v = [&](const clang::Expr* e) {
      const auto* r = dyn_cast<DeclRefExpr>(e->IgnoreParenImpCasts());
      return r && r->getDecl() == v;
    };
    const clang::Expr* term = nullptr;
    if (is_v(b->getLHS()))
      term = b->getRHS();
    else if (b->getOpcode() == BO_Add && is_v(b->getRHS()))
      term = b->getLHS();
    if (!term || mentions(term, v))
      return nullptr;
    negate = b->getOpcode() == BO_Sub;
    return term;
  }

  static bool mentions(const Stmt* s, const VarDecl* v) {
    if (!s)
      return false;
    if (const auto* r = dyn_cast<DeclRefExpr>(s); r && r->getDecl() == v)
      return true;
    for (const Stmt* c : s->children())
      if (mentions(c, v))
        return true;
    return false;
  }

  // Every mention of `v` in `body` is the target of `v += e`, `v -= e` or
  // `v = v + e` (and its `v`), with `e` free of v, and there is at least one.
  static bool is_accumulator(const Stmt* body, const VarDecl* v) {
    int updates = 0;
    bool other = false;
    std::function<void(const Stmt*)> visit = [&](const Stmt* s) {
      if (!s || other)
        return;
      if (const auto* b = dyn_cast<BinaryOperator>(s); b && b->isAssignmentOp()) {
        const auto* r = dyn_cast<DeclRefExpr>(b->getLHS()->IgnoreParenImpCasts());
        if (r && r->getDecl() == v) {
          bool negate = false;
          bool ok = b->getOpcode() == BO_AddAssign || b->getOpcode() == BO_SubAssign
                        ? !mentions(b->getRHS(), v)
                        : b->getOpcode() == BO_Assign &&
                              accumulated_term(b->getRHS(), v, negate) != nullptr;
          if (!ok)
            other = true;
          ++updates;
          return;
        }
      }
      if (const auto* r = dyn_cast<DeclRefExpr>(s); r && r->getDecl() == v) {
        other = true;
        return;
      }
      for (const Stmt* c : s->children())
        visit(c);
    };
    visit(body);
    return updates > 0 && !other;
  }

  // Makes `v` (a real scalar with a value here) an accumulator of the loop
  // about to be lowered; false (and nothing done) where it cannot be one.
  bool start_accumulator(const VarDecl* v, SourceLocation loc) {
    auto it = env_.find(v);
    if (it == env_.end() || it->second.kind != Binding::Value || !it->second.value ||
        !is_real((*it->second.value)->type) || v->getType()->isReferenceType())
      return false;
    // One element per iteration of the enclosing loops: (outer - lo) * extent
    // of the inner ones + ..., which needs polynomial bounds.
    ExprP idx = int_const(0);
    for (size_t d = 0; d < loops_.size(); ++d) {
      const Loop& l = *loops_[d];
      if (!to_poly(l.lo) || !to_poly(l.hi))
        return false;
      ExprP here = binary(Op::Sub, loop_var(l.var), l.lo);
      idx = d == 0 ? here
                   : binary(Op::Add, binary(Op::Mul, idx, binary(Op::Sub, l.hi, l.lo)), here);
    }
    if (k_.hidden.size() == k_.hidden.capacity())
      return false; // (pointers into it must stay valid while lowering)
    Param h;
    h.name = "dpgen_sum_" + v->getNameAsString();
    for (int n = 2; k_.find_param(h.name); ++n)
      h.name = fmt::format("dpgen_sum_{}_{}", v->getNameAsString(), n);
    h.kind = ParamKind::Out;
    h.elem = (*it->second.value)->type;
    h.elem_name = type_spelling(h.elem);
    h.spelling = v->getNameAsString(); // the user's accumulator, for messages
    h.declaration = fmt::format("{}* {}", h.elem_name, h.name);
    k_.hidden.push_back(h);
    add_store(h.name, idx, *it->second.value, false, pos(loc), loc);
    accumulators_[v] = {h.name, idx};
    return true;
  }

  // After the accumulating loop: `v` is the sum, a read of its element.
  void finish_accumulator(const VarDecl* v, SourceLocation loc) {
    const Accumulator a = accumulators_.at(v);
    accumulators_.erase(v);
    const Param* h = k_.find_param(a.array);
    order_after_later_stores(a.array);
    ExprP r = read(a.array, a.index, h->elem, pos(loc), 0);
    std::const_pointer_cast<Expr>(r)->source = v->getNameAsString();
    k_.intermediates.insert(a.array);
    acc_.work_reads.push_back({a.array, cur_key(), next_store_seq_, a.index, path_, pos(loc)});
    env_[v].value = r;
    why_unset_.erase(v);
  }

  static void assigned_vars(const Stmt* s, std::set<const VarDecl*>& out) {
    if (!s)
      return;
    auto target = [&](const clang::Expr* e) {
      e = e->IgnoreParenImpCasts();
      if (const auto* sub = dyn_cast<ArraySubscriptExpr>(e)) // an element of a local array
        e = sub->getBase()->IgnoreParenImpCasts();
      if (const auto* r = dyn_cast<DeclRefExpr>(e))
        if (const auto* v = dyn_cast<VarDecl>(r->getDecl()))
          out.insert(v);
    };
    if (const auto* b = dyn_cast<BinaryOperator>(s); b && b->isAssignmentOp())
      target(b->getLHS());
    if (const auto* u = dyn_cast<UnaryOperator>(s); u && u->isIncrementDecrementOp())
      target(u->getSubExpr());
    for (const Stmt* c : s->children())
      assigned_vars(c, out);
  }

  int loop_step(const clang::Expr* inc, const VarDecl* var) {
    if (!inc)
      return 0;
    inc = inc->IgnoreParens();
    auto is_var = [&](const clang::Expr* e) {
      const auto* r = dyn_cast<DeclRefExpr>(e->IgnoreParenImpCasts());
      return r && r->getDecl() == var;
    };
    if (const auto* u = dyn_cast<UnaryOperator>(inc)) {
      if (!is_var(u->getSubExpr()))
        return 0;
      return u->isIncrementOp() ? 1 : u->isDecrementOp() ? -1 : 0;
    }
    if (const auto* b = dyn_cast<CompoundAssignOperator>(inc)) {
      clang::Expr::EvalResult r;
      if (!is_var(b->getLHS()) || !b->getRHS()->EvaluateAsInt(r, ctx_))
        return 0;
      int64_t k = r.Val.getInt().getSExtValue();
      if (k < 1 || k > 1024)
        return 0;
      return b->getOpcode() == BO_AddAssign ? int(k) : b->getOpcode() == BO_SubAssign ? -int(k) : 0;
    }
    return 0;
  }

  void check_not_assigned(const Stmt* s, const VarDecl* var) {
    if (!s)
      return;
    auto refers = [&](const clang::Expr* e) {
      const auto* r = dyn_cast<DeclRefExpr>(e->IgnoreParenImpCasts());
      return r && r->getDecl() == var;
    };
    if (const auto* b = dyn_cast<BinaryOperator>(s); b && b->isAssignmentOp() && refers(b->getLHS()))
      fail(b->getOperatorLoc(), fmt::format("loop counter '{}' is modified in the loop body",
                                            var->getNameAsString()), "dpgen-loop");
    if (const auto* u = dyn_cast<UnaryOperator>(s);
        u && u->isIncrementDecrementOp() && refers(u->getSubExpr()))
      fail(u->getOperatorLoc(), fmt::format("loop counter '{}' is modified in the loop body",
                                            var->getNameAsString()), "dpgen-loop");
    for (const Stmt* c : s->children())
      check_not_assigned(c, var);
  }

  // An expression statement: an assignment to an output element or a local.
  void expr_stmt(const clang::Expr* e) {
    e = e->IgnoreParens();
    if (const auto* w = dyn_cast<ExprWithCleanups>(e)) // temporaries: std::max(a, 0.0)
      e = w->getSubExpr()->IgnoreParens();
    if (const auto* u = dyn_cast<UnaryOperator>(e); u && u->isIncrementDecrementOp()) {
      assign(u->getSubExpr(), u->isIncrementOp() ? BO_AddAssign : BO_SubAssign, nullptr,
             u->getOperatorLoc());
      return;
    }
    // `(void)x;` (silences an unused-variable warning): nothing to do.
    if (const auto* c = dyn_cast<ExplicitCastExpr>(e);
        c && c->getType()->isVoidType() && isa<DeclRefExpr>(c->getSubExpr()->IgnoreParenImpCasts()))
      return;
    const auto* b = dyn_cast<BinaryOperator>(e);
    if (!b || !b->isAssignmentOp()) {
      if (const auto* c = dyn_cast<CallExpr>(e); c && c->getType()->isVoidType()) {
        (void)expr(e); // a void helper: its out-parameters and stores (or the unknown call)
        return;
      }
      if (isa<CallExpr>(e))
        (void)expr(e); // reports the unknown call
      fail(e->getExprLoc(), "expression statement has no effect on an output; only "
                            "assignments are in the kernel subset");
    }
    assign(b->getLHS(), b->getOpcode(), b->getRHS(), b->getOperatorLoc());
  }

  // `*p` of a helper's pointer parameter bound to a caller's local (`&f`).
  const VarDecl* deref_local(const clang::Expr* e) {
    const auto* u = dyn_cast<UnaryOperator>(e->IgnoreParenImpCasts());
    if (!u || u->getOpcode() != UO_Deref)
      return nullptr;
    const auto* r = dyn_cast<DeclRefExpr>(u->getSubExpr()->IgnoreParenImpCasts());
    const auto* v = r ? dyn_cast<VarDecl>(r->getDecl()) : nullptr;
    auto it = v ? env_.find(v) : env_.end();
    return it != env_.end() && it->second.kind == Binding::Value && it->second.deref_only ? v
                                                                                           : nullptr;
  }

  void assign(const clang::Expr* lhs, BinaryOperatorKind op, const clang::Expr* rhs,
              SourceLocation loc) {
    lhs = lhs->IgnoreParenImpCasts();
    if (const VarDecl* v = deref_local(lhs)) {
      assign_value(v, *scalar_type(v->getType()->getPointeeType()), lhs, op, rhs, loc);
      return;
    }
    if (auto le = local_element(lhs)) {
      Binding& b = env_[le->first];
      std::optional<ExprP>& slot = b.elems[le->second];
      std::string name = fmt::format("{}_{}", le->first->getNameAsString(), le->second);
      if (op == BO_Assign) {
        slot = make_local(name, nullptr, cast(expr(rhs), b.elem));
        return;
      }
      if (!slot)
        fail(lhs->getBeginLoc(), unset_message(le->first, "used before it has a value"));
      ExprP r = rhs ? expr(rhs) : int_const(1);
      Op bop = op == BO_AddAssign ? Op::Add : op == BO_SubAssign ? Op::Sub
               : op == BO_MulAssign ? Op::Mul : op == BO_DivAssign ? Op::Div : Op::Rem;
      if (bop == Op::Rem)
        fail(loc, "this compound assignment is outside the kernel subset");
      slot = make_local(name, nullptr, cast(binary(bop, *slot, r), b.elem));
      return;
    }
    if (auto acc = element(lhs)) {
      const Param* p = acc->param;
      if (p->inout) {
        // u[k] = v / u[k] += v on an in-place array: a store of the new value
        // into its twin; `+=` adds to the value u[k] has here (the old one, or
        // what this iteration stored).
        const Param* twin = k_.find_param(p->name + "_new");
        ExprP value = expr(rhs ? rhs : lhs);
        if (op != BO_Assign) {
          if (op != BO_AddAssign && op != BO_SubAssign && op != BO_MulAssign)
            fail(loc, "this compound assignment is outside the kernel subset");
          ExprP old = inout_value(p, acc->index, lhs->getBeginLoc(), lhs);
          ExprP r = rhs ? expr(rhs) : int_const(1);
          value = binary(op == BO_AddAssign ? Op::Add : op == BO_SubAssign ? Op::Sub : Op::Mul, old, r);
        }
        add_store(twin->name, acc->index, cast(value, p->elem), false, pos(lhs->getBeginLoc()),
                  lhs->getBeginLoc());
        acc_.inout_stores.push_back({p->name, cur_key(), next_store_seq_ - 1, acc->index});
        return;
      }
      if (!frames_.empty() && !frames_.back().is_void)
        fail(lhs->getBeginLoc(), fmt::format("helper '{}' writes to array '{}': helpers return "
                                             "values; store them in the kernel",
                                             frames_.back().fn->getNameAsString(), p->name));
      if (p->kind != ParamKind::Out)
        fail(lhs->getBeginLoc(),
             fmt::format("'{}' is written but is not a DPGEN_OUT parameter; inputs and constant "
                         "arrays are read only{}",
                         p->name,
                         p->kind == ParamKind::In
                             ? " (an array updated in place, as in Gauss-Seidel or an in-place "
                               "time step, carries values from one iteration to the next: "
                               "write the new values to a separate DPGEN_OUT array)"
                             : ""));
      ExprP value;
      bool accumulate = false;
      if (op == BO_Assign) {
        value = expr(rhs);
      } else if (op == BO_AddAssign || op == BO_SubAssign) {
        ExprP r = rhs ? expr(rhs) : int_const(1);
        value = op == BO_AddAssign ? r : unary(Op::Neg, r);
        accumulate = true;
      } else {
        fail(loc, fmt::format("compound assignment '{}' to output '{}' needs the element's "
                              "previous value, which the adjoint does not have; only '=', '+=' "
                              "and '-=' write outputs",
                              BinaryOperator::getOpcodeStr(op).str(), p->name));
      }
      add_store(p->name, acc->index, cast(value, p->elem), accumulate, pos(lhs->getBeginLoc()),
                lhs->getBeginLoc());
      return;
    }
    const auto* ref = dyn_cast<DeclRefExpr>(lhs);
    const auto* var = ref ? dyn_cast<VarDecl>(ref->getDecl()) : nullptr;
    if (!var)
      fail(lhs->getBeginLoc(), "assignment target is outside the kernel subset (write to an "
                               "output element or a local variable)");
    auto it = env_.find(var);
    if (it == env_.end()) {
      if (var->hasGlobalStorage())
        fail(lhs->getBeginLoc(), fmt::format("write to '{}': global state is outside the kernel "
                                             "subset",
                                             var->getNameAsString()));
      fail(lhs->getBeginLoc(), fmt::format("'{}' is outside the kernel subset",
                                           var->getNameAsString()));
    }
    if (it->second.kind != Binding::Value)
      fail(lhs->getBeginLoc(), fmt::format("parameter '{}' is assigned; kernel parameters are "
                                           "read only",
                                           var->getNameAsString()));
    auto t = scalar_type(var->getType().getNonReferenceType());
    if (!t)
      fail(lhs->getBeginLoc(), fmt::format("'{}' has a type outside the kernel subset",
                                           var->getNameAsString()));
    assign_value(var, *t, lhs, op, rhs, loc);
  }

  // var = rhs, var += rhs, ... for a scalar local (or what a helper's `*p`
  // stands for).
  void assign_value(const VarDecl* var, Type t, const clang::Expr* lhs, BinaryOperatorKind op,
                    const clang::Expr* rhs, SourceLocation loc) {
    if (auto acc = accumulators_.find(var); acc != accumulators_.end()) {
      // s += e, s -= e, s = s + e, s = s - e, s = e + s: the hidden array's
      // element for this iteration of the outer loops gets += (-)e.
      const clang::Expr* term = rhs;
      bool negate = op == BO_SubAssign;
      if (op == BO_Assign)
        term = accumulated_term(rhs, var, negate);
      if (!term)
        fail(loc, fmt::format("internal error: accumulator '{}' assigned in an unexpected form",
                              var->getNameAsString()));
      ExprP e = expr(term);
      add_store(acc->second.array, acc->second.index, cast(negate ? unary(Op::Neg, e) : e, t),
                true, pos(lhs->getBeginLoc()), lhs->getBeginLoc());
      return;
    }
    Binding& b = env_[var];
    ExprP value;
    if (op == BO_Assign) {
      value = expr(rhs);
    } else {
      if (!b.value)
        fail(lhs->getBeginLoc(), unset_message(var, "used before it has a value"));
      ExprP r = rhs ? expr(rhs) : int_const(1);
      Op bop;
      switch (op) {
      case BO_AddAssign:
        bop = Op::Add;
        break;
      case BO_SubAssign:
        bop = Op::Sub;
        break;
      case BO_MulAssign:
        bop = Op::Mul;
        break;
      case BO_DivAssign:
        bop = Op::Div;
        break;
      default:
        fail(loc, "this compound assignment is outside the kernel subset");
      }
      value = binary(bop, *b.value, r);
      if (bop == Op::Sub && var->getType().getNonReferenceType()->isUnsignedIntegerType())
        check_unsigned_result(value, loc,
                              fmt::format("unsigned '{}' after '-='", var->getNameAsString()),
                              lhs);
    }
    b.value = make_local(var->getNameAsString(), var, cast(value, t));
  }

  Nest& current_nest() {
    auto it = nest_index_.find(cur_key());
    if (it == nest_index_.end()) {
      Nest n;
      n.key = cur_key();
      for (const auto& l : loops_)
        n.loops.push_back(*l);
      k_.nests.push_back(n);
      it = nest_index_.emplace(cur_key(), k_.nests.size() - 1).first;
    }
    return k_.nests[it->second];
  }

  // `prefix` holds wherever `path` holds: its conditions open `path`.
  static bool is_prefix(const std::vector<PathCond>& prefix, const std::vector<PathCond>& path) {
    if (prefix.size() > path.size())
      return false;
    for (size_t i = 0; i < prefix.size(); ++i)
      if (prefix[i].cond != path[i].cond || prefix[i].positive != path[i].positive)
        return false;
    return true;
  }

  // The store of this iteration that a later statement on the current path
  // sees at `array[idx]`: the last one to that element whose path is still
  // open. nullptr when there is none.
  Store* visible_store(Nest& nest, const std::string& array, const ExprP& idx) {
    for (auto it = nest.stores.rbegin(); it != nest.stores.rend(); ++it)
      if (it->array == array && same_index(it->index, idx) && is_prefix(it->path, path_))
        return &*it;
    return nullptr;
  }

  void add_store(const std::string& array, ExprP idx, ExprP value, bool accumulate, SourcePos p,
                 SourceLocation loc) {
    // Updating an element this nest stored, after a later nest stored the
    // array too: the update goes after that nest.
    if (auto it = nest_index_.find(cur_key()); it != nest_index_.end())
      if (visible_store(k_.nests[it->second], array, idx))
        order_after_later_stores(array);
    Nest& nest = current_nest();
    // A second store to the same element in one iteration updates the first:
    // `x[k] = a; ... x[k] += b;` stores a + b, and a store under a further
    // condition keeps the earlier value where that condition fails.
    if (Store* prev = visible_store(nest, array, idx)) {
      ExprP updated = accumulate ? binary(Op::Add, prev->value, value) : value;
      ExprP cond;
      for (size_t i = prev->path.size(); i < path_.size(); ++i) {
        ExprP c = path_[i].positive ? path_[i].cond : unary(Op::Not, path_[i].cond);
        cond = cond ? binary(Op::And, cond, c) : c;
      }
      prev->value = cond ? select(cond, updated, prev->value) : updated;
      prev->pos = p;
      return;
    }
    // Otherwise a store whose path is not provably disjoint from another
    // store's to an element that may be the same would overwrite it.
    for (auto& s : nest.stores) {
      if (s.array != array || paths_disjoint(s.path, path_) || (s.accumulate && accumulate))
        continue;
      auto pa = to_poly(s.index), pb = to_poly(idx);
      Facts facts;
      for (const auto& l : loops_)
        add_nonempty(*l, facts);
      for (const auto& pc : path_)
        add_facts(pc, facts);
      if (pa && pb) {
        Poly g1 = *pa - *pb - Poly::constant(1), g2 = *pb - *pa - Poly::constant(1);
        if (prove_nonneg(g1, facts) || prove_nonneg(g2, facts))
          continue;
        if (!(*pa - *pb).mentions_any_counter() && !accumulate && !s.accumulate &&
            is_prefix(path_, s.path)) {
          // Different elements for some sizes only (u[0] and u[n - 1]): where
          // they are the same, this store overwrites the earlier one, which
          // then contributes nothing. The earlier store gets that condition.
          s.path.push_back({binary(Op::Eq, s.index, idx), false});
          continue;
        }
      }
      fail(loc, fmt::format("output '{}' may be written twice in one iteration (first at "
                            "line {}); write each element once",
                            array, s.pos.line));
    }
    Store st{array, idx, value, path_, p};
    st.accumulate = accumulate;
    st.seq = next_store_seq_++;
    nest.stores.push_back(st);
  }
  int next_store_seq_ = 0;

  // ---- in-place arrays (DPGEN_INOUT) ------------------------------------------

  // The reads of work arrays and in-place arrays and the stores to in-place
  // arrays, which the checks need besides the IR (check.hpp).
  Accesses acc_;

  // The value u[k] of an in-place array has here: what this iteration stored
  // at k, or the value before the call (a read of the input).
  ExprP inout_value(const Param* p, const ExprP& idx, SourceLocation loc, const clang::Expr* e) {
    auto nit = nest_index_.find(cur_key());
    if (nit != nest_index_.end())
      if (Store* st = visible_store(k_.nests[nit->second], p->name + "_new", idx))
        return st->value;
    acc_.inout_reads.push_back({p->name, cur_key(), next_store_seq_, idx, {}, pos(loc)});
    ExprP r = read(p->name, idx, p->elem, pos(loc), pointer_levels(*p));
    std::const_pointer_cast<Expr>(r)->source = text(e);
    return r;
  }

  // ---- work arrays (outputs a later loop nest reads) ---------------------------

  bool written_by_other_nest(const std::string& array) const {
    for (const auto& [key, idx] : nest_index_)
      if (key != cur_key())
        for (const auto& st : k_.nests[idx].stores)
          if (st.array == array)
            return true;
    return false;
  }

  // Unless set, a read of a work array outside every loop is recorded for
  // the checks (Accesses::kernel_level_work_reads).
  bool path_reads_ok_ = false;

  // `e >= 0` wherever this statement runs: its loops run, the counters are
  // in range, the conditions on its path hold, unsigned sizes are >= 0.
  bool provably_nonneg(const ExprP& e, const std::vector<PathCond>& more = {}) const {
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

  // Integer arithmetic in the generated code is signed and 64 bits wide; the
  // kernel's own may wrap (unsigned below zero, a negative value converted to
  // unsigned) or truncate (to short or char). Where the two could differ the
  // kernel is rejected, unless the value provably stays in range. Loop bounds
  // are exempt: where they differ the forward loop itself runs ~2^64 times.
  bool in_loop_bounds_ = false;
  // The value of `e` only goes into an array index (through + - * and
  // conversions): if it wraps, the kernel itself reads out of bounds.
  bool feeds_index_only(const clang::Expr* e) {
    const clang::Stmt* child = e;
    for (int depth = 0; depth < 32; ++depth) {
      auto parents = ctx_.getParents(*child);
      if (parents.size() != 1)
        return false;
      const clang::Stmt* up = parents[0].get<clang::Stmt>();
      if (!up)
        return false;
      if (const auto* sub = dyn_cast<ArraySubscriptExpr>(up))
        return sub->getIdx()->IgnoreParenImpCasts() == child ||
               sub->getIdx() == child;
      if (const auto* oc = dyn_cast<CXXOperatorCallExpr>(up))
        return oc->getOperator() == OO_Subscript && oc->getNumArgs() == 2 &&
               oc->getArg(1)->IgnoreParenImpCasts() == static_cast<const clang::Expr*>(child)->IgnoreParens();
      if (const auto* b = dyn_cast<BinaryOperator>(up)) {
        if (b->getOpcode() != BO_Add && b->getOpcode() != BO_Sub && b->getOpcode() != BO_Mul)
          return false;
      } else if (const auto* c = dyn_cast<ConditionalOperator>(up)) {
        // an arm (`i == 0 ? n - 1 : i - 1`): taken only where it is the index
        if (c->getCond() == child || c->getCond()->IgnoreParenImpCasts() == child)
          return false;
      } else if (!isa<ParenExpr>(up) && !isa<ImplicitCastExpr>(up)) {
        return false;
      }
      child = up;
    }
    return false;
  }
  // The conditions of the ternaries `e` is an arm of (`i == 0 ? n - 1 : i - 1`).
  std::vector<PathCond> arm_conditions(const clang::Expr* e) {
    std::vector<PathCond> out;
    const clang::Stmt* child = e;
    for (int depth = 0; depth < 32; ++depth) {
      auto parents = ctx_.getParents(*child);
      if (parents.size() != 1)
        break;
      const clang::Stmt* up = parents[0].get<clang::Stmt>();
      if (!up || !isa<clang::Expr>(up))
        break;
      if (const auto* c = dyn_cast<ConditionalOperator>(up)) {
        bool in_true = c->getTrueExpr() == child, in_false = c->getFalseExpr() == child;
        if (in_true || in_false)
          out.push_back({cond(c->getCond()), in_true});
      }
      child = up;
    }
    return out;
  }
  void check_unsigned_result(const ExprP& value, SourceLocation loc, const std::string& what,
                             const clang::Expr* node) {
    if (in_loop_bounds_ || feeds_index_only(node) || provably_nonneg(value) ||
        provably_nonneg(value, arm_conditions(node)))
      return;
    fail(loc, fmt::format("{} may go below zero here, where the kernel's unsigned arithmetic "
                          "wraps around but dpgen's index arithmetic (signed, 64 bits) does not: "
                          "compute it in a signed type, or guard it so that it stays >= 0 (dpgen "
                          "proves that from the loop bounds and the conditions around it)",
                          what));
  }

  // Facts about the parameters on the current path.
  Facts facts_of_path() const {
    Facts f;
    for (const auto& pc : path_)
      add_facts(pc, f);
    return f;
  }

  static bool paths_disjoint(const std::vector<PathCond>& a, const std::vector<PathCond>& b) {
    for (const auto& x : a)
      for (const auto& y : b)
        if (x.cond == y.cond && x.positive != y.positive)
          return true;
    return false;
  }

  // An index that multiplies three or more sizes and counters (a 3D
  // `(l*ny + j)*nx + i`) passes 2^31 on grids of 1290^3 cells: computed in a
  // 32-bit type it overflows, in the forward kernel and in its adjoint alike.
  void check_index_width(const clang::Expr* e, const ExprP& idx, const std::string& array) {
    QualType t = e->IgnoreImpCasts()->getType();
    if (ctx_.getTypeSize(t) >= 64)
      return;
    auto p = to_poly(idx);
    if (!p || p->degree() < 3)
      return;
    // The forward kernel has the same limit; the adjoint computes its indices
    // in 64 bits, so this is a warning about the user's code, not an error.
    if (warned_width_)
      return; // once per kernel
    warned_width_ = true;
    auto& d = ctx_.getDiagnostics();
    unsigned id = d.getCustomDiagID(DiagnosticsEngine::Warning, "%0");
    d.Report(e->getBeginLoc(), id)
        << fmt::format("index of '{}' is computed in the {}-bit type '{}' but multiplies {} sizes "
                       "and counters ('{}'): past 2^31 elements it overflows in this kernel (the "
                       "generated adjoint computes it in 64 bits); compute it in std::ptrdiff_t "
                       "or long [dpgen-index-width]",
                       array, ctx_.getTypeSize(t), t.getAsString(), p->degree(), p->str());
  }
  bool warned_width_ = false;

  // ---- expressions -----------------------------------------------------------

  // ---- helper functions ---------------------------------------------------------

  // A user function called from a kernel (a limiter, a flux, minmod) is
  // differentiated by inlining: its parameters are bound to the arguments'
  // values (arrays to the kernel's arrays), its body is lowered like the
  // kernel's, and its returns become one value, selected by the conditions
  // under which each return is reached.
  struct InlineFrame {
    const FunctionDecl* fn;
    size_t path_depth;
    size_t loop_depth;
    Type ret;
    std::vector<std::pair<std::vector<PathCond>, ExprP>> returns;
    bool is_void = false; // results through out-parameters, or stores
  };
  std::vector<InlineFrame> frames_;

  ExprP inline_call(const CallExpr* c, const FunctionDecl* f) {
    const FunctionDecl* def = nullptr;
    f->hasBody(def);
    for (const auto& fr : frames_)
      if (fr.fn->getCanonicalDecl() == def->getCanonicalDecl())
        fail(c->getBeginLoc(), fmt::format("recursive call to '{}' is outside the kernel subset",
                                           def->getNameAsString()));
    if (frames_.size() == 16)
      fail(c->getBeginLoc(), "helper calls nest more than 16 deep");
    // A lambda of the kernel: its call operator, the closure object first.
    unsigned first = 0;
    if (const auto* m = dyn_cast<CXXMethodDecl>(def); m && m->getParent()->isLambda()) {
      const auto* oc = dyn_cast<CXXOperatorCallExpr>(c);
      const auto* ref =
          oc ? dyn_cast<DeclRefExpr>(oc->getArg(0)->IgnoreParenImpCasts()) : nullptr;
      const auto* lv = ref ? dyn_cast<VarDecl>(ref->getDecl()) : nullptr;
      if (lv && poisoned_.count(lv))
        throw Rejected{}; // its declaration's error is reported already
      auto it = lv ? env_.find(lv) : env_.end();
      if (it == env_.end() || it->second.kind != Binding::Lambda)
        fail(c->getBeginLoc(), "a lambda is called through a local of the kernel that holds it "
                               "(auto f = [&](...) {...}; f(...))");
      if (!m->isConst())
        fail(c->getBeginLoc(), fmt::format("lambda '{}' is mutable: its copies keep their "
                                           "changes from one call to the next, which inlining "
                                           "does not; make it a plain lambda",
                                           lv->getNameAsString()));
      for (const auto& [cv, was] : it->second.captured_arrays)
        if (env_[cv].elems != was)
          fail(c->getBeginLoc(), fmt::format("lambda '{}' captured local array '{}' by copy, "
                                             "and '{}' changed before this call; capture it by "
                                             "reference, or make the lambda after the change",
                                             lv->getNameAsString(), cv->getNameAsString(),
                                             cv->getNameAsString()));
      for (const auto& [cv, was] : it->second.captured)
        if (env_[cv].value != was)
          fail(c->getBeginLoc(), fmt::format("lambda '{}' captured '{}' by copy, and '{}' "
                                             "changed before this call; capture it by "
                                             "reference, or make the lambda after the change",
                                             lv->getNameAsString(), cv->getNameAsString(),
                                             cv->getNameAsString()));
      first = 1;
    } else if (isa<CXXMethodDecl>(def) || def->isVariadic()) {
      fail(c->getBeginLoc(), fmt::format("'{}' is a member or variadic function; a kernel calls "
                                         "free helper functions only",
                                         def->getNameAsString()));
    }
    const bool is_void = def->getReturnType()->isVoidType();
    auto rt = is_void ? std::optional<Type>(Type::Double) : scalar_type(def->getReturnType());
    if (!rt || def->getReturnType()->isReferenceType())
      fail(c->getBeginLoc(), fmt::format("helper '{}' returns '{}'; a helper called from a kernel "
                                         "returns an int, float, double or bool value (or "
                                         "void, with its results in out-parameters)",
                                         def->getNameAsString(),
                                         def->getReturnType().getAsString()));
    if (c->getNumArgs() != def->getNumParams() + first)
      fail(c->getBeginLoc(), "call with default arguments is outside the kernel subset");
    // Bind the parameters (arguments are evaluated in the caller's scope).
    std::vector<std::pair<const VarDecl*, Binding>> binds;
    // Out-parameters: `double& f` and `double* f` (called with `&x`) bound to
    // a local x of the caller: copied in, and copied back after the body
    // (the same as a reference while no two of them name one local).
    std::vector<std::pair<const ParmVarDecl*, const VarDecl*>> outs;
    auto out_param = [&](const ParmVarDecl* pd, const clang::Expr* arg, bool pointer) {
      const clang::Expr* a = arg->IgnoreParenImpCasts();
      if (pointer) {
        const auto* u = dyn_cast<UnaryOperator>(a);
        a = u && u->getOpcode() == UO_AddrOf ? u->getSubExpr()->IgnoreParenImpCasts() : nullptr;
      }
      const auto* r = a ? dyn_cast<DeclRefExpr>(a) : nullptr;
      const auto* v = r ? dyn_cast<VarDecl>(r->getDecl()) : nullptr;
      auto it = v ? env_.find(v) : env_.end();
      if (it == env_.end() || it->second.kind != Binding::Value || it->second.deref_only)
        fail(arg->getBeginLoc(), fmt::format("argument for out-parameter '{}' of helper '{}' must "
                                             "be {}a local variable of the caller",
                                             pd->getNameAsString(), def->getNameAsString(),
                                             pointer ? "the address of " : ""));
      for (const auto& [q, w] : outs)
        if (w == v)
          fail(arg->getBeginLoc(), fmt::format("local '{}' is passed to two out-parameters of "
                                               "helper '{}'",
                                               v->getNameAsString(), def->getNameAsString()));
      if (!is_void)
        fail(pd->getLocation(), fmt::format("helper '{}' returns a value and has out-parameter "
                                            "'{}': return void and put every result in an "
                                            "out-parameter, or return the one result",
                                            def->getNameAsString(), pd->getNameAsString()));
      Binding b = it->second;
      b.deref_only = pointer;
      binds.push_back({pd, b});
      outs.push_back({pd, v});
    };
    for (unsigned i = 0; i < def->getNumParams(); ++i) {
      const ParmVarDecl* pd = def->getParamDecl(i);
      const clang::Expr* arg = c->getArg(i + first);
      QualType pt = pd->getType();
      if (pt->isPointerType() && !pt->getPointeeType().isConstQualified() &&
          scalar_type(pt->getPointeeType()) && [&] {
            const auto* u = dyn_cast<UnaryOperator>(arg->IgnoreParenImpCasts());
            return u && u->getOpcode() == UO_AddrOf;
          }()) {
        out_param(pd, arg, true);
        continue;
      }
      if (pt->isPointerType()) {
        const clang::Expr* base = arg->IgnoreParenImpCasts();
        const Param* ap = isa<DeclRefExpr>(base) ? array_base(base) : nullptr;
        if (!ap)
          fail(arg->getBeginLoc(), fmt::format("argument for pointer parameter '{}' of helper "
                                               "'{}' must be an array parameter of the kernel "
                                               "itself (no pointer arithmetic)",
                                               pd->getNameAsString(), def->getNameAsString()));
        Binding b;
        b.kind = Binding::ArrayParam;
        b.param = ap;
        binds.push_back({pd, b});
        continue;
      }
      if (pt->isReferenceType() && !pt.getNonReferenceType().isConstQualified()) {
        if (!scalar_type(pt.getNonReferenceType()))
          fail(pd->getLocation(), fmt::format("parameter '{}' of helper '{}' has type '{}', "
                                              "outside the kernel subset",
                                              pd->getNameAsString(), def->getNameAsString(),
                                              pt.getAsString()));
        out_param(pd, arg, false);
        continue;
      }
      auto t = scalar_type(pt.getNonReferenceType());
      if (!t)
        fail(pd->getLocation(), fmt::format("parameter '{}' of helper '{}' has type '{}', outside "
                                            "the kernel subset",
                                            pd->getNameAsString(), def->getNameAsString(),
                                            pt.getAsString()));
      Binding b;
      b.kind = Binding::Value;
      b.value = make_local(pd->getNameAsString(), pd, cast(expr(arg), *t));
      binds.push_back({pd, b});
    }
    for (const auto& [pd, b] : binds)
      env_[pd] = b;
    frames_.push_back({def, path_.size(), loops_.size(), *rt, {}, is_void});
    Escape e;
    try {
      e = lower(def->getBody());
    } catch (const Rejected&) {
      path_.resize(frames_.back().path_depth);
      frames_.pop_back();
      throw;
    }
    InlineFrame fr = frames_.back();
    frames_.pop_back();
    path_.resize(fr.path_depth);
    if (is_void) {
      for (const auto& [pd, v] : outs)
        env_[v].value = env_[pd].value;
      return nullptr;
    }
    if (e != Escape::Always || fr.returns.empty())
      fail(def->getBody()->getEndLoc(), fmt::format("helper '{}' may reach its end without "
                                                    "returning a value",
                                                    def->getNameAsString()));
    // The last return is reached when no earlier one was.
    ExprP v = fr.returns.back().second;
    for (size_t i = fr.returns.size() - 1; i-- > 0;) {
      ExprP cond;
      for (const auto& pc : fr.returns[i].first) {
        ExprP c1 = pc.positive ? pc.cond : unary(Op::Not, pc.cond);
        cond = cond ? binary(Op::And, cond, c1) : c1;
      }
      v = cond ? select(cond, fr.returns[i].second, v) : fr.returns[i].second;
    }
    return v;
  }

  // An element of an array parameter: `a[k]`, `a[j][i]` of a multi-dimensional
  // array (flattened row-major), `*p` (element 0: a scalar passed by pointer).
  struct Access {
    const Param* param;
    ExprP index;
  };

  std::optional<Access> element(const clang::Expr* e) {
    e = e->IgnoreParens();
    if (const auto* u = dyn_cast<UnaryOperator>(e); u && u->getOpcode() == UO_Deref) {
      const clang::Expr* base = u->getSubExpr()->IgnoreParenImpCasts();
      if (isa<DeclRefExpr>(base)) {
        const Param* p = array_base(base);
        if (p->row_pointers)
          fail(u->getOperatorLoc(), fmt::format("'*{}' of row-pointer array '{}' is a row; index "
                                                "its elements as {}[j][i]",
                                                p->name, p->name, p->name));
        return Access{p, int_const(0)};
      }
      fail(u->getOperatorLoc(), "pointer arithmetic is outside the kernel subset; index the "
                                "parameter directly: a[i + 1]");
    }
    if (const auto* oc = dyn_cast<CXXOperatorCallExpr>(e);
        oc && oc->getOperator() == OO_Subscript && oc->getNumArgs() == 2) {
      // v[i] of a std::vector parameter
      const clang::Expr* base = oc->getArg(0)->IgnoreParenImpCasts();
      if (!isa<DeclRefExpr>(base))
        fail(base->getBeginLoc(), "operator[] must index a std::vector parameter of the kernel");
      const Param* p = array_base(base);
      ExprP idx = expr(oc->getArg(1));
      if (idx->type != Type::Int)
        fail(oc->getArg(1)->getBeginLoc(), "array index must be an integer");
      return Access{p, idx};
    }
    const auto* sub = dyn_cast<ArraySubscriptExpr>(e);
    if (!sub)
      return std::nullopt;
    ExprP idx = expr(sub->getIdx());
    if (idx->type != Type::Int)
      fail(sub->getIdx()->getBeginLoc(), "array index must be an integer");
    const clang::Expr* base = sub->getBase()->IgnoreParenImpCasts();
    if (const auto* row = dyn_cast<ArraySubscriptExpr>(base);
        row && row->getType().getCanonicalType()->isPointerType()) {
      // a[j][i] of row pointers `double** a`: the flat j * R + i (R the row
      // symbol); a[k][j][i] of `double*** a`: k * P + j * R + i. The indices
      // must be affine: the printer writes them back as [k][j][i].
      std::vector<const clang::Expr*> outer = {row->getIdx()}; // j, then k
      const clang::Expr* rb = row->getBase()->IgnoreParenImpCasts();
      if (const auto* plane = dyn_cast<ArraySubscriptExpr>(rb);
          plane && plane->getType().getCanonicalType()->isPointerType()) {
        outer.push_back(plane->getIdx());
        rb = plane->getBase()->IgnoreParenImpCasts();
      }
      const Param* p = isa<DeclRefExpr>(rb) ? array_base(rb) : nullptr;
      if (!p || !p->row_pointers)
        fail(base->getBeginLoc(), "rows reached through a pointer must come straight from a "
                                  "'double**' or 'double***' kernel parameter: a[j][i], "
                                  "a[k][j][i]");
      if (outer.size() != (p->plane_pointers ? 2u : 1u))
        fail(sub->getBeginLoc(), fmt::format("'{}' is indexed with {} subscripts; index its "
                                             "elements as {}",
                                             p->name, outer.size() + 1,
                                             p->plane_pointers ? "a[k][j][i]" : "a[j][i]"));
      ExprP flat = idx;
      std::vector<ExprP> symbols = {row_lengths_.at(p->name)};
      if (p->plane_pointers)
        symbols.push_back(plane_lengths_.at(p->name));
      bool affine = to_poly(idx).has_value();
      for (size_t d = 0; d < outer.size(); ++d) {
        ExprP x = expr(outer[d]);
        if (x->type != Type::Int)
          fail(outer[d]->getBeginLoc(), "array index must be an integer");
        affine = affine && to_poly(x).has_value();
        flat = binary(Op::Add, binary(Op::Mul, x, symbols[d]), flat);
      }
      if (!affine)
        fail(sub->getBeginLoc(), fmt::format("row-pointer array '{}' is indexed at a "
                                             "data-dependent row or column; dpgen needs every "
                                             "index of a[j][i] affine in the loop counters "
                                             "and sizes for row pointers (pass a flat array for "
                                             "interpolation)",
                                             p->name));
      return Access{p, flat};
    }
    if (const auto* row = dyn_cast<ArraySubscriptExpr>(base)) {
      // a[j][i]: row j of an array of rows, each `extent` elements long.
      QualType rt = row->getType().getCanonicalType();
      const clang::ArrayType* at = ctx_.getAsArrayType(rt);
      if (!at)
        fail(base->getBeginLoc(),
             "rows reached through a pointer ('double** a', a[j][i]) are outside the kernel "
             "subset: dpgen cannot prove rows do not overlap; pass the array as 'double (*a)[N]', "
             "'double a[][N]' or a flat pointer with a[j * N + i]");
      ExprP extent;
      if (const auto* c = dyn_cast<ConstantArrayType>(at))
        extent = int_const(static_cast<long long>(c->getSize().getZExtValue()));
      else if (const auto* v = dyn_cast<VariableArrayType>(at))
        extent = expr(v->getSizeExpr());
      else
        fail(base->getBeginLoc(), "this array type is outside the kernel subset");
      auto inner = element(row);
      ExprP flat = binary(Op::Add, binary(Op::Mul, inner->index, extent), idx);
      // (the flat index of a[j][i] is computed by the compiler in 64 bits)
      return Access{inner->param, flat};
    }
    const Param* p = array_base(base);
    if (p->row_pointers)
      fail(sub->getBeginLoc(), fmt::format("row '{}[...]' of row-pointer array '{}' is used as a "
                                           "value; index its elements as {}[j][i]",
                                           p->name, p->name, p->name));
    check_index_width(sub->getIdx(), idx, p->name);
    return Access{p, idx};
  }

  const Param* array_base(const clang::Expr* base) {
    const auto* ref = dyn_cast<DeclRefExpr>(base);
    if (!ref) {
      if (isa<BinaryOperator>(base) || isa<UnaryOperator>(base))
        fail(base->getBeginLoc(), "pointer arithmetic is outside the kernel subset; index the "
                                  "parameter directly: a[i + 1]");
      fail(base->getBeginLoc(), "array access must index a pointer parameter of the kernel");
    }
    if (const auto* v = dyn_cast<VarDecl>(ref->getDecl()); v && poisoned_.count(v))
      throw Rejected{}; // its declaration's error is reported already
    auto it = env_.find(dyn_cast<VarDecl>(ref->getDecl()));
    if (it == env_.end() || it->second.kind != Binding::ArrayParam) {
      if (const auto* v = dyn_cast<VarDecl>(ref->getDecl()); v && v->hasGlobalStorage())
        fail(base->getBeginLoc(), fmt::format("'{}' is global state, outside the kernel subset",
                                              v->getNameAsString()));
      fail(base->getBeginLoc(), "array access must index a pointer parameter of the kernel");
    }
    return it->second.param;
  }

  ExprP cond(const clang::Expr* e) {
    ExprP c = expr(e);
    if (c->type != Type::Bool)
      c = binary(Op::Ne, c, c->type == Type::Int ? int_const(0) : real_const(0, c->type, ""));
    return c;
  }

  ExprP expr(const clang::Expr* e) {
    e = e->IgnoreParens();
    if (const auto* c = dyn_cast<ImplicitCastExpr>(e))
      return cast_expr(c, c->getSubExpr());
    if (const auto* c = dyn_cast<ExplicitCastExpr>(e))
      return cast_expr(c, c->getSubExpr());
    if (const auto* m = dyn_cast<MaterializeTemporaryExpr>(e))
      return expr(m->getSubExpr());
    if (const auto* w = dyn_cast<ExprWithCleanups>(e))
      return expr(w->getSubExpr());
    if (const auto* c = dyn_cast<ConstantExpr>(e))
      return expr(c->getSubExpr());
    if (const auto* l = dyn_cast<IntegerLiteral>(e))
      return int_const(static_cast<long long>(l->getValue().getSExtValue()));
    if (const auto* l = dyn_cast<FloatingLiteral>(e)) {
      Type t = type_of(e);
      // The literal as written; from a macro (`#define C 0.5` in a header the
      // generated code does not include), its spelling in the definition.
      SourceLocation at = l->getLocation();
      std::string spelled_as =
          at.isMacroID()
              ? Lexer::getSourceText(CharSourceRange::getTokenRange(sm_.getSpellingLoc(at)), sm_,
                                     ctx_.getLangOpts())
                    .str()
              : text(l);
      return real_const(l->getValueAsApproximateDouble(), t, spelled_as);
    }
    if (const auto* l = dyn_cast<CXXBoolLiteralExpr>(e))
      return binary(Op::Eq, int_const(l->getValue() ? 1 : 0), int_const(1));
    if (const auto* r = dyn_cast<DeclRefExpr>(e))
      return decl_ref(r);
    if (const VarDecl* v = deref_local(e)) {
      const Binding& b = env_[v];
      if (!b.value)
        fail(e->getBeginLoc(), unset_message(v, "may be used before it has a value"));
      return *b.value;
    }
    if (auto le = local_element(e)) {
      const std::optional<ExprP>& v = env_[le->first].elems[le->second];
      if (!v)
        fail(e->getBeginLoc(), unset_message(le->first, "may be used before it has a value"));
      return *v;
    }
    if (auto acc = element(e)) {
      const Param* p = acc->param;
      if (p->kind == ParamKind::Out) {
        // An output read back in the iteration that stored it: that value.
        order_after_later_stores(p->name);
        auto nit = nest_index_.find(cur_key());
        Store* st = nit == nest_index_.end()
                        ? nullptr
                        : visible_store(k_.nests[nit->second], p->name, acc->index);
        // An output an earlier loop nest wrote (a work array: fluxes, then
        // the update from them): an intermediate, read like an input; the
        // adjoint recomputes it and runs the nests backwards.
        if (!st && written_by_other_nest(p->name)) {
          if (loops_.empty() && !path_reads_ok_)
            acc_.kernel_level_work_reads.push_back({p->name, pos(e->getBeginLoc())});
          ExprP r = read(p->name, acc->index, p->elem, pos(e->getBeginLoc()), pointer_levels(*p));
          std::const_pointer_cast<Expr>(r)->source = text(e);
          k_.intermediates.insert(p->name);
          acc_.work_reads.push_back(
              {p->name, cur_key(), next_store_seq_, acc->index, path_, pos(e->getBeginLoc())});
          return r;
        }
        if (!st || st->accumulate)
          fail(e->getBeginLoc(),
               fmt::format("reads output '{}'{}: the adjoint has only the output's seed, not its "
                           "values; read the input it came from, or store it earlier in the same "
                           "iteration and read it back at the same index",
                           p->name, st ? " after '+=' (its previous contents)" : ""));
        return st->value;
      }
      if (p->inout)
        return inout_value(p, acc->index, e->getBeginLoc(), e);
      ExprP r = read(p->name, acc->index, p->elem, pos(e->getBeginLoc()), pointer_levels(*p));
      std::const_pointer_cast<Expr>(r)->source = text(e); // as written, for remarks
      return r;
    }
    if (const auto* u = dyn_cast<UnaryOperator>(e)) {
      switch (u->getOpcode()) {
      case UO_Minus: {
        ExprP x = expr(u->getSubExpr());
        if (u->getType()->isUnsignedIntegerType())
          check_unsigned_result(unary(Op::Neg, x), u->getOperatorLoc(),
                                fmt::format("unsigned negation '{}'", text(u)), u);
        return unary(Op::Neg, x);
      }
      case UO_Plus:
        return expr(u->getSubExpr());
      case UO_LNot:
        return unary(Op::Not, cond(u->getSubExpr()));
      case UO_Deref: // `*p` of a parameter is an element access (handled above)
      case UO_AddrOf:
        fail(u->getOperatorLoc(), "pointer arithmetic is outside the kernel subset; index "
                                  "parameters directly");
      default:
        fail(u->getOperatorLoc(), "increment/decrement inside an expression is outside the "
                                  "kernel subset");
      }
    }
    if (const auto* b = dyn_cast<BinaryOperator>(e))
      return binary_expr(b);
    if (const auto* c = dyn_cast<ConditionalOperator>(e)) {
      ExprP cc = cond(c->getCond());
      Type t = type_of(c);
      return select(cc, cast(expr(c->getTrueExpr()), t), cast(expr(c->getFalseExpr()), t));
    }
    if (const auto* m = dyn_cast<CXXMemberCallExpr>(e)) {
      const auto* obj = dyn_cast<DeclRefExpr>(m->getImplicitObjectArgument()->IgnoreParenImpCasts());
      auto it = obj ? env_.find(dyn_cast<VarDecl>(obj->getDecl())) : env_.end();
      const CXXMethodDecl* md = m->getMethodDecl();
      if (it != env_.end() && it->second.kind == Binding::ArrayParam &&
          !it->second.param->container.empty() && md && md->getName() == "size" &&
          m->getNumArgs() == 0)
        return scalar_param(it->second.param->name + "_size", Type::Int);
      fail(e->getExprLoc(), "member call is outside the kernel subset (of a std::vector "
                            "parameter, the kernel may call size())");
    }
    if (const auto* c = dyn_cast<CallExpr>(e))
      return call_expr(c);
    fail(e->getExprLoc(), fmt::format("expression '{}' is outside the kernel subset",
                                      e->getStmtClassName()));
  }

  ExprP cast_expr(const CastExpr* c, const clang::Expr* sub) {
    switch (c->getCastKind()) {
    case CK_LValueToRValue:
    case CK_NoOp:
      return expr(sub);
    case CK_IntegralCast: {
      // An explicit cast that widens to 64 bits is kept, so index arithmetic
      // stays as wide in the adjoint as in the kernel; implicit promotions
      // happen again by themselves around it.
      ExprP inner = expr(sub);
      QualType to = c->getType().getCanonicalType(), from = sub->getType().getCanonicalType();
      if (to->isUnsignedIntegerType() && from->isSignedIntegerType())
        check_unsigned_result(inner, c->getExprLoc(),
                              fmt::format("'{}', converted to unsigned '{}',", text(sub),
                                          to.getAsString()),
                              c);
      if (!to->isBooleanType() && ctx_.getTypeSize(to) < 32 &&
          ctx_.getTypeSize(to) < ctx_.getTypeSize(from) && !in_loop_bounds_) {
        auto pv = to_poly(inner);
        if (!pv || !pv->is_constant())
          fail(c->getExprLoc(), fmt::format("conversion of '{}' to '{}' may truncate it; dpgen "
                                            "computes integers in 64 bits: use int or a wider "
                                            "type",
                                            text(sub), to.getAsString()));
      }
      const auto* implicit = dyn_cast<ImplicitCastExpr>(c);
      bool explicit_cast = isa<ExplicitCastExpr>(c) || (implicit && implicit->isPartOfExplicitCast());
      if (!explicit_cast || ctx_.getTypeSize(c->getType()) < 64 ||
          ctx_.getTypeSize(sub->getType()) >= 64 || inner->type != Type::Int)
        return inner;
      auto w = std::make_shared<dpgen::Expr>();
      w->op = Op::Cast;
      w->type = Type::Int;
      w->ops = {inner};
      w->cast_type = spelled(c->getType());
      return w;
    }
    case CK_IntegralToFloating:
    case CK_FloatingCast:
    case CK_FloatingToIntegral:
      return cast(expr(sub), type_of(c));
    case CK_IntegralToBoolean:
    case CK_FloatingToBoolean:
      return cond(sub);
    case CK_BooleanToSignedIntegral:
    case CK_ToVoid:
    default:
      if (c->getType()->isPointerType() || sub->getType()->isPointerType())
        fail(c->getExprLoc(), "pointer arithmetic is outside the kernel subset");
      fail(c->getExprLoc(), fmt::format("conversion '{}' is outside the kernel subset",
                                        c->getCastKindName()));
    }
  }

  ExprP decl_ref(const DeclRefExpr* r) {
    if (const auto* ec = dyn_cast<EnumConstantDecl>(r->getDecl()))
      return int_const(ec->getInitVal().getSExtValue());
    const auto* v = dyn_cast<VarDecl>(r->getDecl());
    if (!v)
      fail(r->getLocation(), fmt::format("'{}' is outside the kernel subset",
                                         r->getDecl()->getNameAsString()));
    if (poisoned_.count(v))
      throw Rejected{}; // its declaration's error is reported already
    auto it = env_.find(v);
    if (it == env_.end()) {
      // A global constant with a known value is a constant.
      if (v->hasGlobalStorage() && v->getType().isConstQualified()) {
        if (const clang::Expr* init = v->getAnyInitializer()) {
          clang::Expr::EvalResult res;
          if (init->EvaluateAsRValue(res, ctx_) && res.Val.isFloat())
            return real_const(res.Val.getFloat().convertToDouble(), type_of(r));
          if (init->EvaluateAsRValue(res, ctx_) && res.Val.isInt())
            return int_const(res.Val.getInt().getSExtValue());
        }
      }
      fail(r->getLocation(), fmt::format("'{}' is global state, outside the kernel subset; "
                                         "pass it as a parameter",
                                         v->getNameAsString()));
    }
    const Binding& b = it->second;
    switch (b.kind) {
    case Binding::ScalarParam:
      return scalar_param(b.param->name, b.param->elem);
    case Binding::ArrayParam:
      fail(r->getLocation(), fmt::format("array '{}' used as a value; only its elements can be "
                                         "read",
                                         b.param->name));
    case Binding::LoopVar:
      return *b.value;
    case Binding::LocalArray:
      fail(r->getLocation(), fmt::format("local array '{}' used as a value; only its elements "
                                         "can be read",
                                         v->getNameAsString()));
    case Binding::Lambda:
      fail(r->getLocation(), fmt::format("lambda '{}' is used other than called; a kernel calls "
                                         "its lambdas, which dpgen inlines",
                                         v->getNameAsString()));
    case Binding::Value:
      if (b.deref_only)
        fail(r->getLocation(), fmt::format("pointer '{}' to a local is used without '*': only "
                                           "'*{}' is in the kernel subset",
                                           v->getNameAsString(), v->getNameAsString()));
      if (!b.value)
        fail(r->getLocation(), unset_message(v, "may be used before it has a value"));
      return *b.value;
    }
    throw std::logic_error("internal error: lower: a binding of no known kind");
  }

  ExprP binary_expr(const BinaryOperator* b) {
    if (b->isAssignmentOp())
      fail(b->getOperatorLoc(), "assignment inside an expression is outside the kernel subset");
    if (b->getOpcode() == BO_Comma)
      fail(b->getOperatorLoc(), "comma operator is outside the kernel subset");
    if (b->getOpcode() == BO_LAnd || b->getOpcode() == BO_LOr)
      return binary(b->getOpcode() == BO_LAnd ? Op::And : Op::Or, cond(b->getLHS()),
                    cond(b->getRHS()));
    ExprP l = expr(b->getLHS()), r = expr(b->getRHS());
    switch (b->getOpcode()) {
    case BO_Add:
      return binary(Op::Add, l, r);
    case BO_Sub:
      if (b->getType()->isUnsignedIntegerType())
        check_unsigned_result(binary(Op::Sub, l, r), b->getOperatorLoc(),
                              fmt::format("unsigned difference '{}'", text(b)), b);
      return binary(Op::Sub, l, r);
    case BO_Mul:
      return binary(Op::Mul, l, r);
    case BO_Div:
      return binary(Op::Div, l, r);
    case BO_Rem:
      return binary(Op::Rem, l, r);
    case BO_LT:
      return binary(Op::Lt, l, r);
    case BO_LE:
      return binary(Op::Le, l, r);
    case BO_GT:
      return binary(Op::Gt, l, r);
    case BO_GE:
      return binary(Op::Ge, l, r);
    case BO_EQ:
      return binary(Op::Eq, l, r);
    case BO_NE:
      return binary(Op::Ne, l, r);
    default:
      fail(b->getOperatorLoc(), fmt::format("operator '{}' is outside the kernel subset",
                                            b->getOpcodeStr().str()));
    }
  }

  ExprP call_expr(const CallExpr* c) {
    const FunctionDecl* f = c->getDirectCallee();
    if (!f)
      fail(c->getBeginLoc(), "indirect call is outside the kernel subset", "dpgen-call");
    if (f->getCanonicalDecl() == fn_->getCanonicalDecl())
      fail(c->getBeginLoc(), fmt::format("recursive call to '{}' is outside the kernel subset",
                                         f->getNameAsString()), "dpgen-call");
    const MathFn* math = find_math_function(f->getNameAsString());
    bool from_library = sm_.isInSystemHeader(sm_.getExpansionLoc(f->getLocation())) ||
                        f->getBuiltinID() != 0;
    if (!from_library && f->hasBody())
      return inline_call(c, f);
    if (!from_library)
      fail(c->getBeginLoc(), fmt::format("call to '{}', whose body dpgen cannot see: helper "
                                         "functions are inlined, so define '{}' in the kernel's "
                                         "file or a header it includes",
                                         f->getQualifiedNameAsString(), f->getNameAsString()), "dpgen-call");
    if (!math)
      fail(c->getBeginLoc(), fmt::format("call to '{}', which dpgen cannot differentiate; the "
                                         "kernel subset calls only {}",
                                         f->getQualifiedNameAsString(), supported_calls()), "dpgen-call");
    Type t = type_of(c);
    std::vector<ExprP> args;
    for (const clang::Expr* a : c->arguments())
      args.push_back(cast(expr(a), t == Type::Int ? type_of(a) : t));
    std::string fnname = math->name;
    if (args.size() != math->arity)
      fail(c->getBeginLoc(), fmt::format("'{}' takes {} argument(s) in the kernel subset",
                                         fnname, math->arity), "dpgen-call");
    return call(fnname, args, t);
  }
};

} // namespace

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
