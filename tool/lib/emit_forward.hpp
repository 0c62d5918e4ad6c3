// Emit (phase 6): a forward kernel printed from the IR, for the staged
// adjoint (emit.cpp) of a kernel whose work arrays include the hidden arrays
// of its accumulators (Kernel::hidden), which the user's own kernel keeps to
// itself.
#pragma once

#include "emit_util.hpp"
#include "ir.hpp"

#include <string>

namespace dpgen {

/// `void <name>(<the kernel's parameters, flat>, T* <hidden array>...)`: the
/// kernel's loop nests and stores in order, serial, each store under its
/// path; the stores to hidden arrays fill them. Defined `static`.
void emit_recompute(Code& code, const Kernel& k, const std::string& name);

} // namespace dpgen
