// Check (the end of phase 2, on the lowered IR): the rules a kernel's outputs
// must follow for its adjoint to be correct, proved on the loop nests and
// stores lowering made. Each element of an output is written once (or only
// added to), by one iteration; work arrays (outputs a later loop reads) and
// in-place arrays are read only where the adjoint can recompute them; every
// output's extent is bounded. Rules that hold only for some sizes become
// run-time SizeChecks. No Clang here: errors are reported at the SourcePos
// the IR carries, through a Diagnostics sink.
#pragma once

#include "ir.hpp"

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace dpgen {

/// Where the checks report errors (lower.cpp reports them through Clang).
class Diagnostics {
public:
  virtual ~Diagnostics() = default;
  /// `id`: the rule, clang-tidy style ("dpgen-write-once"), printed after
  /// the message.
  virtual void error(const SourcePos& at, const std::string& id, const std::string& message) = 0;
};

/// An access lowering recorded for the checks: a read of a work array or of
/// an in-place array, or a store to an in-place array.
struct Access {
  std::string array;
  std::vector<int> nest_key; // Nest::key of the nest it is in
  int seq;                   // stores numbered below this one (Store::seq) came before it
  ExprP index;
  std::vector<PathCond> path = {}; // work-array reads: the conditions it is under
  SourcePos pos = {};
};

/// What the checks need beyond the kernel IR: the reads of outputs and
/// in-place arrays, which the IR keeps only as Read nodes.
struct Accesses {
  std::vector<Access> work_reads;  // reads of an output an earlier nest wrote
  std::vector<Access> inout_reads; // reads of an in-place array's old values
  std::vector<Access> inout_stores;
  /// Reads of a work array outside every loop (not directly in a store).
  std::vector<std::pair<std::string, SourcePos>> kernel_level_work_reads;
  /// Line buffers (local arrays of more than 64 elements, VLAs), by their
  /// hidden array: the kernel's `tmp[e]` is element row * length + e, `row`
  /// the iteration of the `depth` loops around all the buffer's uses.
  struct Buffer {
    std::string name; // as the kernel names it
    size_t depth = 0;
    ExprP row, length;
    std::vector<ExprP> extents; // hi - lo of each row loop
  };
  std::map<std::string, Buffer> buffers;
};

/// Checks the lowered kernel: work arrays, in-place arrays, the write-once
/// rule for every output, and the extents of the outputs the adjoint needs
/// buffers for. Adds `k.size_checks` and `k.extent`. Reports every
/// violation to `diag` (one per store or read; where an output index is not
/// affine, the rules that need its range are left out) and returns false if
/// there was any.
bool check_kernel(Kernel& k, const Accesses& accesses, Diagnostics& diag);

/// Two indices are the same (as polynomials where they are affine).
bool same_index(const ExprP& a, const ExprP& b);

} // namespace dpgen
