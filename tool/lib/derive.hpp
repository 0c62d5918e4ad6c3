// Derive (phase 3): reverse-mode partials of the scalar expressions of a
// store. The adjoint of a read is "the partial of the store's value w.r.t.
// that read, evaluated at the iteration that made the read, times the seed of
// the output cell"; this file computes the partial.
#pragma once

#include "ir.hpp"

#include <map>
#include <set>
#include <string>
#include <vector>

namespace dpgen {

/// The locals derivative rules introduce for a kernel (the value of a call
/// that its own derivative reuses, such as exp(a) in d exp(a) = exp(a)·da),
/// one per call node, named in order of first use within the kernel.
struct DeriveNames {
  /// A call's value, by the call and the conditions of the arms it is in.
  std::map<std::pair<const Expr*, std::string>, LocalP> calls;
  int next = 0;
  /// The locals that name a local's derivative shared within a partial
  /// (`x2_d0`), numbered apart from the calls' so adding one renames none.
  int next_partial = 0;
  /// Names the locals must not take (the kernel's own, Kernel::names).
  const std::set<std::string>* taken = nullptr;
  /// Where the names given out are added, if anywhere (Kernel::names, so the
  /// names later passes make up, Kernel::fresh and hoist's, avoid them).
  std::set<std::string>* given = nullptr;
};

/// d value / d(reads): the partial of `value` w.r.t. the Read nodes in
/// `reads` (occurrences that all read the same cell), as an expression over
/// the primal values; zero() (ir.hpp) where it vanishes, never null.
ExprP derivative(const ExprP& value, const std::set<const Expr*>& reads, DeriveNames& names);

/// The partials of one kernel's stores, each computed once: d store.value /
/// d(reads) per store and set of reads. derive() fills in every read of a
/// differentiable input alone; the schedule looks those up (is the read a
/// value at all? its scatter partial) and asks for the reads each gather
/// block merges, computed on the first request (a block of one read gets the
/// read's own partial). The order of computation numbers the locals the rules
/// introduce (`exp_v0`, ...), so the names depend on the kernel only; a
/// merged partial needs no new one (a call's rule applies to a set of reads
/// only where it applies to one of them).
class Partials {
public:
  /// `taken`: names the rules' locals avoid (Kernel::names); must outlive this.
  /// `given`: where the names of those locals are added (may be `taken`).
  explicit Partials(const std::set<std::string>* taken = nullptr,
                    std::set<std::string>* given = nullptr) {
    names_.taken = taken;
    names_.given = given;
  }
  /// d s.value / d(reads); zero() where it vanishes (is_zero), never null.
  const ExprP& of(const Store& s, const std::set<const Expr*>& reads);

private:
  std::map<std::pair<const Store*, std::set<const Expr*>>, ExprP> table_;
  DeriveNames names_;
};

/// Phase 3: the partial of every store that runs (store_domain, prove.hpp)
/// w.r.t. each read of a DPGEN_IN array in it, one read at a time, in the
/// order input -> loop nest -> store -> read. `names`: where the names of
/// the locals the partials introduce are added (the kernel's Kernel::names,
/// so the names later passes make up avoid them); the partials keep it.
Partials derive(const Kernel& k, std::set<std::string>* names = nullptr);

/// The locals a tangent introduces: `<local>_dot` for each local whose
/// derivative is not trivial (numbered after every other local), and the
/// names in use (parameters and their `_dot`s, so none is shadowed).
struct TangentLocals {
  std::vector<LocalP> locals;
  std::set<std::string> taken;
  std::map<const LocalVar*, ExprP> memo; // a local's tangent, once per kernel
};

/// Forward mode: the directional derivative of `value` when each array in
/// `active` moves along `<array>_dot` (a read a[k] contributes a_dot[k]).
/// zero() where it vanishes (is_zero), never null. One `DeriveNames` and `TangentLocals`
/// per kernel, so a local shared by several stores gets one tangent.
ExprP tangent(const ExprP& value, const std::set<std::string>& active, DeriveNames& names,
              TangentLocals& tangents);

/// A Read node and the conditions of the conditional expressions whose arm it
/// sits in (`i > 0 ? p[i - 1] : 0.0` reads p[i - 1] only where i > 0).
/// Conditions are collected within one definition: a local's own reads are
/// taken as unconditional where the local is defined.
struct ReadSite {
  const Expr* read;
  std::vector<PathCond> conds;
};

/// Every Read node reachable from `e` (through Locals), in first-seen order.
std::vector<ReadSite> reads_in(const ExprP& e);

} // namespace dpgen
