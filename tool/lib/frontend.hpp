// Find and lower: parse kernel files with Clang, find DPGEN_KERNEL functions,
// check them against the supported subset and lower them to the kernel IR.
#pragma once

#include "ir.hpp"

#include <string>
#include <vector>

namespace dpgen {

struct FrontendOptions {
  std::vector<std::string> compiler_args; // after `--`
  std::string resource_dir;               // Clang's builtin headers
};

/// Parses `file` and lowers its kernels. Diagnostics go to stderr as
/// `file:line:col: error: ...` (Clang's format); remarks likewise.
/// Returns false if any error was reported.
bool lower_file(const std::string& file, const FrontendOptions& opts,
                std::vector<Kernel>& kernels);

} // namespace dpgen
