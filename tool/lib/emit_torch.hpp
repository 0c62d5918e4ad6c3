// Emit (phase 6, --torch): the PyTorch glue of a kernel file (`dpgen --torch`): for each kernel a
// torch::autograd::Function whose forward calls the kernel and whose backward
// calls its generated adjoint, registered as the op torch.ops.dpgen.<kernel>.
#pragma once

#include "output.hpp"
#include "schedule.hpp"

#include <string>
#include <vector>

namespace dpgen {

struct TorchFile {
  std::string header; // <stem>_torch.hpp: the ops as C++ functions (namespace dpgen::ops)
  std::string source; // <stem>_torch.cpp: the autograd Functions and their registration
  /// "file:line:col: error: ..." for kernels that cannot be ops (nothing is written then).
  std::vector<std::string> errors;
};

/// The op's schema, e.g. "upwind_step(Tensor d, Tensor u, int n, float dt, float dx, *,
/// int[]? d_next_shape=None) -> Tensor".
std::string torch_schema(const Kernel& k);

TorchFile emit_torch_file(const std::vector<AdjointPlan>& plans, const std::string& source_name,
                          const std::string& stem);

/// `dpgen --torch`: appends <out_dir>/<stem>_torch.{hpp,cpp} of `input` to `pending`.
/// Returns false, with the errors printed to stderr, when a kernel cannot be an op.
bool add_torch_files(const std::vector<AdjointPlan>& plans, const std::string& input,
                     const std::string& out_dir, std::vector<PendingFile>& pending);

} // namespace dpgen
