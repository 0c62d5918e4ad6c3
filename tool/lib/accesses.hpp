// Which elements of each array the kernel touches, computed once for the
// output forms that check sizes against them (the checked entry point,
// emit_checked.cpp; the PyTorch ops, emit_torch.cpp): every store, and every
// read in a store's value, index and conditions or in a kernel-level local,
// each with the iterations in which it happens.
#pragma once

#include "affine.hpp"
#include "ir.hpp"

#include <map>
#include <string>
#include <vector>

namespace dpgen {

struct ArrayAccess {
  ExprP index;
  /// The nest it happens in; nullptr: before every loop (a kernel-level local).
  const Nest* nest = nullptr;
  /// The iterations of the nest in which it happens: the store's, narrowed by
  /// the index conditions of the conditional expressions the read sits in
  /// (those all its occurrences share: derive.hpp, reads_in). A local's reads
  /// happen where the local is defined, so in the whole store's domain
  /// (`t = a[i + 1]; out[i] = i < n - 1 ? t : 0` reads a[n]).
  Domain where;
  /// false: it also depends on a condition that is not an index range (a
  /// data-dependent one): `where` holds iterations in which it does not happen.
  bool exact = true;
};

/// The accesses of each array, in the order of the stores: each store's own,
/// then the reads of its value, its index and its conditions; then those of
/// the kernel-level locals.
std::map<std::string, std::vector<ArrayAccess>> array_accesses(const Kernel& k);

} // namespace dpgen
