// The IR in a stable text form, after each pass (dpgen --print-after=<pass>):
// what lit tests of one pass check, and what a developer reads to see what a
// pass did. Expressions print as C++ (print.hpp); everything else is one
// indented line per object, in the IR's own order, with no addresses.
#pragma once

#include "derive.hpp"
#include "ir.hpp"
#include "loop_plan.hpp"
#include "schedule.hpp"

#include <string>
#include <vector>

namespace dpgen {

/// The passes, in pipeline order: what --print-after accepts.
const std::vector<std::string>& pass_names();

/// After `lower` (with its checks): parameters, kernel-level locals, guards,
/// loop nests with their stores, size checks, extents.
std::string print_ir(const Kernel& k);
/// After `derive`: the partial of every store w.r.t. each read of an input,
/// in derive's order.
std::string print_partials(const Kernel& k, Partials& partials);
/// After `schedule`: gather groups (layout, base, blocks with shift, domain,
/// guards and terms), scatter units, remarks, stages.
std::string print_schedule(const AdjointPlan& plan);
/// After `plan`: per input, the cell loops (cell box, interior, parallel
/// test) of each gather step, and the scatter units.
std::string print_plan(const LoopPlan& plan);
/// After the pass `hoist`: the locals each function of the adjoint files
/// defines before its loops, and the interior terms that use them.
std::string print_hoisted(const LoopPlan& plan);
/// After the pass `share`: the values each gather loop's interior strips share.
std::string print_shared(const LoopPlan& plan);
/// The forward forms' loops (loop_plan.hpp: ForwardPlan): each nest serial or parallel.
std::string print_forward_plan(const ForwardPlan& plan);

/// A domain as text: "{i: [max(1), min(n)); j: ...} | {...}".
std::string domain_text(const Domain& d);

} // namespace dpgen
