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

/// In the flat form of a kernel with flat std::vector (or std::span) parameters, at its start:
/// a container the kernel surely touches beyond its size (`int n` larger than u.size(), a seed
/// shorter than its output) throws std::invalid_argument ("<fn>: 'u' has ... elements, but the
/// kernel touches elements 0 to 7") before anything is read or written.
void emit_container_reach_checks(Code& code, const Kernel& k, const std::string& fn);
std::string checked_signature(const Kernel& k);
/// Whether its checked entry point runs the kernel's loops to check indices that depend on
/// the data (emit_checked.cpp: the probe, dpgen/checked_probe.hpp).
bool needs_probe(const Kernel& k);
/// `void <kernel>_check_reach(const char* caller, <checked_signature's parameters>)`, which
/// kernels that need the probe have: it runs the probe on those arrays (the PyTorch ops call it
/// where an index cannot be bounded from the loops).
std::string reach_signature(const Kernel& k);
/// Its name: <kernel>_check_reach (unless the kernel uses that name: Kernel::fresh).
std::string reach_name(const Kernel& k);
void emit_checked_entry(Code& code, const ForwardPlan& plan);

} // namespace dpgen
