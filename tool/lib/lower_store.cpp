// Lowering, stores: assignments to outputs and locals, the stores of the
// current nest and what a later statement sees of them, in-place arrays'
// values (lower_stmt.hpp).
#include "lower_impl.hpp"

namespace dpgen::lowering {

// `*p` of a helper's pointer parameter bound to a caller's local (`&f`).
const VarDecl* Stores::deref_local(const clang::Expr* e) {
  const auto* u = dyn_cast<UnaryOperator>(e->IgnoreParenImpCasts());
  if (!u || u->getOpcode() != UO_Deref)
    return nullptr;
  const auto* r = dyn_cast<DeclRefExpr>(u->getSubExpr()->IgnoreParenImpCasts());
  const auto* v = r ? dyn_cast<VarDecl>(r->getDecl()) : nullptr;
  auto it = v ? L.env_.find(v) : L.env_.end();
  return it != L.env_.end() && it->second.kind == Binding::Value && it->second.deref_only ? v
                                                                                          : nullptr;
}

// (lower_stmt.hpp)
size_t Stores::first_outer_frame(const VarDecl* var) const {
  const auto* owner = dyn_cast<FunctionDecl>(var->getDeclContext());
  size_t first = 0;
  for (size_t k = 0; k < L.frames_.size(); ++k)
    if (owner && owner->getCanonicalDecl() == L.frames_[k].fn->getCanonicalDecl())
      first = k + 1;
  return first;
}

// (lower_stmt.hpp)
void Stores::check_caller_write(const VarDecl* var, SourceLocation loc) {
  const size_t first = first_outer_frame(var);
  for (const auto& [depth, where] : L.cond_operands_)
    if (first <= depth && depth < L.frames_.size())
      L.fail(loc, fmt::format("'{}' is assigned by a call in an operand that C++ evaluates only "
                              "under a condition (line {}: a '?:' arm, or the right side of "
                              "'&&' / '||'), which dpgen evaluates as if it always ran; make "
                              "the call in an if/else statement",
                              var->getNameAsString(), L.pos(where).line));
}

void Stores::assign(const clang::Expr* lhs, BinaryOperatorKind op, const clang::Expr* rhs,
                    SourceLocation loc) {
  lhs = lhs->IgnoreParenImpCasts();
  if (const VarDecl* v = deref_local(lhs)) {
    assign_value(v, *L.scalar_type(v->getType()->getPointeeType()), lhs, op, rhs, loc);
    return;
  }
  if (auto le = L.stmts_.local_element(lhs)) {
    check_caller_write(le->first, lhs->getBeginLoc());
    // The right side first (C++17 sequences it before the left), then the
    // binding: lowering it may inline a call whose branches reassign env_,
    // which reuses its nodes for other variables (a reference taken before
    // pointed at another one: the assignment was lost).
    ExprP r = rhs ? L.exprs_.expr(rhs) : int_const(1);
    Binding& b = L.env_[le->first];
    std::optional<ExprP>& slot = b.elems[le->second];
    std::string name = fmt::format("{}_{}", le->first->getNameAsString(), le->second);
    if (op == BO_Assign) {
      slot = L.stmts_.make_local(name, nullptr, cast(r, b.elem));
      return;
    }
    if (!slot)
      L.fail(lhs->getBeginLoc(), L.unset_message(le->first, "used before it has a value"));
    Op bop = op == BO_AddAssign   ? Op::Add
             : op == BO_SubAssign ? Op::Sub
             : op == BO_MulAssign ? Op::Mul
             : op == BO_DivAssign ? Op::Div
                                  : Op::Rem;
    if (bop == Op::Rem)
      L.fail(loc, "this compound assignment is outside the kernel subset");
    slot = L.stmts_.make_local(name, nullptr, cast(binary(bop, *slot, r), b.elem));
    return;
  }
  if (L.red_.element_update(lhs, op, rhs, loc)) // *err = fmax(*err, e)
    return;
  if (auto acc = L.exprs_.element(lhs)) {
    const Param* p = acc->param;
    if (!acc->dims.empty())
      L.fail(lhs->getBeginLoc(), fmt::format("view '{}' is written at a choice of positions (a "
                                             "periodic wrap): write each element at an affine "
                                             "index, with the wrap as a branch around the store",
                                             p->name));
    if (p->inout) {
      // u[k] = v / u[k] += v on an in-place array: a store of the new value
      // into its twin; `+=` adds to the value u[k] has here (the old one, or
      // what this iteration stored).
      const Param* twin = L.k_.find_param(p->name + "_new");
      ExprP value = L.exprs_.expr(rhs ? rhs : lhs);
      if (op != BO_Assign) {
        if (op != BO_AddAssign && op != BO_SubAssign && op != BO_MulAssign)
          L.fail(loc, "this compound assignment is outside the kernel subset");
        ExprP old = inout_value(p, acc->index, lhs->getBeginLoc(), lhs);
        ExprP r = rhs ? L.exprs_.expr(rhs) : int_const(1);
        value = binary(op == BO_AddAssign   ? Op::Add
                       : op == BO_SubAssign ? Op::Sub
                                            : Op::Mul,
                       old, r);
      }
      add_store(twin->name, acc->index, cast(value, p->elem), false, L.pos(lhs->getBeginLoc()),
                lhs->getBeginLoc());
      L.acc_.inout_stores.push_back({p->name, L.cur_key(), L.next_store_seq_ - 1, acc->index});
      return;
    }
    if (!L.frames_.empty() && !L.frames_.back().is_void)
      L.fail(lhs->getBeginLoc(), fmt::format("helper '{}' writes to array '{}': helpers return "
                                             "values; store them in the kernel",
                                             L.frames_.back().fn->getNameAsString(), p->name));
    if (p->global)
      L.fail(lhs->getBeginLoc(), fmt::format("write to '{}': global state is outside the kernel "
                                             "subset (a kernel reads globals; its results go to "
                                             "DPGEN_OUT parameters)",
                                             p->name));
    if (p->kind != ParamKind::Out)
      L.fail(lhs->getBeginLoc(),
             fmt::format("'{}' is written but is not a DPGEN_OUT parameter; inputs and constant "
                         "arrays are read only{}",
                         p->name,
                         p->kind == ParamKind::In
                             ? " (an array updated in place, as in Gauss-Seidel or an in-place "
                               "time step, carries values from one iteration to the next: "
                               "write the new values to a separate DPGEN_OUT array)"
                             : ""));
    std::vector<std::pair<const clang::Expr*, bool>> terms;
    if (op == BO_Assign && !visible_store(current_nest(), p->name, acc->index) &&
        L.red_.forms().self_update_terms(lhs, rhs, terms)) {
      // out[j] = out[j] + e - f where this iteration has not stored out[j] (that is a read
      // back): the element is summed into, as C++ adds the terms.
      if (L.bufs_.is_buffer(p->name))
        L.bufs_.check_buffer_store(p, acc->index, true, lhs);
      add_sum(p->name, acc->index, terms, p->elem, L.pos(lhs->getBeginLoc()), lhs->getBeginLoc());
      return;
    }
    ExprP value;
    if (op == BO_Assign) {
      value = L.exprs_.expr(rhs);
    } else if (op == BO_AddAssign || op == BO_SubAssign) {
      ExprP r = rhs ? L.exprs_.expr(rhs) : int_const(1);
      if (L.bufs_.is_buffer(p->name))
        L.bufs_.check_buffer_store(p, acc->index, true, lhs);
      add_sum(p->name, acc->index, {op == BO_AddAssign ? r : unary(Op::Neg, r)}, p->elem,
              L.pos(lhs->getBeginLoc()), lhs->getBeginLoc());
      return;
    } else if ((op == BO_MulAssign || op == BO_DivAssign) &&
               visible_store(current_nest(), p->name, acc->index)) {
      // b[i] = t; ... b[i] *= s;: the element's value is this iteration's store (a read back),
      // so this is b[i] = b[i] * s.
      ExprP r = L.exprs_.expr(rhs);
      value = binary(op == BO_MulAssign ? Op::Mul : Op::Div, L.exprs_.expr(lhs), r);
    } else {
      L.fail(loc, fmt::format("compound assignment '{}' to output '{}' needs the element's "
                              "previous value, which the adjoint does not have; '=', '+=' and "
                              "'-=' write outputs ('*=' and '/=' an element this iteration has "
                              "stored)",
                              BinaryOperator::getOpcodeStr(op).str(), p->name));
    }
    if (L.bufs_.is_buffer(p->name)) // a line buffer: in bounds, no value carried (lower_buffer.cpp)
      L.bufs_.check_buffer_store(p, acc->index, false, lhs);
    add_store(p->name, acc->index, cast(value, p->elem), false, L.pos(lhs->getBeginLoc()),
              lhs->getBeginLoc());
    return;
  }
  const auto* ref = dyn_cast<DeclRefExpr>(lhs);
  const auto* var = ref ? dyn_cast<VarDecl>(ref->getDecl()) : nullptr;
  if (!var)
    L.fail(lhs->getBeginLoc(), "assignment target is outside the kernel subset (write to an "
                               "output element or a local variable)");
  auto it = L.env_.find(var);
  if (it == L.env_.end() || (it->second.param && it->second.param->global)) {
    if (var->hasGlobalStorage())
      L.fail(lhs->getBeginLoc(), fmt::format("write to '{}': global state is outside the kernel "
                                             "subset",
                                             var->getNameAsString()));
    L.fail(lhs->getBeginLoc(),
           fmt::format("'{}' is outside the kernel subset", var->getNameAsString()));
  }
  if (it->second.kind == Binding::ArrayParam && it->second.offset)
    L.fail(lhs->getBeginLoc(),
           fmt::format("pointer '{}' is changed after its declaration; dpgen follows a pointer "
                       "fixed where it is declared: declare another ('const double* next = {} + "
                       "nx;') or index this one",
                       var->getNameAsString(), var->getNameAsString()),
           "dpgen-pointer");
  if (it->second.kind != Binding::Value)
    L.fail(lhs->getBeginLoc(), fmt::format("parameter '{}' is assigned; kernel parameters are "
                                           "read only",
                                           var->getNameAsString()));
  auto t = L.scalar_type(var->getType().getNonReferenceType());
  if (!t)
    L.fail(lhs->getBeginLoc(),
           fmt::format("'{}' has a type outside the kernel subset", var->getNameAsString()));
  assign_value(var, *t, lhs, op, rhs, loc);
}

// var = rhs, var += rhs, ... for a scalar local (or what a helper's `*p`
// stands for).
void Stores::assign_value(const VarDecl* var, Type t, const clang::Expr* lhs, BinaryOperatorKind op,
                          const clang::Expr* rhs, SourceLocation loc) {
  check_caller_write(var, lhs->getBeginLoc());
  if (L.red_.local_update(var, t, lhs, op, rhs, loc)) // s += e, m = std::max(m, e)
    return;
  // The right side first, then the binding (as for a local array's element
  // above: a reference into env_ does not survive lowering a call).
  ExprP r = rhs ? L.exprs_.expr(rhs) : int_const(1);
  Binding& b = L.env_[var];
  ExprP value;
  if (op == BO_Assign) {
    value = r;
  } else {
    if (!b.value)
      L.fail(lhs->getBeginLoc(), L.unset_message(var, "used before it has a value"));
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
    case BO_RemAssign: // (an integer's: `m %= 5`)
      bop = Op::Rem;
      break;
    default:
      L.fail(loc, "this compound assignment is outside the kernel subset");
    }
    value = binary(bop, *b.value, r);
    if (var->getType().getNonReferenceType()->isUnsignedIntegerType() && rhs)
      L.ints_.check_unsigned_constant(op, loc,
                                      fmt::format("{} {} {}", var->getNameAsString(),
                                                  BinaryOperator::getOpcodeStr(op).str(),
                                                  L.text(rhs)),
                                      *b.value, r);
    if (bop == Op::Sub && var->getType().getNonReferenceType()->isUnsignedIntegerType())
      L.ints_.check_unsigned_result(
          value, loc, fmt::format("unsigned '{}' after '-='", var->getNameAsString()), lhs);
  }
  b.value = L.stmts_.make_local(var->getNameAsString(), var, cast(value, t));
}

bool Stores::swap(const clang::Expr* e) {
  const auto* c = dyn_cast<CallExpr>(e);
  const FunctionDecl* f = c ? c->getDirectCallee() : nullptr;
  if (!f || !f->isInStdNamespace() || f->getName() != "swap" || c->getNumArgs() != 2)
    return false;
  const VarDecl* v[2];
  for (int k = 0; k < 2; ++k) {
    const auto* r = dyn_cast<DeclRefExpr>(c->getArg(k)->IgnoreParenImpCasts());
    v[k] = r ? dyn_cast<VarDecl>(r->getDecl()) : nullptr;
    auto it = v[k] ? L.env_.find(v[k]) : L.env_.end();
    if (it == L.env_.end() || it->second.kind != Binding::Value ||
        !L.scalar_type(v[k]->getType().getNonReferenceType()))
      L.fail(c->getArg(k)->getBeginLoc(),
             fmt::format("std::swap of '{}': dpgen swaps two scalar locals (std::swap(a, b)); "
                         "pointers, arrays and their elements are swapped by assignments of "
                         "their own, or not at all (index the other array instead)",
                         L.text(c->getArg(k))));
  }
  // Both values as they are before the call (a read before either has one is refused as
  // any read would be), then each variable gets the other's.
  const ExprP x = L.exprs_.expr(c->getArg(0)), y = L.exprs_.expr(c->getArg(1));
  for (int k = 0; k < 2; ++k)
    check_caller_write(v[k], c->getBeginLoc());
  L.env_[v[0]].value = L.stmts_.make_local(v[0]->getNameAsString(), v[0], y);
  L.env_[v[1]].value = L.stmts_.make_local(v[1]->getNameAsString(), v[1], x);
  return true;
}

Store* Stores::visible_store(Nest& nest, const std::string& array, const ExprP& idx) {
  for (auto it = nest.stores.rbegin(); it != nest.stores.rend(); ++it)
    if (it->array == array && same_index(it->index, idx) && is_prefix(it->path, L.path_))
      return &*it;
  return nullptr;
}

Nest& Stores::current_nest() {
  auto it = L.nest_index_.find(L.cur_key());
  if (it == L.nest_index_.end()) {
    Nest n;
    n.key = L.cur_key();
    for (const auto& l : L.loops_)
      n.loops.push_back(*l);
    L.k_.nests.push_back(n);
    it = L.nest_index_.emplace(L.cur_key(), L.k_.nests.size() - 1).first;
  }
  return L.k_.nests[it->second];
}

// `prefix` holds wherever `path` holds: its conditions open `path`.
bool Stores::is_prefix(const std::vector<PathCond>& prefix, const std::vector<PathCond>& path) {
  if (prefix.size() > path.size())
    return false;
  for (size_t i = 0; i < prefix.size(); ++i)
    if (prefix[i].cond != path[i].cond || prefix[i].positive != path[i].positive)
      return false;
  return true;
}

namespace {

// `base + t1 + t2 ...` as C++ adds it (each sum in the wider of its operands' types), converted
// to `elem`.
ExprP added_onto(ExprP base, const std::vector<ExprP>& terms, Type elem) {
  for (const ExprP& t : terms)
    base = binary(Op::Add, base, t);
  return cast(base, elem);
}

} // namespace

void Stores::add_sum(const std::string& array, ExprP idx, const std::vector<ExprP>& terms,
                     Type elem, SourcePos p, SourceLocation loc) {
  ExprP sum = terms.at(0);
  for (size_t k = 1; k < terms.size(); ++k)
    sum = binary(Op::Add, sum, terms[k]);
  put(array, std::move(idx), cast(sum, elem), true, p, loc, 0, &terms);
}

void Stores::add_sum(const std::string& array, ExprP idx,
                     const std::vector<std::pair<const clang::Expr*, bool>>& terms, Type elem,
                     SourcePos p, SourceLocation loc) {
  std::vector<ExprP> lowered;
  for (const auto& [term, negate] : terms) {
    ExprP r = L.exprs_.expr(term);
    lowered.push_back(negate ? unary(Op::Neg, r) : r);
  }
  add_sum(array, std::move(idx), lowered, elem, p, loc);
}

void Stores::put(const std::string& array, ExprP idx, ExprP value, bool accumulate, SourcePos p,
                 SourceLocation loc, int extremum, const std::vector<ExprP>* terms) {
  for (const auto& [depth, where] : L.cond_operands_)
    if (depth < L.frames_.size())
      L.fail(loc, fmt::format("a call in an operand that C++ evaluates only under a condition "
                              "(line {}: a '?:' arm, or the right side of '&&' / '||') stores "
                              "into '{}', which dpgen would store as if the call always ran; "
                              "make the call in an if/else statement",
                              L.pos(where).line, local_base(array)));
  // `(j << lg) | i` as the sum it equals, `j * n + i`, where the loops keep
  // i below n = 1 << lg (prove.hpp: bits_as_sum)
  if (!to_poly(idx)) {
    std::vector<Loop> around;
    for (const auto& l : L.loops_)
      around.push_back(*l);
    idx = bits_as_sum(idx, around, L.path_, L.k_.kernel_locals);
  }
  // A sum into one element from the iterations of a library parallel-for
  // (`ParallelFor(bx, [&](...) { sum += ...; })`) is a data race under its
  // parallel semantics: refused, though a serial reading would be a sum.
  if (accumulate && !L.library_loops_.empty()) {
    auto pi = to_poly(idx);
    for (const auto& l : L.loops_)
      if (L.library_loops_.count(l.get()) && (!pi || !pi->mentions_counter(l->var)))
        L.fail(loc,
               fmt::format("'+=' into '{}' in the body of a parallel-for ('{}'), at an "
                           "element its iterations over '{}' share: a data race under the "
                           "library's parallel semantics; write the sum as a loop nest of the "
                           "kernel (a parallel_reduce is outside the kernel subset)",
                           array, L.frames_.empty() ? "?" : L.frames_.front().fn->getNameAsString(),
                           l->var),
               "dpgen-loop");
  }
  // Updating an element this nest stored, after a later nest stored the
  // array too: the update goes after that nest.
  if (auto it = L.nest_index_.find(L.cur_key()); it != L.nest_index_.end())
    if (visible_store(L.k_.nests[it->second], array, idx))
      L.order_after_later_stores(array);
  Nest& nest = current_nest();
  // A second store to the same element in one iteration updates the first:
  // `x[k] = a; ... x[k] += b;` stores a + b, and a store under a further
  // condition keeps the earlier value where that condition fails.
  if (Store* prev = visible_store(nest, array, idx)) {
    // (two min/max updates in one iteration: the scan takes the extremum of
    // both, still a constant to derivatives)
    // (the value is evaluated past the arm, in a select on the arm's
    // conditions, which may read the arm's values too: `if (d > 0.0)`)
    ExprP cond = path_condition(L.path_, prev->path.size());
    std::vector<ExprP> guarded_terms;
    if (terms)
      guarded_terms = *terms;
    if (cond) {
      cond = L.guards_.guarded(cond, prev->path.size());
      value = L.guards_.guarded(value, prev->path.size());
      for (ExprP& t : guarded_terms)
        t = L.guards_.guarded(t, prev->path.size());
      if (accumulate || extremum) // (the earlier value is in both arms of the select below)
        shared_value(*prev, local_base(array));
    }
    // (`x[k] = a; x[k] += b;`: a + b as C++ adds it, also where b is wider than x)
    auto add_to = [&](const ExprP& before) {
      return terms ? added_onto(before, guarded_terms, before->type)
                   : binary(Op::Add, before, value);
    };
    ExprP updated =
        extremum     ? call("dpgen_nograd",
                            {call(extremum > 0 ? "max" : "min", {prev->value, value}, value->type)},
                            value->type)
        : accumulate ? add_to(prev->value)
                     : value;
    if (prev->accumulate && !prev->extremum && !accumulate && !extremum) {
      // `x[k] += a; x[k] = b;`: the element holds b, what it held is gone
      if (cond)
        L.fail(loc, fmt::format("output '{}' is set here under a condition after '+=' added to "
                                "it in this iteration: where the condition fails it keeps what "
                                "it held before plus the sum, and where it holds it does not; "
                                "set it before adding to it",
                                array));
      prev->accumulate = false;
      prev->chain = nullptr;
      prev->value = value;
      prev->pos = p;
      return;
    }
    if (accumulate && prev->accumulate && !extremum) { // (x + a) + b, as the kernel adds
      const Param* a = L.k_.find_param(array);
      const ExprP before =
          prev->chain
              ? prev->chain
              : binary(Op::Add, read(array, idx, value->type, p, a ? shape_of(*a) : Shape{}),
                       prev->value);
      // (in both arms of the select: one local, `x_1 = x[k] + a`)
      const ExprP shared = cond ? local_at(*prev, local_base(array), before) : before;
      const ExprP after = add_to(shared);
      prev->chain = cond ? select(cond, after, shared) : after;
    } else {
      prev->chain = nullptr;
    }
    prev->value = cond ? select(cond, updated, prev->value) : updated;
    prev->pos = p;
    return;
  }
  // Otherwise a store whose path is not provably disjoint from another
  // store's to an element that may be the same would overwrite it.
  for (auto& s : nest.stores) {
    if (s.array != array || paths_disjoint(s.path, L.path_) || (s.accumulate && accumulate))
      continue;
    auto pa = to_poly(s.index), pb = to_poly(idx);
    Facts facts;
    for (const auto& l : L.loops_)
      add_nonempty(*l, facts);
    for (const auto& pc : L.path_)
      add_facts(pc, facts);
    if (pa && pb) {
      Poly g1 = *pa - *pb - Poly::constant(1), g2 = *pb - *pa - Poly::constant(1);
      if (prove_nonneg(g1, facts) || prove_nonneg(g2, facts))
        continue;
      // A view's (row pointers') layout symbols stand for no size the
      // generated code can compare: elements in different constant planes
      // (rows) are apart (the plane symbol exceeds any offset in a plane);
      // any other difference in them is not decided here.
      if (layout_apart(*pa - *pb))
        continue;
      if (!(*pa - *pb).mentions_any_counter() && !accumulate && !s.accumulate &&
          is_prefix(L.path_, s.path) && !mentions_layout(*pa - *pb)) {
        // Different elements for some sizes only (u[0] and u[n - 1]): where
        // they are the same, this store overwrites the earlier one, which
        // then contributes nothing. The earlier store gets that condition.
        s.path.push_back({binary(Op::Eq, s.index, idx), false});
        continue;
      }
    }
    const Param* twin = L.k_.find_param(array); // (an in-place array's new values: u_new)
    L.fail(loc,
           fmt::format("{} may be written twice in one iteration (first at line {}); write "
                       "each element once",
                       twin && !twin->twin_of.empty() ? "in-place array '" + twin->twin_of + "'"
                                                      : "output '" + array + "'",
                       s.pos.line));
  }
  Store st{array, idx, value, L.path_, p, accumulate, extremum, nullptr, 0};
  // (`x += t` where x + t rounds otherwise than x + (elem)t, or a chain: the element's new value
  // for the forward forms)
  if (terms &&
      (terms->size() > 1 || (value->type == Type::Float && terms->front()->type == Type::Double))) {
    const Param* a = L.k_.find_param(array);
    st.chain = added_onto(read(array, idx, value->type, p, a ? shape_of(*a) : Shape{}), *terms,
                          value->type);
  }
  st.seq = L.next_store_seq_++;
  nest.stores.push_back(st);
}

// The value u[k] of an in-place array has here: what this iteration stored
// at k, or the value before the call (a read of the input). A store under
// conditions that hold no longer here (`if (f[i] > 0.5) u[i] = 2 * u[i];`,
// then a read after the if) is that store's value where its conditions held
// and the earlier value elsewhere; one in an arm that excludes this point
// (the other arm of the if) did not happen.
ExprP Stores::inout_value(const Param* p, const ExprP& idx, SourceLocation loc,
                          const clang::Expr* e) {
  const std::string twin = p->name + "_new";
  auto nit = L.nest_index_.find(L.cur_key());
  if (nit != L.nest_index_.end())
    if (Store* st = visible_store(L.k_.nests[nit->second], twin, idx))
      return shared_value(*st, p->name);
  L.acc_.inout_reads.push_back({p->name, L.cur_key(), L.next_store_seq_, idx, {}, L.pos(loc)});
  ExprP r = read(p->name, idx, p->elem, L.pos(loc), shape_of(*p));
  std::const_pointer_cast<Expr>(r)->source = L.text(e);
  if (nit == L.nest_index_.end())
    return r;
  for (const Store& s : L.k_.nests[nit->second].stores) {
    if (s.array != twin || !same_index(s.index, idx) || paths_disjoint(s.path, L.path_))
      continue;
    size_t common = 0; // the conditions this point shares with the store
    while (common < s.path.size() && common < L.path_.size() &&
           s.path[common].cond == L.path_[common].cond &&
           s.path[common].positive == L.path_[common].positive)
      ++common;
    const ExprP cond = path_condition(s.path, common);
    r = cond ? select(L.guards_.guarded(cond, common), L.guards_.guarded(s.value, common), r)
             : s.value;
  }
  return r;
}

ExprP Stores::shared_value(Store& st, const std::string& name) {
  return st.value = local_at(st, name, st.value);
}

ExprP Stores::local_at(const Store& st, const std::string& name, const ExprP& v) {
  if (v->ops.empty() || v->op == Op::Local || v->op == Op::Read || L.loops_.empty())
    return v;
  ExprP l = L.stmts_.make_local(name, nullptr, v);
  // (made where the store is: its value holds wherever the store's path does)
  std::const_pointer_cast<LocalVar>(l->local)->made_under = st.path;
  return l;
}

std::string Stores::local_base(const std::string& array) const {
  const Param* a = L.k_.find_param(array); // (u_new: u's new values)
  return a && !a->twin_of.empty() ? a->twin_of : array;
}

bool Stores::written_by_other_nest(const std::string& array) const {
  for (const auto& [key, idx] : L.nest_index_)
    if (key != L.cur_key())
      for (const auto& st : L.k_.nests[idx].stores)
        if (st.array == array)
          return true;
  return false;
}

} // namespace dpgen::lowering
