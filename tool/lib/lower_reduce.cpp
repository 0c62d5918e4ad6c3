// Lowering, reductions: scalar accumulators (`s += f(a[i])`, read after the
// loop) and min/max reductions into locals and output elements
// (lower_reduce.hpp).
#include "lower_impl.hpp"

namespace dpgen::lowering {

// ---- the interface (lower_reduce.hpp) -------------------------------------

Reductions::Reductions(Lowerer& lowerer) : L(lowerer), forms_(lowerer.ctx_, lowerer.sm_) {}

bool Reductions::LoopScope::accumulates(const VarDecl* v) const {
  return std::find(accumulating.begin(), accumulating.end(), v) != accumulating.end();
}

Reductions::LoopScope Reductions::begin_loop(const ForStmt* f, const VarDecl* counter,
                                             const std::set<const VarDecl*>& assigned,
                                             bool open) {
  LoopScope scope;
  scope.element_reductions_before = element_reductions_.size();
  if (!open)
    return scope;
  start_element_reductions(f, counter, assigned);
  for (const VarDecl* v : assigned) {
    int extremum = forms_.is_accumulator(f->getBody(), v) ? 0 : forms_.extremum_kind(f->getBody(), {v, nullptr});
    if ((extremum != 0 || forms_.is_accumulator(f->getBody(), v)) &&
        start_accumulator(v, f->getForLoc(), extremum))
      scope.accumulating.push_back(v);
  }
  return scope;
}

void Reductions::end_loop(const LoopScope& scope, const ForStmt* f) {
  finish_element_reductions(scope.element_reductions_before, f->getEndLoc());
  for (const VarDecl* v : scope.accumulating)
    finish_accumulator(v, f->getEndLoc());
}

std::optional<std::string> Reductions::why_unset_inside(const VarDecl* v) const {
  auto acc = accumulators_.find(v);
  if (acc == accumulators_.end())
    return std::nullopt;
  if (acc->second.extremum != 0)
    return fmt::format("'{}' is a {} reduction in this loop: its value is known after the "
                       "loop, read it there",
                       v->getNameAsString(), acc->second.extremum > 0 ? "max" : "min");
  return fmt::format("'{}' accumulates in this loop ('+='): its sum is known after the loop, "
                     "read it there",
                     v->getNameAsString());
}

bool Reductions::if_update(const IfStmt* s) {
  ReductionTarget target;
  int kind = 0;
  const clang::Expr* rest = nullptr;
  const clang::Expr* term = forms_.extremum_if(s, target, kind, &rest);
  // (under the other conjunct, if any: `if (e > m && i > 0)`)
  auto update = [&](Accumulator& a, Type t) {
    size_t depth = L.path_.size();
    if (rest)
      L.path_.push_back(
          {L.guards_.conditional(rest, std::nullopt, [&] { return L.exprs_.cond(rest); }), true});
    extremum_update(a, term, t, s->getBeginLoc());
    L.path_.resize(depth);
  };
  const auto* v = term && !target.element ? dyn_cast<VarDecl>(target.decl) : nullptr;
  if (auto acc = v ? accumulators_.find(bound(v)) : accumulators_.end();
      acc != accumulators_.end() && acc->second.extremum == kind) {
    check_serial(v, s->getBeginLoc());
    update(acc->second, *L.scalar_type(v->getType().getNonReferenceType()));
    return true;
  }
  for (auto& r : element_reductions_)
    if (term && target.element && r.acc.extremum == kind && forms_.is_target(target.element, r.target)) {
      update(r.acc, L.k_.find_param(r.acc.array)->elem);
      return true;
    }
  return false;
}

bool Reductions::element_update(const clang::Expr* lhs, BinaryOperatorKind op,
                                const clang::Expr* rhs, SourceLocation loc) {
  for (auto& r : element_reductions_)
    if (forms_.is_target(lhs, r.target)) { // *err = fmax(*err, e): the reduction's update
      int kind = 0;
      std::vector<const clang::Expr*> more; // (std::max({*err, e1, e2}): e2)
      const clang::Expr* term =
          op == BO_Assign ? forms_.extremum_term(rhs, r.target, kind, &more) : nullptr;
      if (!term || kind != r.acc.extremum)
        L.fail(loc, "internal error: an element reduction assigned in an unexpected form");
      more.insert(more.begin(), term);
      for (const clang::Expr* e : more) // (each term an update of its own: max(max(v, e1), e2))
        extremum_update(r.acc, e, L.k_.find_param(r.acc.array)->elem, lhs->getBeginLoc());
      return true;
    }
  return false;
}

bool Reductions::local_update(const VarDecl* var, Type t, const clang::Expr* lhs,
                              BinaryOperatorKind op, const clang::Expr* rhs, SourceLocation loc) {
  auto acc = accumulators_.find(bound(var));
  if (acc == accumulators_.end())
    return false;
  check_serial(var, loc);
  if (acc->second.extremum) {
    // m = std::max(m, e), fmin(e, m), m > e ? m : e, ...: the scan's update.
    int kind = 0;
    std::vector<const clang::Expr*> more; // (m = std::max({m, e1, e2}): e2)
    const clang::Expr* term =
        op == BO_Assign ? forms_.extremum_term(rhs, {var, nullptr}, kind, &more) : nullptr;
    if (!term || kind != acc->second.extremum)
      L.fail(loc, fmt::format("internal error: reduction '{}' assigned in an unexpected form",
                              var->getNameAsString()));
    more.insert(more.begin(), term);
    for (const clang::Expr* e : more) // (each term an update of its own: max(max(m, e1), e2))
      extremum_update(acc->second, e, t, lhs->getBeginLoc());
    return true;
  }
  // s += e, s -= e, s = s + e, s = e + s, s = s + e - f: the hidden array's element for this
  // iteration of the outer loops gets += (-)e, the terms added as C++ adds them.
  std::vector<std::pair<const clang::Expr*, bool>> terms{{rhs, op == BO_SubAssign}};
  if (op == BO_Assign)
    terms = forms_.accumulated_terms(rhs, var);
  if (terms.empty())
    L.fail(loc, fmt::format("internal error: accumulator '{}' assigned in an unexpected form",
                            var->getNameAsString()));
  // The sums of two loop nests (`for (j) { s += b[j]; for (i) s += a[j * nx + i]; }`) would be
  // added nest by nest, all of one before the other: otherwise rounded than the kernel's order.
  auto& first = acc->second.first_update;
  if (!first)
    first = {L.cur_key(), L.pos(lhs->getBeginLoc()).line};
  else if (first->first != L.cur_key())
    L.fail(lhs->getBeginLoc(),
           fmt::format("'{}' is added to here and on line {}, in loops nested otherwise: dpgen "
                       "splits them into two loop nests and would add all the terms of one "
                       "before the other's, which rounds otherwise than the kernel does; sum "
                       "the inner loop into a local of its own and add that "
                       "(`double t = 0; for (...) t += ...; {} += ... + t;`)",
                       var->getNameAsString(), first->second, var->getNameAsString()));
  L.stores_.add_sum(acc->second.array, acc->second.index, terms, t, L.pos(lhs->getBeginLoc()),
                    lhs->getBeginLoc());
  return true;
}

// An update of a reduction of the caller's loop inside a void helper's own loop, which
// dpgen runs as a parallel-for: refused, naming the helper (not the hidden array).
void Reductions::check_serial(const VarDecl* var, SourceLocation loc) {
  if (L.in_loop_body_frame() || L.loops_.size() <= L.frames_.back().loop_depth)
    return;
  L.fail(loc, fmt::format("'{}' is updated in the loop of helper '{}', which dpgen runs as a "
                          "parallel loop (each iteration on its own, as a library's "
                          "parallel-for): a sum or min/max over its iterations is outside the "
                          "kernel subset there; write the loop in the kernel or in a lambda, "
                          "and call the helper inside it",
                          var->getNameAsString(), L.frames_.back().fn->getNameAsString()));
}

// A read of hidden work array `array` at `idx` by a later nest.
ExprP Reductions::hidden_read(const std::string& array, const ExprP& idx, SourceLocation loc) {
  const Param* h = L.k_.find_param(array);
  ExprP r = read(array, idx, h->elem, L.pos(loc), {});
  std::const_pointer_cast<Expr>(r)->source = h->spelling;
  L.k_.intermediates.insert(array);
  L.acc_.work_reads.push_back({array, L.cur_key(), L.next_store_seq_, idx, L.path_, L.pos(loc)});
  return r;
}

// The update `v = max(v, e)` here (lower_impl.hpp).
void Reductions::extremum_update(Accumulator& a, const clang::Expr* term, Type t,
                              SourceLocation loc) {
  ExprP e = cast(L.exprs_.expr(term), t);
  L.stores_.add_store(a.array, a.index, call("dpgen_nograd", {e}, t), true, L.pos(loc), loc,
                      a.extremum);
  ExtremumUpdate u;
  u.term = e;
  u.path = L.path_;
  for (size_t d = a.depth; d < L.loops_.size(); ++d)
    u.loops.push_back(*L.loops_[d]);
  u.pos = L.pos(loc);
  a.updates.push_back(u);
}

// After the reducing loop: the ties and the result (lower_impl.hpp).
void Reductions::finish_extremum(const Accumulator& a, SourceLocation loc) {
  const Type t = L.k_.find_param(a.array)->elem;
  auto ng = [&](const ExprP& x) { return call("dpgen_nograd", {x}, t); };
  auto one = real_const(1, t), nil = real_const(0, t);
  // A store after every nest so far that stores `array`'s inputs.
  auto straight = [&](const std::string& reads, const std::string& array, auto&& value) {
    L.order_after_later_stores(reads);
    L.stores_.add_store(array, a.index, value(), false, L.pos(loc), loc);
  };
  // One nest per update, with the update's loops and path.
  auto per_update = [&](const std::string& array, auto&& value) {
    for (const auto& u : a.updates) {
      auto path_before = L.path_;
      for (const auto& l : u.loops) {
        L.loops_.push_back(std::make_shared<Loop>(l));
        L.loop_ids_.push_back(L.next_loop_id_++);
        L.segments_.push_back(--L.next_segment_);
      }
      L.path_ = u.path;
      L.stores_.add_store(array, a.index, value(u.term), true, u.pos, loc);
      for (size_t i = 0; i < u.loops.size(); ++i) {
        L.loops_.pop_back();
        L.loop_ids_.pop_back();
        L.segments_.pop_back();
      }
      L.path_ = path_before;
    }
  };
  // T = [S == M] + sum [e == M]
  straight(a.array, a.ties, [&] {
    ExprP m = ng(hidden_read(a.array, a.index, loc));
    return select(binary(Op::Eq, hidden_read(a.start, a.index, loc), m), one, nil);
  });
  per_update(a.ties, [&](const ExprP& e) {
    ExprP m = ng(hidden_read(a.array, a.index, loc));
    return select(binary(Op::Eq, e, m), one, nil);
  });
  // R = M + [S == M](S - M)/T + sum [e == M](e - M)/T
  auto share = [&](const ExprP& x) {
    ExprP m = ng(hidden_read(a.array, a.index, loc));
    ExprP ties = ng(hidden_read(a.ties, a.index, loc));
    return select(binary(Op::Eq, x, m), binary(Op::Div, binary(Op::Sub, x, m), ties), nil);
  };
  straight(a.ties, a.result, [&] {
    return binary(Op::Add, ng(hidden_read(a.array, a.index, loc)),
                  share(hidden_read(a.start, a.index, loc)));
  });
  per_update(a.result, share);
}

// Makes `v` (a real scalar with a value here) an accumulator of the loop
// about to be lowered (a min/max reduction if `extremum`); false (and
// nothing done) where it cannot be one.
bool Reductions::start_accumulator(const VarDecl* v, SourceLocation loc, int extremum) {
  auto it = L.env_.find(v);
  // (a reference or a pointer: only a helper's out-parameter, bound to a local for the call)
  const bool alias = v->getType()->isReferenceType() || v->getType()->isPointerType();
  if (it == L.env_.end() || it->second.kind != Binding::Value || !it->second.value ||
      !is_real((*it->second.value)->type) || (alias && !params_.count(v)))
    return false;
  auto a = make_accumulator(v->getNameAsString(), v->getNameAsString(), *it->second.value,
                            extremum, loc, nullptr);
  if (!a)
    return false;
  accumulators_[v] = *a;
  return true;
}

// The hidden arrays of an accumulator of the loop about to be lowered, from
// value `init`, and their stores before the loop (lower_impl.hpp); `start`:
// a store of `init` to reuse as the start's.
std::optional<Reductions::Accumulator>
Reductions::make_accumulator(const std::string& name, const std::string& spelling, ExprP init,
                             int extremum, SourceLocation loc, Store* start) {
  // One element per iteration of the enclosing loops: (outer - lo) * extent
  // of the inner ones + ..., which needs polynomial bounds.
  ExprP idx = int_const(0);
  for (size_t d = 0; d < L.loops_.size(); ++d) {
    const Loop& l = *L.loops_[d];
    if (!to_poly(l.lo) || !to_poly(l.hi))
      return std::nullopt;
    ExprP here = binary(Op::Sub, loop_var(l.var), l.lo);
    idx = d == 0 ? here
                 : binary(Op::Add, binary(Op::Mul, idx, binary(Op::Sub, l.hi, l.lo)), here);
  }
  if (L.k_.hidden.size() + (extremum ? 4 : 1) > L.k_.hidden.capacity())
    return std::nullopt; // (pointers into it must stay valid while lowering)
  const Type t = init->type;
  auto hidden = [&](const char* what) {
    Param h;
    h.name = fmt::format("dpgen_{}_{}", what, name);
    for (int n = 2; L.k_.find_param(h.name); ++n)
      h.name = fmt::format("dpgen_{}_{}_{}", what, name, n);
    h.kind = ParamKind::Out;
    h.elem = t;
    h.elem_name = type_spelling(h.elem);
    h.spelling = spelling; // the user's accumulator, for messages
    h.declaration = fmt::format("{}* {}", h.elem_name, h.name);
    L.k_.hidden.push_back(h);
    return h.name;
  };
  Accumulator a;
  a.index = idx;
  a.extremum = extremum;
  a.depth = L.loops_.size();
  if (extremum == 0) {
    a.array = hidden("sum");
    L.stores_.add_store(a.array, idx, init, false, L.pos(loc), loc);
    return a;
  }
  a.start = hidden("start");
  a.array = hidden("scan");
  a.ties = hidden("ties");
  a.result = hidden(extremum > 0 ? "max" : "min");
  if (start) { // (before add_store, which may move it)
    start->array = a.start;
    start->index = idx;
  } else {
    L.stores_.add_store(a.start, idx, init, false, L.pos(loc), loc);
  }
  L.stores_.add_store(a.array, idx, call("dpgen_nograd", {init}, t), false, L.pos(loc), loc);
  return a;
}

// The element reductions of loop `f` (lower_impl.hpp): assignments in its
// body to an element of a DPGEN_OUT parameter at an index the loop does not
// change, every one a min/max update of that element.
void Reductions::start_element_reductions(const ForStmt* f, const VarDecl* counter_decl,
                                       const std::set<const VarDecl*>& assigned) {
  std::vector<ReductionTarget> targets;
  std::function<void(const Stmt*)> visit = [&](const Stmt* s) {
    if (!s)
      return;
    const clang::Expr* lhs = nullptr;
    if (const auto* b = dyn_cast<BinaryOperator>(s); b && b->getOpcode() == BO_Assign)
      lhs = b->getLHS();
    ReductionTarget t = lhs ? forms_.target_of(lhs) : ReductionTarget{};
    if (t.element && isa<ParmVarDecl>(t.decl)) {
      bool known = std::any_of(targets.begin(), targets.end(), [&](const ReductionTarget& o) {
        return forms_.same_expr(o.element, t.element);
      });
      // (its subscripts mention neither the loop's counter nor a variable
      // the loop assigns)
      std::vector<const clang::Expr*> subscripts;
      for (const clang::Expr* e = t.element->IgnoreParenImpCasts();
           const auto* sub = dyn_cast<ArraySubscriptExpr>(e);
           e = sub->getBase()->IgnoreParenImpCasts())
        subscripts.push_back(sub->getIdx());
      bool loop_invariant = true;
      for (const clang::Expr* x : subscripts) {
        loop_invariant = loop_invariant && !forms_.mentions(x, counter_decl);
        for (const VarDecl* v : assigned)
          loop_invariant = loop_invariant && !forms_.mentions(x, v);
      }
      if (!known && loop_invariant)
        targets.push_back(t);
    }
    for (const Stmt* c : s->children())
      visit(c);
  };
  visit(f->getBody());
  for (const auto& t : targets) {
    bool active = std::any_of( // (an outer loop's reduction)
        element_reductions_.begin(), element_reductions_.end(),
        [&](const ElementReduction& r) { return forms_.same_expr(r.target.element, t.element); });
    int kind = active ? 0 : forms_.extremum_kind(f->getBody(), t);
    if (kind == 0)
      continue;
    auto acc = L.exprs_.element(t.element);
    if (!acc || !acc->dims.empty() || acc->param->kind != ParamKind::Out || acc->param->inout || acc->param->global)
      continue;
    const Param* p = acc->param;
    auto nit = L.nest_index_.find(L.cur_key());
    Store* prev = nit == L.nest_index_.end()
                      ? nullptr
                      : L.stores_.visible_store(L.k_.nests[nit->second], p->name, acc->index);
    if (!prev || prev->accumulate)
      L.fail(t.element->getBeginLoc(),
           fmt::format("the {} reduction into '{}' in this loop starts from the value it has "
                       "before the loop, which the kernel does not set (the caller's, which the "
                       "adjoint does not have): store the start value first (`{} = 0.0;`), or "
                       "reduce into a local and store that after the loop",
                       kind > 0 ? "max" : "min", L.text(t.element), L.text(t.element)),
           "dpgen-reduction");
    ExprP init = prev->value;
    auto a = make_accumulator(p->name, L.text(t.element), init, kind, f->getForLoc(), prev);
    if (!a)
      L.fail(t.element->getBeginLoc(),
           fmt::format("the {} reduction into '{}': dpgen cannot number the iterations of the "
                       "loops around it (bounds that are not polynomials in the sizes)",
                       kind > 0 ? "max" : "min", L.text(t.element)),
           "dpgen-reduction");
    element_reductions_.push_back({t, p->name, acc->index, *a});
  }
}

// After the reducing loop: each element reduction started at or after `from`
// is stored its result.
void Reductions::finish_element_reductions(size_t from, SourceLocation loc) {
  while (element_reductions_.size() > from) {
    const ElementReduction r = element_reductions_.back();
    element_reductions_.pop_back();
    finish_extremum(r.acc, loc);
    L.order_after_later_stores(r.acc.result);
    ExprP v = hidden_read(r.acc.result, r.acc.index, loc);
    L.stores_.add_store(r.array, r.index, v, false, L.pos(loc), loc);
  }
}

// After the accumulating loop: `v` is the sum, a read of its element.
void Reductions::finish_accumulator(const VarDecl* v, SourceLocation loc) {
  const Accumulator a = accumulators_.at(v);
  accumulators_.erase(v);
  if (a.extremum != 0)
    finish_extremum(a, loc);
  const std::string& sum = a.extremum != 0 ? a.result : a.array;
  L.order_after_later_stores(sum);
  ExprP r = hidden_read(sum, a.index, loc);
  std::const_pointer_cast<Expr>(r)->source = v->getNameAsString();
  L.env_[v].value = r;
  L.why_unset_.erase(v);
}


} // namespace dpgen::lowering
