// Emit (phase 6): print one kernel's adjoint from its loop plan as readable
// C++ (fmt), with a comment per contribution naming its rule. The file around
// the kernels (banner, includes, declarations) is emit_file.hpp.
#pragma once

#include "emit_util.hpp"
#include "loop_plan.hpp"

#include <string>

namespace dpgen {

/// The adjoint's declaration, e.g.
/// `void upwind_step_adjoint(const double* d, double* d_adj, ...)`.
std::string adjoint_signature(const Kernel& k);

/// Appends the adjoint of `plan`'s kernel (its entry points, in the kernel's
/// namespaces) to `code`.
void emit_kernel(Code& code, const LoopPlan& plan);

} // namespace dpgen
