// Lowering, line buffers: local arrays of more than 64 elements and VLAs
// (`double u1[M]`, `double tmp[nx]`) indexed by loop counters, and pointers
// to arrays made by a cast of an array parameter (C99 `double (*u)[n][n] =
// (double (*)[n][n]) u_flat;`). See lower_impl.hpp ("line buffers").
//
// A buffer is a hidden work array (Kernel::hidden) with one row of the
// buffer's length per iteration of the loops around all its uses: the
// element `tmp[e]` is `H[row * L + e]`, the row the mixed-radix number of
// those loops' iterations. Within a row every element is written once
// (with '='), in bounds, before any read of it in the same iteration of
// the row loops; a read of an element no earlier loop of that iteration
// wrote is an error (or, where only the sizes decide, a run-time check).
#include "lower_impl.hpp"
#include "lower_while.hpp"
#include "print.hpp"

namespace dpgen::lowering {

namespace {

// The counter a `for` statement declares or assigns (`int i = lo`, `i = lo`).
const VarDecl* counter_of(const ForStmt* f) {
  if (const auto* ds = dyn_cast_or_null<DeclStmt>(f->getInit()); ds && ds->isSingleDecl())
    return dyn_cast<VarDecl>(ds->getSingleDecl());
  const auto* e = dyn_cast_or_null<clang::Expr>(f->getInit());
  const auto* a = e ? dyn_cast<BinaryOperator>(e->IgnoreParens()) : nullptr;
  if (!a || a->getOpcode() != BO_Assign)
    return nullptr;
  const auto* r = dyn_cast<DeclRefExpr>(a->getLHS()->IgnoreParenImpCasts());
  return r ? dyn_cast<VarDecl>(r->getDecl()) : nullptr;
}

void collect_uses(const Stmt* s, const VarDecl* v, std::vector<const Stmt*>& out) {
  if (!s)
    return;
  if (const auto* r = dyn_cast<DeclRefExpr>(s); r && r->getDecl() == v)
    out.push_back(s);
  for (const Stmt* c : s->children())
    collect_uses(c, v, out);
}

// The name of the LoopVar in a counter's value (`i`, or `lo + 2 * i_step`).
std::string loop_var_in(const ExprP& e) {
  std::string name;
  any_node(e, [&](const ExprP& x) {
    if (x->op == Op::LoopVar && name.empty())
      name = x->name;
    return false;
  });
  return name;
}

// `std::vector<T> v(count)` or `(count, value)` (the allocator defaulted): count, as written
// (its conversion to size_type aside); null for any other way of making it.
const clang::Expr* vector_count(const VarDecl* v) {
  const auto* ctor =
      dyn_cast_or_null<CXXConstructExpr>(v->getInit() ? v->getInit()->IgnoreImplicit() : nullptr);
  if (!ctor || ctor->isListInitialization())
    return nullptr;
  unsigned given = ctor->getNumArgs();
  while (given > 0 && isa<CXXDefaultArgExpr>(ctor->getArg(given - 1)))
    --given;
  if (given < 1 || given > 2 || !ctor->getArg(0)->getType()->isIntegerType() ||
      (given == 2 && !ctor->getArg(1)->getType()->isRealFloatingType()))
    return nullptr;
  return ctor->getArg(0)->IgnoreImpCasts();
}

// The statement above `s`; for an expression in a declaration's initializer
// (`const double a = v[i];`), its DeclStmt. Null at the top.
const Stmt* parent_stmt(ASTContext& ctx, const Stmt* s, bool* in_declaration = nullptr) {
  auto pp = ctx.getParents(*s);
  if (pp.empty())
    return nullptr;
  if (const Stmt* up = pp[0].get<Stmt>())
    return up;
  const Decl* d = pp[0].get<Decl>();
  if (!d)
    return nullptr;
  if (in_declaration)
    *in_declaration = true;
  auto dp = ctx.getParents(*d);
  return dp.empty() ? nullptr : dp[0].get<Stmt>();
}

// The statement that holds the declaration of `v` (a compound statement, a loop's body).
const Stmt* declaration_scope(ASTContext& ctx, const VarDecl* v) {
  auto ps = ctx.getParents(*v);
  const Stmt* ds = ps.empty() ? nullptr : ps[0].get<Stmt>();
  return ds ? parent_stmt(ctx, ds) : nullptr;
}

// Whether use `u` of a buffer is the array of an element access (`v[i]`, `t[i]`) or asks
// for the length (`v.size()`).
bool element_use(ASTContext& ctx, const Stmt* u) {
  for (const Stmt* s = u;;) {
    auto pp = ctx.getParents(*s);
    const Stmt* p = pp.empty() ? nullptr : pp[0].get<Stmt>();
    if (p && (isa<ImplicitCastExpr>(p) || isa<ParenExpr>(p))) {
      s = p;
      continue;
    }
    if (const auto* o = dyn_cast_or_null<CXXOperatorCallExpr>(p))
      return o->getOperator() == OO_Subscript && o->getArg(0)->IgnoreParenImpCasts() == u;
    if (const auto* a = dyn_cast_or_null<ArraySubscriptExpr>(p))
      return a->getBase()->IgnoreParenImpCasts() == u;
    if (const auto* m = dyn_cast_or_null<MemberExpr>(p))
      return m->getMemberNameInfo().getAsString() == "size";
    return false;
  }
}

// The loops around every use of `v`: the `for` statements (and `while` loops that count)
// above the innermost statement that holds all the uses, below the declaration's scope,
// outermost first. `stray`: a use outside that scope's statements, or in a declaration other
// than by an element (`double* p = v.data();`), else null.
std::vector<const VarDecl*> row_loops(ASTContext& ctx, const VarDecl* v, const Stmt*& stray) {
  const Stmt* scope = declaration_scope(ctx, v);
  std::vector<const Stmt*> uses;
  collect_uses(scope, v, uses);
  std::vector<std::vector<const Stmt*>> chains; // scope ... use, for each use
  for (const Stmt* u : uses) {
    std::vector<const Stmt*> chain;
    const Stmt* s = u;
    bool in_declaration = false; // (`const double a = v[i];`: on through its DeclStmt)
    while (s && s != scope) {
      chain.push_back(s);
      s = parent_stmt(ctx, s, &in_declaration);
    }
    if ((s != scope || (in_declaration && !element_use(ctx, u))) && !stray)
      stray = u;
    std::reverse(chain.begin(), chain.end());
    chains.push_back(chain);
  }
  std::vector<const VarDecl*> counters;
  if (chains.empty())
    return counters;
  size_t common = chains[0].size();
  for (const auto& c : chains) {
    size_t n = 0;
    while (n < common && n < c.size() && c[n] == chains[0][n])
      ++n;
    common = n;
  }
  for (size_t i = 0; i < common; ++i)
    if (const auto* f = dyn_cast<ForStmt>(chains[0][i]))
      counters.push_back(counter_of(f));
    else if (const auto* w = dyn_cast<WhileStmt>(chains[0][i]))
      counters.push_back(while_counter(w)); // (lowered as a for loop: lower_while.cpp)
  return counters;
}

// `p` as an expression, its loop counters too (`headers` turns the sizes' symbols).
ExprP index_expr(const Poly& p, LoopHeaders& headers) {
  ExprP sum;
  for (const auto& [m, coef] : p.terms()) {
    ExprP term = int_const(coef);
    for (const auto& sym : m)
      term =
          binary(Op::Mul, term, sym.is_counter() ? loop_var(sym.name) : headers.symbol_expr(sym));
    sum = sum ? binary(Op::Add, sum, term) : term;
  }
  return sum ? sum : int_const(0);
}

// Whether `s` writes an element of `v` (`v[i] = ...`, `v[i] += ...`, `++v[i]`).
bool writes_element(const Stmt* s, const VarDecl* v) {
  if (!s)
    return false;
  const clang::Expr* target = nullptr;
  if (const auto* b = dyn_cast<BinaryOperator>(s); b && b->isAssignmentOp())
    target = b->getLHS();
  else if (const auto* u = dyn_cast<UnaryOperator>(s); u && u->isIncrementDecrementOp())
    target = u->getSubExpr();
  else if (const auto* o = dyn_cast<CXXOperatorCallExpr>(s); o && o->isAssignmentOp())
    target = o->getArg(0);
  if (target) {
    const clang::Expr* base = target->IgnoreParenImpCasts();
    if (const auto* o = dyn_cast<CXXOperatorCallExpr>(base); o && o->getOperator() == OO_Subscript)
      base = o->getArg(0)->IgnoreParenImpCasts();
    else if (const auto* a = dyn_cast<ArraySubscriptExpr>(base))
      base = a->getBase()->IgnoreParenImpCasts();
    if (const auto* r = dyn_cast<DeclRefExpr>(base); r && r->getDecl() == v)
      return true;
  }
  for (const Stmt* c : s->children())
    if (writes_element(c, v))
      return true;
  return false;
}

// A loop around `e`, below the declaration of `v`, that also writes an element of `v`; null
// if none. (A read there may see what an earlier iteration stored: not the vector's value.)
const Stmt* loop_writing_around(ASTContext& ctx, const clang::Expr* e, const VarDecl* v) {
  const Stmt* scope = declaration_scope(ctx, v);
  for (const Stmt* s = e; s && s != scope; s = parent_stmt(ctx, s))
    if ((isa<ForStmt>(s) || isa<WhileStmt>(s) || isa<DoStmt>(s) || isa<CXXForRangeStmt>(s)) &&
        writes_element(s, v))
      return s;
  return nullptr;
}

// The value of `std::vector<T> v(count, value)`; null for `v(count)` (zero).
const clang::Expr* vector_fill(const VarDecl* v) {
  const auto* ctor = llvm::cast<CXXConstructExpr>(v->getInit()->IgnoreImplicit());
  return ctor->getNumArgs() > 1 && !isa<CXXDefaultArgExpr>(ctor->getArg(1)) ? ctor->getArg(1)
                                                                            : nullptr;
}

// A read of a line buffer that no earlier loop of its row is known to have written:
// `written` the intervals they write ("a to b (line l)"), `reads` the elements read.
std::string unwritten_read(const std::string& name, const std::string& read,
                           const std::string& rows, const std::vector<std::string>& written,
                           unsigned conditional, const std::string& reads,
                           const std::string& hint) {
  if (written.empty())
    return fmt::format("line buffer '{}' is read at '{}', and no earlier loop of {} writes "
                       "it{}: a buffer holds values within one iteration of the loops around "
                       "all its uses, so this would read an element never written in this "
                       "iteration (a value carried over from an earlier one, or "
                       "uninitialised), outside the kernel subset; write every element a "
                       "loop reads, with '=', in an earlier loop of the same iteration{}",
                       name, read, rows,
                       conditional ? fmt::format(" wherever this read runs (line {} writes it "
                                                 "under a condition that may not hold here)",
                                                 conditional)
                                   : "",
                       hint);
  return fmt::format("line buffer '{}' is read at '{}'{}, and dpgen cannot prove that the "
                     "earlier loops of {} wrote every element read (they write elements {}): "
                     "a read of an element not written in this iteration (a value carried "
                     "over from an earlier one, or uninitialised) is outside the kernel "
                     "subset; read only elements the filling loop writes{}",
                     name, read, reads, rows, fmt::join(written, ", "), hint);
}

std::string vector_form(const std::string& name) {
  return fmt::format("local std::vector '{}' is in the kernel subset as a line buffer made with "
                     "its length (`std::vector<double> {}(n + 1);` or `(n + 1, 0.0)`), filled "
                     "and read by the kernel's loops; not made from a list, a copy or another "
                     "vector (a table of constants is an array: `const double {}[3] = {{...}};`)",
                     name, name, name);
}

// For a buffer that is a std::vector: when the value it is made with counts.
std::string vector_read_hint(const VarDecl* v) {
  const auto* spec = dyn_cast_or_null<ClassTemplateSpecializationDecl>(
      v->getType().getCanonicalType()->getAsCXXRecordDecl());
  if (!spec || spec->getName() != "vector" || !spec->isInStdNamespace())
    return "";
  return fmt::format(" (the value a std::vector is made with is read where no store wrote only "
                     "when the vector is made inside the loops around all its uses, every loop "
                     "that writes it before the read fills a known range unconditionally and no "
                     "loop around the read writes it; else assign the elements the loops leave "
                     "out, `{}[0] = 0.0;`)",
                     v->getNameAsString());
}

} // namespace

const LineBuffers::Buffer* LineBuffers::buffer_of(const std::string& array) const {
  auto it = buffers_.find(array);
  return it == buffers_.end() ? nullptr : &it->second;
}

// `double u1[M]` (M > 64), `double tmp[nx]`, `std::array<double, 200> t`.
void LineBuffers::declare_buffer(const VarDecl* v, QualType elem, ExprP length, bool sized) {
  const std::string name = v->getNameAsString();
  auto t = L.scalar_type(elem);
  if (!t || !is_real(*t) || L.ctx_.getAsArrayType(elem))
    L.fail(v->getLocation(), fmt::format("local array '{}' of type '{}' is outside the kernel "
                                         "subset: a line buffer (a local array of more than 64 "
                                         "elements, or of a run-time length) holds float or "
                                         "double values, one dimension",
                                         name, v->getType().getAsString()));
  if (const clang::Expr* init = sized ? nullptr : v->getInit()) {
    const auto* ctor = dyn_cast<CXXConstructExpr>(init);
    if (!ctor || ctor->getNumArgs() != 0 || ctor->requiresZeroInitialization())
      L.fail(init->getBeginLoc(),
             fmt::format("line buffer '{}' has an initializer: a buffer of more than 64 elements "
                         "(or of a run-time length) is filled by the kernel's loops, each element "
                         "written before it is read in the same iteration; initialise it in a loop",
                         name));
  }
  auto len = to_poly(length);
  if (!len || len->mentions_any_counter())
    L.fail(v->getLocation(), fmt::format("the length of line buffer '{}' must be a polynomial in "
                                         "the integer parameters (not in loop counters)",
                                         name));
  if (L.k_.hidden.size() == L.k_.hidden.capacity())
    L.fail(v->getLocation(), fmt::format("line buffer '{}': a kernel has at most {} buffers and "
                                         "accumulators",
                                         name, Lowerer::kMaxAccumulators));
  Param h;
  h.name = "dpgen_buf_" + name;
  for (int n = 2; L.k_.find_param(h.name); ++n)
    h.name = fmt::format("dpgen_buf_{}_{}", name, n);
  h.kind = ParamKind::Out;
  h.elem = *t;
  h.elem_name = type_spelling(h.elem);
  h.spelling = name;
  h.declaration = fmt::format("{}* {}", h.elem_name, h.name);
  L.k_.hidden.push_back(h);

  Buffer b;
  b.decl = v;
  b.array = h.name;
  b.length = length;
  b.decl_loop_ids = L.loop_ids_;
  const Stmt* stray = nullptr;
  b.row_counters = row_loops(L.ctx_, v, stray);
  if (stray) // (a use in a declaration: `double* p = flux.data();`)
    L.fail(stray->getBeginLoc(), fmt::format("line buffer '{}' is used here other than by its "
                                             "elements ('{}[i]'): a pointer into it, or a call "
                                             "that takes it, is outside the kernel subset",
                                             name, name));
  buffers_[h.name] = b;
  Binding bind;
  bind.kind = Binding::ArrayParam;
  bind.param = &L.k_.hidden.back();
  L.env_[v] = bind;
}

// The flat element of `local` (the index as the kernel writes it) of buffer
// `p`: row * length + local, the row of the current iteration.
ExprP LineBuffers::buffer_index(const Param* p, const ExprP& local, const clang::Expr* at) {
  Buffer& b = buffers_.at(p->name);
  const std::string& name = b.decl->getNameAsString();
  SourceLocation loc = at->getBeginLoc();
  if (!to_poly(local))
    L.fail(loc,
           fmt::format("line buffer '{}' is indexed at '{}', which is not a polynomial in the "
                       "loop counters and sizes (a data-dependent or conditional index): dpgen "
                       "follows which elements of a buffer each loop writes and reads; index "
                       "it by loop counters",
                       name, L.text(at)),
           "dpgen-buffer");
  const size_t decl_depth = b.decl_loop_ids.size();
  if (L.loop_ids_.size() < decl_depth ||
      !std::equal(b.decl_loop_ids.begin(), b.decl_loop_ids.end(), L.loop_ids_.begin()))
    L.fail(loc, fmt::format("line buffer '{}' is used outside the loops it is declared in", name));
  // Each loop around all the uses is a loop of the kernel here, in order.
  for (size_t k = 0; k < b.row_counters.size(); ++k) {
    const VarDecl* c = b.row_counters[k];
    auto it = c ? L.env_.find(c) : L.env_.end();
    if (it != L.env_.end() && it->second.kind == Binding::Value)
      L.fail(loc, fmt::format("line buffer '{}' is used in every iteration of loop '{}', which "
                              "dpgen unrolls (constant bounds, at most 16 iterations): its "
                              "copies would share one row of the buffer; declare the buffer "
                              "inside that loop",
                              name, c->getNameAsString()));
    std::string var = it != L.env_.end() && it->second.kind == Binding::LoopVar && it->second.value
                          ? loop_var_in(*it->second.value)
                          : "";
    size_t d = decl_depth + k;
    if (var.empty() || d >= L.loops_.size() || L.loops_[d]->var != var)
      L.fail(loc, fmt::format("line buffer '{}': dpgen cannot place this use in the loops around "
                              "its uses (a buffer is used in one function, inside the loops of "
                              "its declaration)",
                              name));
  }
  const size_t depth = decl_depth + b.row_counters.size();
  std::vector<int> ids(L.loop_ids_.begin(), L.loop_ids_.begin() + depth);
  if (!b.placed) {
    // One row per iteration of the row loops: (outer - lo) * extent of the
    // inner ones + ..., as for an accumulator's sums.
    ExprP row = int_const(0);
    std::vector<ExprP> extents;
    for (size_t d = 0; d < depth; ++d) {
      const Loop& l = *L.loops_[d];
      if (!to_poly(l.lo) || !to_poly(l.hi))
        L.fail(loc, fmt::format("line buffer '{}' is used in loop '{}', whose bounds are not "
                                "polynomials in the sizes",
                                name, l.var));
      ExprP here = binary(Op::Sub, loop_var(l.var), l.lo);
      extents.push_back(binary(Op::Sub, l.hi, l.lo));
      row =
          d == 0 ? here : binary(Op::Add, binary(Op::Mul, row, binary(Op::Sub, l.hi, l.lo)), here);
    }
    b.placed = true;
    b.depth = depth;
    b.row_ids = ids;
    b.row = row;
    L.acc_.buffers[p->name] = {name, depth, row, b.length, extents};
  } else if (ids != b.row_ids) {
    L.fail(loc, fmt::format("internal error: line buffer '{}' is used in different loops", name));
  }
  if (depth == 0)
    return local;
  return binary(Op::Add, binary(Op::Mul, b.row, b.length), local);
}

// The index as the kernel wrote it, from the flat element of a buffer.
std::optional<Poly> LineBuffers::buffer_local(const Buffer& b, const ExprP& flat) const {
  auto p = to_poly(flat);
  if (!p)
    return std::nullopt;
  if (b.depth == 0)
    return p;
  return *p - *to_poly(b.row) * *to_poly(b.length);
}

// Facts where the current statement runs: its loops run, their counters are
// in range, its path holds (counters included).
Facts LineBuffers::facts_here() const {
  Facts f;
  for (const auto& l : L.loops_) {
    add_nonempty(*l, f);
    add_counter_range(*l, f);
  }
  for (const auto& pc : L.path_)
    add_facts_with_counters(pc, f);
  return f;
}

// A condition a store is under holds wherever the current statement runs:
// it is on the current path, the facts here imply it, or it says two
// integers differ (`pad[0]` and `pad[nx + 1]` are apart) and they provably
// do here.
bool LineBuffers::holds_here(const PathCond& pc, const Facts& facts) const {
  if (std::any_of(L.path_.begin(), L.path_.end(), [&](const PathCond& q) {
        return q.cond == pc.cond && q.positive == pc.positive;
      }))
    return true;
  if (implied(pc, facts))
    return true;
  bool differ = (pc.cond->op == Op::Eq && !pc.positive) || (pc.cond->op == Op::Ne && pc.positive);
  if (!differ)
    return false;
  auto a = to_poly(pc.cond->ops[0]), b = to_poly(pc.cond->ops[1]);
  if (!a || !b)
    return false;
  Poly d = *a - *b;
  return prove_nonneg(d - Poly::constant(1), facts) || prove_nonneg(-d - Poly::constant(1), facts);
}

// [min, max] of `p` over the counters of loops `loops[from...]`, each
// coefficient's sign proved from `facts`; nullopt where one is unknown.
static std::optional<std::pair<Poly, Poly>> range_over(Poly p, const std::vector<Loop>& loops,
                                                       size_t from, const Facts& facts) {
  Poly lo, hi;
  for (size_t d = from; d < loops.size(); ++d) {
    const Loop& l = loops[d];
    Poly c = p.coefficient(Sym::counter(l.var));
    if (c.mentions_any_counter())
      return std::nullopt;
    p = p.without(Sym::counter(l.var));
    if (c == Poly())
      continue;
    bool up = prove_nonneg(c, facts);
    if (!up && !prove_nonneg(-c, facts))
      return std::nullopt;
    Poly first = *to_poly(l.lo), last = *to_poly(l.hi) - Poly::constant(1);
    lo = lo + c * (up ? first : last);
    hi = hi + c * (up ? last : first);
  }
  return std::pair{lo + p, hi + p};
}

// The C++ conditions under which a check on this statement applies: its
// loops run and the conditions on its path that the sizes decide hold.
std::vector<SizeCond> LineBuffers::premises_here() const {
  std::vector<SizeCond> out;
  for (const auto& l : L.loops_)
    out.push_back(SizeCond::runs(*to_poly(l->lo), *to_poly(l->hi)));
  for (const auto& pc : L.path_) {
    Facts f;
    add_facts(pc, f);
    for (const auto& p : f)
      out.push_back(SizeCond::nonneg(p));
  }
  return sorted_conds(std::move(out));
}

// `goals` (each >= 0) hold here: proved, or (where they depend on the sizes
// alone and can hold) checked at run time. Otherwise an error `why` (with
// "provably" or "cannot prove" filled in by `never`).
bool LineBuffers::prove_or_check(const std::vector<Poly>& goals, const Facts& facts,
                                 const std::string& what, SourceLocation loc, bool& never) {
  never = false;
  std::vector<std::vector<SizeCond>> must;
  for (const Poly& g : goals) {
    if (prove_nonneg(g, facts))
      continue;
    if (prove_nonneg(-g - Poly::constant(1), facts)) {
      never = true;
      return false;
    }
    if (g.mentions_any_counter())
      return false;
    must.push_back({SizeCond::nonneg(g)});
  }
  if (!must.empty()) {
    SizeCheck c;
    c.premises = premises_here();
    c.must_hold = must;
    c.what = what;
    c.pos = L.pos(loc);
    L.k_.size_checks.push_back(c);
  }
  return true;
}

// A store to a buffer: with '=', it moves with every loop inside the row
// loops (else it would carry a value from one iteration to the next), and
// stays inside the buffer.
void LineBuffers::check_buffer_store(const Param* p, const ExprP& flat, bool accumulate,
                                     const clang::Expr* lhs) {
  const Buffer& b = buffers_.at(p->name);
  const std::string name = b.decl->getNameAsString();
  SourceLocation loc = lhs->getBeginLoc();
  Poly local = *buffer_local(b, flat);
  if (!accumulate)
    for (size_t d = b.depth; d < L.loops_.size(); ++d)
      if (!local.mentions_counter(L.loops_[d]->var))
        L.fail(loc, fmt::format("line buffer '{}' is written at the same element '{}' by every "
                              "iteration of loop '{}': its value would carry from one iteration "
                              "to the next (a recurrence through a buffer), outside the kernel "
                              "subset; a buffer holds one value per element {}, written before "
                              "it is read",
                              name, L.text(lhs), L.loops_[d]->var, b.depth == 0 ? std::string(
                                  "for the whole kernel where it is used outside every loop") : [&] {
                                std::vector<std::string> v;
                                for (size_t i = 0; i < b.depth; ++i)
                                  v.push_back("'" + L.loops_[i]->var + "'");
                                return fmt::format("in each iteration of the loops around all "
                                                   "its uses ({})",
                                                   fmt::join(v, ", "));
                              }()),
             "dpgen-buffer");
  Facts facts = facts_here();
  std::vector<Loop> loops;
  for (const auto& l : L.loops_)
    loops.push_back(*l);
  Poly len = *to_poly(b.length);
  const Poly one = Poly::constant(1);
  facts.push_back(len - one); // a VLA has at least one element (C11 6.7.6.2)
  // Per element (counters in range): 0 <= local <= length - 1.
  if (prove_nonneg(local, facts) && prove_nonneg(len - one - local, facts))
    return;
  auto r = range_over(local, loops, 0, facts); // (over every loop: a bound for all rows)
  bool never = false;
  if (r &&
      prove_or_check({r->first, len - one - r->second}, facts,
                     fmt::format("line buffer '{}' of {} elements holds the elements "
                                 "written at '{}' (from {} to {})",
                                 name, len.str(), L.text(lhs), r->first.str(), r->second.str()),
                     loc, never))
    return;
  L.fail(loc,
         fmt::format("line buffer '{}' of {} elements is written at '{}'{}, which dpgen "
                     "{} within the buffer",
                     name, len.str(), L.text(lhs),
                     r ? fmt::format(" (elements {} to {})", r->first.str(), r->second.str()) : "",
                     never ? "finds is not always" : "cannot prove is"),
         "dpgen-buffer");
}

// 0 <= local <= length - 1 for a read at `e` (proved, or checked at run time).
bool LineBuffers::read_inside(const Buffer& b, const Poly& local, Facts facts,
                              const clang::Expr* e) {
  const Poly len = *to_poly(b.length), one = Poly::constant(1);
  facts.push_back(len - one);
  if (prove_nonneg(local, facts) && prove_nonneg(len - one - local, facts))
    return true;
  std::vector<Loop> loops;
  for (const auto& l : L.loops_)
    loops.push_back(*l);
  auto r = range_over(local, loops, 0, facts);
  bool never = false;
  return r && prove_or_check({r->first, len - one - r->second}, facts,
                             fmt::format("line buffer '{}' of {} elements holds the elements read "
                                         "at '{}' (from {} to {})",
                                         b.decl->getNameAsString(), len.str(), L.text(e),
                                         r->first.str(), r->second.str()),
                             e->getBeginLoc(), never);
}

// A read of a buffer element that this iteration did not store just before (visible_store):
// an earlier loop of the same iteration of the row loops, sharing no other loop with the read,
// wrote it with '='; or a std::vector's value where none wrote (BufferRead, lower_buffer.hpp).
LineBuffers::BufferRead LineBuffers::check_buffer_read(const Param* p, const ExprP& flat,
                                                       const clang::Expr* e) {
  const Buffer& b = buffers_.at(p->name);
  const std::string name = b.decl->getNameAsString();
  SourceLocation loc = e->getBeginLoc();
  auto nit = L.nest_index_.find(L.cur_key());
  if (nit != L.nest_index_.end() && L.stores_.visible_store(L.k_.nests[nit->second], p->name, flat))
    return {}; // stored earlier in this iteration, at this element
  Poly local = *buffer_local(b, flat);
  std::string rows = "the kernel";
  if (b.depth > 0) {
    std::vector<std::string> v;
    for (size_t i = 0; i < b.depth; ++i)
      v.push_back("'" + L.loops_[i]->var + "'");
    rows = fmt::format("an iteration of loop{} {}", b.depth > 1 ? "s" : "", fmt::join(v, ", "));
  }
  // The intervals earlier loops of this iteration wrote.
  struct Written {
    Poly lo, hi;
    unsigned line;
  };
  std::vector<Written> written;
  unsigned conditional = 0; // a store left out: its condition may not hold here
  bool unknown = false;     // a store of the row whose elements are not an interval here
  std::vector<int> key = L.cur_key();
  Facts facts = facts_here();
  facts.push_back(*to_poly(b.length) - Poly::constant(1)); // (a VLA has an element at least)
  for (const auto& n : L.k_.nests) {
    size_t shared = 0;
    while (shared < n.key.size() && shared < key.size() && n.key[shared] == key[shared])
      ++shared;
    const bool other = shared != b.depth; // another iteration of a loop the read is in
    for (const auto& st : n.stores) {
      if (st.array != p->name)
        continue;
      unknown = unknown || (other && n.key != key) || st.accumulate;
      if (other || st.accumulate)
        continue;
      bool holds = std::all_of(st.path.begin(), st.path.end(),
                               [&](const PathCond& pc) { return holds_here(pc, facts); });
      if (!holds) {
        conditional = st.pos.line; // under a condition that may not hold here
        continue;
      }
      auto w = buffer_local(b, st.index);
      unknown = unknown || !w;
      if (!w)
        continue;
      std::vector<const Loop*> inner;
      for (size_t d = b.depth; d < n.loops.size(); ++d)
        inner.push_back(&n.loops[d]);
      if (inner.empty()) {
        written.push_back({*w, *w, st.pos.line});
        continue;
      }
      Poly c = inner.size() == 1 ? w->coefficient(Sym::counter(inner[0]->var)) : Poly();
      if (!(c == Poly::constant(1)) && !(c == Poly::constant(-1))) {
        unknown = true;
        continue; // (contiguous fills only: one loop, step 1)
      }
      Poly rest = w->without(Sym::counter(inner[0]->var));
      Poly first = rest + c * *to_poly(inner[0]->lo);
      Poly last = rest + c * (*to_poly(inner[0]->hi) - Poly::constant(1));
      if (c == Poly::constant(1))
        written.push_back({first, last, st.pos.line});
      else
        written.push_back({last, first, st.pos.line});
    }
  }
  const Poly one = Poly::constant(1);
  // Intervals that meet or overlap, joined: [a1, b1] and [a2, b2] with
  // a2 <= b1 + 1 cover [a1, b2] (an element past b1 is at least a2), even
  // where one of them is empty.
  std::vector<Written> joined = written;
  for (size_t round = 0; round < written.size() && joined.size() < 32; ++round) {
    bool grew = false;
    for (size_t x = 0; x < joined.size() && joined.size() < 32; ++x)
      for (size_t y = 0; y < joined.size() && joined.size() < 32; ++y) {
        if (x == y || !prove_nonneg(joined[x].hi + one - joined[y].lo, facts))
          continue;
        Written m{joined[x].lo, joined[y].hi, joined[x].line};
        if (std::none_of(joined.begin(), joined.end(),
                         [&](const Written& w) { return w.lo == m.lo && w.hi == m.hi; })) {
          joined.push_back(m);
          grew = true;
        }
      }
    if (!grew)
      break;
  }
  // Per element (the counters in range): inside one of the intervals.
  for (const auto& w : joined)
    if (prove_nonneg(local - w.lo, facts) && prove_nonneg(w.hi - local, facts))
      return {};
  // A std::vector made in this row (no loop between its declaration and the uses) whose row
  // stored only the intervals: where the element is in none, it holds the vector's value.
  const bool stores_here =
      nit != L.nest_index_.end() &&
      std::any_of(L.k_.nests[nit->second].stores.begin(), L.k_.nests[nit->second].stores.end(),
                  [&](const Store& st) { return st.array == p->name; });
  // (not where a loop around the read writes it: a later store there carries over)
  if (b.fill && b.row_counters.empty() && !unknown && conditional == 0 && !stores_here &&
      !loop_writing_around(L.ctx_, e, b.decl) && read_inside(b, local, facts, e)) {
    const ExprP at = index_expr(local, L.headers_);
    ExprP in;
    for (const auto& w : written) {
      ExprP inside = binary(Op::And, binary(Op::Le, index_expr(w.lo, L.headers_), at),
                            binary(Op::Le, at, index_expr(w.hi, L.headers_)));
      in = in ? binary(Op::Or, in, inside) : inside;
    }
    return {in, b.fill};
  }
  std::vector<Loop> loops;
  for (const auto& l : L.loops_)
    loops.push_back(*l);
  auto r = range_over(local, loops, b.depth, facts);
  if (r) {
    // One interval, where the sizes alone decide: checked at run time.
    if (written.size() == 1) {
      bool never = false;
      if (prove_or_check({r->first - written[0].lo, written[0].hi - r->second}, facts,
                         fmt::format("line buffer '{}' is read at '{}' (elements {} to {}) only "
                                     "where the loop on line {} wrote it (elements {} to {})",
                                     name, L.text(e), r->first.str(), r->second.str(),
                                     written[0].line, written[0].lo.str(), written[0].hi.str()),
                         loc, never))
        return {};
    }
  }
  if (nit != L.nest_index_.end())
    for (const auto& st : L.k_.nests[nit->second].stores)
      if (st.array == p->name)
        L.fail(loc,
               fmt::format("line buffer '{}' is read at '{}', an element this iteration does "
                           "not write before (it writes '{}' on line {}): a value carried from "
                           "another iteration{} (a recurrence) is outside the kernel subset; "
                           "fill the buffer in one loop, read it in a later one",
                           name, L.text(e), name + subscript(*buffer_local(b, st.index), {}),
                           st.pos.line,
                           L.loops_.empty() ? "" : " of loop '" + L.loops_.back()->var + "'"),
               "dpgen-buffer");
  std::vector<std::string> ws;
  for (const auto& w : written)
    ws.push_back(fmt::format("{} to {} (line {})", w.lo.str(), w.hi.str(), w.line));
  L.fail(
      loc,
      unwritten_read(name, L.text(e), rows, ws, conditional,
                     r ? fmt::format(" (elements {} to {})", r->first.str(), r->second.str()) : "",
                     vector_read_hint(b.decl)),
      "dpgen-buffer");
}

// `std::vector<double> flux(n + 1);`, `std::vector<float> t(nx, 0.0f);`: the vector's values
// are the line buffer's. Its constructor's value (zero, or the one given) is read where no
// store of the row wrote, under check_buffer_read's conditions.
bool LineBuffers::declare_vector(const VarDecl* v) {
  QualType elem = L.vector_element(v->getType(), "vector");
  if (elem.isNull() || v->getType()->isReferenceType())
    return false;
  const clang::Expr* count = vector_count(v);
  if (!count && elem->isRealFloatingType()) // (other elements: declare_buffer's message)
    L.fail(v->getLocation(), vector_form(v->getNameAsString()), "dpgen-buffer");
  declare_buffer(v, elem, count ? L.exprs_.expr(count) : int_const(0), /*sized=*/true);
  const clang::Expr* value = vector_fill(v);
  buffers_.at(L.k_.hidden.back().name).fill =
      value ? L.exprs_.expr(value) : real_const(0.0, *L.scalar_type(elem));
  return true;
}

// `double (*u)[n][n] = (double (*)[n][n]) u_flat;`: `u[k][j][i]` is the flat
// element (k * n + j) * n + i of the parameter. False if `v` is no such
// pointer.
bool LineBuffers::declare_array_pointer(const VarDecl* v) {
  QualType t = v->getType();
  if (!t->isPointerType() || !L.ctx_.getAsArrayType(t->getPointeeType()))
    return false;
  const std::string name = v->getNameAsString();
  const clang::Expr* init = v->getInit();
  const clang::Expr* src = init;
  while (src) { // through the casts: (double (*)[n][n]) u, reinterpret_cast, void*
    src = src->IgnoreParens();
    if (const auto* c = dyn_cast<CastExpr>(src))
      src = c->getSubExpr();
    else
      break;
  }
  const auto* ref = src ? dyn_cast<DeclRefExpr>(src) : nullptr;
  const auto* pv = ref ? dyn_cast<VarDecl>(ref->getDecl()) : nullptr;
  auto it = pv ? L.env_.find(pv) : L.env_.end();
  const Param* p =
      it != L.env_.end() && it->second.kind == Binding::ArrayParam ? it->second.param : nullptr;
  if (p && it->second.offset) // (rows from a pointer local: its offset is not a whole row)
    L.fail(v->getLocation(),
           fmt::format("pointer '{}' to arrays is made from pointer '{}'; make it from the array "
                       "parameter '{}' itself",
                       name, pv->getNameAsString(), p->name),
           "dpgen-pointer");
  if (!p || p->row_pointers || p->view || !p->container.empty() || p->scalar_ref ||
      !p->rows.empty() || buffer_of(p->name) || p->global)
    L.fail(v->getLocation(), fmt::format("pointer '{}' to arrays must be initialised with a cast "
                                         "of a flat array parameter of the kernel ('double "
                                         "(*{})[n][n] = (double (*)[n][n]) u;')",
                                         name, name));
  // The element type is the parameter's.
  QualType el = t->getPointeeType();
  while (const auto* at = L.ctx_.getAsArrayType(el)) {
    if (const auto* vat = dyn_cast<VariableArrayType>(at)) {
      // The extent as it is here: kept for every later u[k][j] (a local in
      // it may be assigned later; the pointer's rows do not change).
      ExprP x = L.exprs_.expr(vat->getSizeExpr());
      auto px = to_poly(x);
      if (!px || px->mentions_any_counter())
        L.fail(vat->getSizeExpr()->getBeginLoc(),
               fmt::format("the extent '{}' of pointer '{}' must be a polynomial in the integer "
                           "parameters (not in loop counters)",
                           L.text(vat->getSizeExpr()), name));
      vla_sizes_[vat->getSizeExpr()] = x;
    } else if (!isa<ConstantArrayType>(at)) {
      L.fail(v->getLocation(), fmt::format("pointer '{}' has an array type outside the kernel "
                                           "subset",
                                           name));
    }
    el = at->getElementType();
  }
  auto et = L.scalar_type(el);
  if (!et || *et != p->elem)
    L.fail(v->getLocation(), fmt::format("pointer '{}' has elements of type '{}', parameter '{}' "
                                         "of '{}': the cast must keep the element type",
                                         name, el.getAsString(), p->name, p->elem_name));
  Binding b;
  b.kind = Binding::ArrayParam;
  b.param = p;
  L.env_[v] = b;
  return true;
}

} // namespace dpgen::lowering
