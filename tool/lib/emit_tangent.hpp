// Emit tangents (phase 6, --tangent; forward mode): `<kernel>_tangent`, the Jacobian-vector
// product of a kernel, from the same IR as its adjoint.
#pragma once

#include "emit_file.hpp"
#include "emit_util.hpp"
#include "ir.hpp"

#include <string>
#include <vector>

namespace dpgen {

/// `void k_tangent(const double* a, const double* a_dot, double* out, double* out_dot, ...)`:
/// each DPGEN_IN array followed by its direction, each DPGEN_OUT array by its
/// tangent (written), in the kernel's parameter order.
std::string tangent_signature(const Kernel& k);

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
void emit_parallel_forward(Code& code, const Kernel& k);

/// `<stem>_tangent.{hpp,cpp}` for the kernels of one input file.
EmittedFile emit_tangent_file(const std::vector<const Kernel*>& kernels,
                              const std::string& source_name, const std::string& stem);

} // namespace dpgen
