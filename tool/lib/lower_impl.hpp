// The lowering's internals (lower.hpp is its interface): the Lowerer, which
// holds the state of one kernel's lowering and drives it (lower.cpp: run,
// statements' error recovery, names, types, facts of the path), and the parts
// it is split into along its seams, each a class with its own file(s) that
// reaches the shared state through the Lowerer: statements and stores
// (lower_stmt.hpp), loops and their headers (lower_loop.hpp), expressions
// (lower_expr.hpp), guards of values made under conditions (lower_guard.hpp),
// reductions, line buffers, inlined helpers, integer checks,
// views, objects, the signature and globals. Included by those files only.
#pragma once

#include "lower.hpp"
#include "check.hpp"
#include "ir_walk.hpp"
#include "ops.hpp"

#include "affine.hpp"
#include "lower_buffer.hpp"
#include "lower_common.hpp"
#include "lower_expr.hpp"
#include "lower_globals.hpp"
#include "lower_guard.hpp"
#include "lower_inline.hpp"
#include "lower_int.hpp"
#include "lower_loop.hpp"
#include "lower_object.hpp"
#include "lower_pointer.hpp"
#include "lower_reduce.hpp"
#include "lower_signature.hpp"
#include "lower_stmt.hpp"
#include "lower_view.hpp"
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

#include <cctype>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>

namespace dpgen::lowering {

// Whether evaluating `e` where the kernel would not may fault or be undefined:
// it reads an array, divides integers by a variable, shifts by a variable
// (`1 << (i - 1)` at i = 0) or shifts a variable left (`(i - 1) << 2`: a
// negative value), or converts a real to an integer (out of range: undefined)
// (not looking into its locals).
bool may_fault(const ExprP& e);

// `cond ? value : 0` (`cond && value` for a boolean; `value` where cond is
// null): a value safe to evaluate where `cond` fails.
ExprP when(const ExprP& cond, const ExprP& value);

// Whether no iteration takes both paths (lower.cpp).
bool paths_disjoint(const std::vector<PathCond>& a, const std::vector<PathCond>& b);

using namespace clang;

enum class Escape { None, Always };
class Lowerer {
public:
  Lowerer(ASTContext& ctx, const FunctionDecl* fn) : ctx_(ctx), sm_(ctx.getSourceManager()), fn_(fn) {}

  bool run(Kernel& out);

  // Errors in one statement do not stop the lowering of the next ones, so a
  // run reports every error of a kernel. A variable whose declaration failed
  // is poisoned: its uses are not reported again.
  bool failed_ = false;
  std::set<const ValueDecl*> poisoned_; // parameters, locals, members

  // Lowers `s`; on an error (already reported) marks the kernel failed and
  // goes on, unless inside a helper or an unrolled loop (whose copies would
  // repeat the same error), where the error propagates.
  Escape lower_recovering(const Stmt* s);

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
  void order_after_later_stores(const std::string& array);
  std::map<std::vector<int>, size_t> nest_index_;
  std::map<std::string, ExprP> row_lengths_; // row-pointer array -> its row symbol
  std::map<std::string, ExprP> plane_lengths_; // double*** array -> its plane symbol
  std::map<std::string, ExprP> cube_lengths_;  // rank-4 view -> its cube symbol
  std::map<std::string, ExprP> signed_views_; // unsigned scalar parameter -> its signed copy
  std::map<std::string, ExprP> enum_views_;   // enum parameter -> its integer copy
  // A kernel-level `const std::ptrdiff_t <name>_<suffix> = def;` through which
  // generated code reads parameter `name`: its reference.
  ExprP integer_copy(const std::string& name, const char* suffix, const ExprP& def);
  ExprP scalar_param(const std::string& name, Type t) {
    for (const auto* views : {&signed_views_, &enum_views_})
      if (auto it = views->find(name); it != views->end())
        return it->second;
    return param(name, t);
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
  // dpgen-call (math functions and helpers), dpgen-lambda, dpgen-buffer
  // (line buffers: what each iteration writes and reads), dpgen-pointer (pointer locals), and
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
  SourcePos pos(SourceLocation loc) const;

  std::string text(const Stmt* s) const {
    return Lexer::getSourceText(CharSourceRange::getTokenRange(s->getSourceRange()), sm_,
                                ctx_.getLangOpts())
        .str();
  }

  // ---- types ---------------------------------------------------------------

  // T of a std::vector<T> (any allocator); null for any other type.
  QualType vector_element(QualType q, const char* which = "vector") const;

  // std::array<T, N>: (T, N); nullopt for any other type.
  std::optional<std::pair<QualType, uint64_t>> std_array(QualType q) const;

  // A type as the generated code spells it: canonical, so a typedef of the
  // user's (`FLOAT`, `real_t`) or a library alias (`size_t`) never appears in
  // a generated file that does not declare it.
  static std::string spelled(QualType q, bool keep_const = false) {
    QualType c = q.getCanonicalType();
    if (!keep_const)
      c = c.getUnqualifiedType();
    PrintingPolicy policy{LangOptions()};
    policy.Bool = true; // `bool`, as the generated C++ spells it (not `_Bool`)
    policy.SuppressTagKeyword = true; // `XDir`, not `struct XDir`
    return with_unsigned_suffix(c.getAsString(policy));
  }

  // mdspan's dynamic_extent (size_t(-1)) as clang prints a template argument,
  // 18446744073709551615, warns in every build that includes the generated
  // header ("so large that it is unsigned"): written with its suffix.
  static std::string with_unsigned_suffix(std::string s) {
    const std::string max = "18446744073709551615";
    for (size_t at = s.find(max); at != std::string::npos; at = s.find(max, at + 1)) {
      size_t end = at + max.size();
      if (end == s.size() || (s[end] != 'U' && s[end] != 'u' && !std::isdigit(s[end])))
        s.insert(end, "ULL");
    }
    return s;
  }

  std::optional<Type> scalar_type(QualType q) const;

  Type type_of(const clang::Expr* e);

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
  bool is_reserved(const std::string& name) const;

  // The array parameter whose adjoint or tangent the signature rule names
  // `name` (<array>_adj, <array>_dot), or null.
  const Param* contract_name_of(const std::string& name) const;

  static bool is_cxx_only_keyword(const std::string& name);

  // Every name the generated code takes from the kernel (Kernel::names).
  void collect_names();

  // Hidden work arrays a kernel may have (accumulators, min/max reductions,
  // line buffers): k_.hidden's capacity, so pointers into it stay valid.
  static constexpr size_t kMaxAccumulators = 32;
  bool is_hidden(const std::string& array) const {
    return std::any_of(k_.hidden.begin(), k_.hidden.end(),
                       [&](const Param& h) { return h.name == array; });
  }
  // Scalar accumulators and min/max reductions (lower_reduce.hpp).
  friend class Reductions;
  Reductions red_{*this};

  // Line buffers and pointers to arrays (lower_buffer.hpp); pointer locals (lower_pointer.hpp).
  friend class LineBuffers;
  LineBuffers bufs_{*this};
  friend class PointerLocals;
  PointerLocals ptrs_{*this};

  // The number of the next store lowered (Store::seq: the order of the
  // kernel's stores, which the checks compare).
  int next_store_seq_ = 0;

  // How many small constant loops being unrolled enclose the current
  // statement (ForLoops): their counters are constants in each copy.
  int unrolling_ = 0;

  // How many if/else arms enclose the current statement (Statements::branch):
  // an escape (`return`, `continue`) inside one reaches what follows the
  // outermost if as a condition, which that if makes a kernel guard.
  int open_arms_ = 0;

  // The reads of work arrays and in-place arrays (DPGEN_INOUT) and the stores
  // to in-place arrays, which the checks need besides the IR (check.hpp).
  Accesses acc_;

  // Unless set, a read of a work array outside every loop is recorded for
  // the checks (Accesses::kernel_level_work_reads).
  bool path_reads_ok_ = false;

  // `e >= 0` wherever this statement runs: its loops run, the counters are
  // in range, the conditions on its path hold, unsigned sizes are >= 0.
  bool provably_nonneg(const ExprP& e, const std::vector<PathCond>& more = {}) const;

  // Lowering a loop's bounds (exempt from IntegerChecks: where the kernel's
  // unsigned arithmetic and ours differ, its loop runs ~2^64 times).
  bool in_loop_bounds_ = false;
  // Integer results checked against wrapping and truncation (lower_int.hpp).
  friend class IntegerChecks;
  IntegerChecks ints_{*this};

  // Facts about the parameters on the current path.
  Facts facts_of_path() const {
    Facts f;
    for (const auto& pc : path_)
      add_facts(pc, f);
    return f;
  }

  // ---- helper functions and lambdas (lower_inline.hpp) ------------------------

  // A user function called from a kernel (a limiter, a flux, minmod) is
  // differentiated by inlining: its parameters are bound to the arguments'
  // values (arrays to the kernel's arrays), its body is lowered like the
  // kernel's, and its returns become one value, selected by the conditions
  // under which each return is reached; so do the caller's variables it
  // assigns (`exits`: the bindings at each return inside a branch).
  struct InlineFrame {
    const FunctionDecl* fn;
    size_t path_depth;
    size_t loop_depth;
    Type ret;
    std::vector<std::pair<std::vector<PathCond>, ExprP>> returns;
    bool is_void = false; // results through out-parameters, or stores
    int unrolling = 0;    // Lowerer::unrolling_ at the call
    FrameExits exits = {};
  };
  std::vector<InlineFrame> frames_;
  // Operands C++ evaluates only under a condition (`?:` arms, `&&`'s right
  // side), being lowered: the frame depth at each start, and where it is.
  std::vector<std::pair<size_t, SourceLocation>> cond_operands_;
  // The inlining of helpers and lambdas (lower_inline.hpp).
  friend class Inliner;
  Inliner inl_{*this};

  // `flux(a, b)` / `this->flux(a, b)` inside a member kernel or a functor's
  // call operator: a call of a method on the same object.
  bool this_call(const CallExpr* c) const {
    const auto* m = dyn_cast<CXXMemberCallExpr>(c);
    return m && (self_class_ || !fields_.empty()) &&
           isa<CXXThisExpr>(m->getImplicitObjectArgument()->IgnoreParenImpCasts());
  }

  // ---- member kernels (lower_signature.cpp, lower_expr.cpp) -------------------

  // The class of a member kernel (null for a free one), and its members'
  // bindings (Param::member), as env_ binds variables.
  const CXXRecordDecl* self_class_ = nullptr;
  std::map<const FieldDecl*, Binding> fields_;
  // What `e` names: a variable (env_) or a member of the kernel's object
  // (`u_`, `this->u_`: fields_); null for anything else. Throws Rejected for
  // a poisoned one (its error is reported already).
  const Binding* bound(const clang::Expr* e) const;

  // ---- the signature (lower_signature.hpp) ----------------------------------
  friend class Signature;
  friend class Globals;
  Signature sig_{*this};

  // ---- array views and objects (lower_view.hpp, lower_object.hpp) ----------
  friend class Views;
  friend class Objects;
  Views views_{*this};
  Objects objects_{*this};
  // Loops of an inlined helper or lambda (a library parallel-for's): their
  // iterations run in parallel under the library's semantics.
  std::set<const Loop*> library_loops_;
  // Statements of the kernel itself, or of the body of a parallel-for (a
  // lambda's or functor's call operator): where a local may accumulate.
  bool in_loop_body_frame() const {
    if (frames_.empty())
      return true;
    const auto* m = dyn_cast<CXXMethodDecl>(frames_.back().fn);
    return m && (m->getParent()->isLambda() || objects_.is_functor_class(m->getParent())) &&
           m->getReturnType()->isVoidType();
  }
  // A kernel-level symbol the index algebra cannot see into (its value only
  // ever compared in generated code).
  ExprP opaque_symbol(const std::string& name, long long value);

  // The parameter `e` names if it is a scalar by reference (Param::scalar_ref).
  const Param* scalar_ref_param(const clang::Expr* e) const;
  std::map<std::string, const VarDecl*> global_decls_;

  // ---- the parts along the seams (lower_stmt.hpp, lower_loop.hpp,
  // lower_expr.hpp, lower_guard.hpp) ------------------------------------------
  friend class Statements;
  friend class Stores;
  friend class LoopHeaders;
  friend class ForLoops;
  friend class RunningIndices;
  friend class Expressions;
  friend class Guards;
  Statements stmts_{*this};
  Stores stores_{*this};
  LoopHeaders headers_{*this};
  ForLoops for_loops_{*this};
  Expressions exprs_{*this};
  Guards guards_{*this};
};

} // namespace dpgen::lowering
