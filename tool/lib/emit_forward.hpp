// Emit (phase 6): the forward forms' printer, one loop nest of the kernel
// printed from its IR as the forward plan (loop_plan.hpp) has it, used by the
// tangent, the torch ops' parallel forward (emit_tangent.cpp) and the
// recompute below; and that recompute, a forward kernel for the staged
// adjoint (emit.cpp) of a kernel that the user's own kernel cannot recompute
// into buffers: its work arrays include the hidden arrays of its
// accumulators (Kernel::hidden), which the user's kernel keeps to itself; it
// updates an array in place (the caller's old values must stay); or it has
// view outputs, which the user's kernel writes only through a view of its
// class (here: a dpgen::ViewBuffer laid out like the output's seed).
#pragma once

#include "emit_util.hpp"
#include "hoist.hpp"
#include "ir.hpp"
#include "loop_plan.hpp"

#include <map>
#include <string>
#include <vector>

namespace dpgen {

/// How a forward form prints a nest.
struct ForwardOptions {
  /// The plan's parallel nests on every thread (threaded_loop); else all serial.
  bool threads = true;
  /// An in-place array's new values (the twin `u_new`, Param::twin_of) to a buffer, each
  /// store also setting the element's flag in the array this map names for the twin (the
  /// tangent copies back the flagged elements only); empty: no flags (the recompute).
  std::map<std::string, std::string> written;
};

/// Nest `plan` of `k`: its loops (a descending one counted down, as the
/// kernel counts, so that a sum adds in the kernel's order: the same bits),
/// each store under its path, as planned (the pass `hoist` has moved their
/// loop-invariant subexpressions before the loops: ForwardPlan::hoisted);
/// with `tangent` each store followed by its tangent `<array>_dot`
/// (ForwardStore::dot). A split nest (ForwardNest::interior, peel_forward):
/// its outer loops test their counters, its innermost loop runs edge /
/// interior / edge in the kernel's order, the interior printing
/// `interior_stores`.
void emit_forward_nest(Code& code, const Kernel& k, const ForwardNest& plan, bool tangent,
                       const ForwardOptions& options);

/// `void <name>(<the kernel's parameters, flat>, T* <hidden array>...)`: the
/// kernel's loop nests and stores in order, serial, each store under its
/// path; the stores to hidden arrays fill them. A view output is a
/// `dpgen::ViewBuffer<...>&`.
void emit_recompute(Code& code, const ForwardPlan& plan, const std::string& name);

/// Every nest of `plan` (each printed by emit_forward_nest, the loop-invariant subexpressions
/// before them), each under a `// loop nest <n>` comment if `comments`.
void emit_forward_nests(Code& code, const ForwardPlan& plan, const ForwardOptions& options,
                        bool comments);

/// Whether `k` has a parallel forward (emit_parallel_forward): some nest runs on every
/// thread (loop_plan.hpp: ForwardNest::parallel), and the kernel has plain arrays only and no
/// accumulator (whose sums the forward would have to allocate).
bool has_parallel_forward(const Kernel& k);

/// `void <kernel>_parallel_forward(<the kernel's parameters, arrays flat>)`.
std::string parallel_forward_signature(const Kernel& k);

/// Its definition: the kernel printed from its IR in its own loops, the outermost loop of each
/// nest that sets every element once on every thread (OpenMP). Each element gets the same
/// stores in the same order as in the kernel, so the results are the kernel's, bit for bit
/// (where the compiler contracts both alike: no `-ffp-contract=fast` differences). In the
/// adjoint files (emit_file.cpp), for C++ callers and the torch ops' forward.
void emit_parallel_forward(Code& code, const ForwardPlan& plan);

} // namespace dpgen
