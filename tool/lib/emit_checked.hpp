// Emit (phase 6): the checked entry point of an adjoint, `<kernel>_adjoint_checked`: every
// array followed by its element count, checked against the elements the
// kernel touches before the raw adjoint runs (see emit_checked.cpp).
#pragma once

#include "emit_util.hpp"
#include "ir.hpp"
#include "loop_plan.hpp"

#include <string>

namespace dpgen {

/// Kernels whose arrays are flat pointers get one (std::vector entry points
/// check their sizes themselves; arrays of rows have none).
bool has_checked_entry(const Kernel& k);
std::string checked_signature(const Kernel& k);
/// Whether its checked entry point runs the kernel's loops to check indices that depend on
/// the data (emit_checked.cpp: the probe, dpgen/checked_probe.hpp).
bool needs_probe(const ForwardPlan& plan);
void emit_checked_entry(Code& code, const ForwardPlan& plan);

} // namespace dpgen
