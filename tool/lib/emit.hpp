// Emit (phase 5): print an adjoint plan as readable C++ (fmt), with a header
// naming the source kernel and a comment per contribution naming its rule.
#pragma once

#include "schedule.hpp"

#include <string>

namespace dpgen {

struct EmittedFile {
  std::string header; // <stem>_adjoint.hpp
  std::string source; // <stem>_adjoint.cpp
  std::string kernels; // <stem>_kernels.hpp: declarations of the forward kernels
};

/// The adjoint's declaration, e.g.
/// `void upwind_step_adjoint(const double* d, double* d_adj, ...)`.
std::string adjoint_signature(const Kernel& k);

/// Prints all kernels of one input file. `source_name` is shown in comments,
/// `stem` names the generated files.
EmittedFile emit_file(const std::vector<AdjointPlan>& plans, const std::string& source_name,
                      const std::string& stem);

} // namespace dpgen
