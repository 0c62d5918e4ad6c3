// Emit tangents (phase 6, --tangent; forward mode): `<kernel>_tangent`, the Jacobian-vector
// product of a kernel, from the same IR as its adjoint.
#pragma once

#include "emit_file.hpp"
#include "ir.hpp"

#include <string>
#include <vector>

namespace dpgen {

/// `void k_tangent(const double* a, const double* a_dot, double* out, double* out_dot, ...)`:
/// each DPGEN_IN array followed by its direction, each DPGEN_OUT array by its
/// tangent (written), in the kernel's parameter order.
std::string tangent_signature(const Kernel& k);

/// `<stem>_tangent.{hpp,cpp}` for the kernels of one input file.
EmittedFile emit_tangent_file(const std::vector<const Kernel*>& kernels,
                              const std::string& source_name, const std::string& stem);

} // namespace dpgen
