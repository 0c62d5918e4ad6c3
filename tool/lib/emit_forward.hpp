// Emit (phase 6): a forward kernel printed from the IR, for the staged
// adjoint (emit.cpp) of a kernel that the user's own kernel cannot recompute
// into buffers: its work arrays include the hidden arrays of its
// accumulators (Kernel::hidden), which the user's kernel keeps to itself; it
// updates an array in place (the caller's old values must stay); or it has
// view outputs, which the user's kernel writes only through a view of its
// class (here: a dpgen::ViewBuffer laid out like the output's seed).
#pragma once

#include "emit_util.hpp"
#include "ir.hpp"

#include <string>

namespace dpgen {

/// `void <name>(<the kernel's parameters, flat>, T* <hidden array>...)`: the
/// kernel's loop nests and stores in order, serial, each store under its
/// path; the stores to hidden arrays fill them. A view output is a
/// `dpgen::ViewBuffer<...>&`.
void emit_recompute(Code& code, const Kernel& k, const std::string& name);

} // namespace dpgen
