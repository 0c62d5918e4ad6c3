// Emit, file level (phase 6): the generated files of one input file around
// the kernels that emit.hpp prints: the banner, the includes, the adjoint
// declarations and the forward kernels' declarations.
#pragma once

#include "loop_plan.hpp"

#include <string>
#include <vector>

namespace dpgen {

struct EmittedFile {
  std::string header;  // <stem>_adjoint.hpp
  std::string source;  // <stem>_adjoint.cpp
  std::string kernels; // <stem>_kernels.hpp: declarations of the forward kernels
};

/// Prints all kernels of one input file. `source_name` is shown in comments,
/// `stem` names the generated files.
EmittedFile emit_file(const std::vector<LoopPlan>& plans, const std::string& source_name,
                      const std::string& stem);

} // namespace dpgen
