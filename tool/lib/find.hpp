// Find (phase 1): parse kernel files with Clang and find their DPGEN_KERNEL
// functions, which lower.hpp turns into checked kernel IR. The entry points
// of the front end (find, lower, check).
#pragma once

#include "ir.hpp"

#include <string>
#include <vector>

namespace dpgen {

struct FrontendOptions {
  std::vector<std::string> compiler_args; // after `--`
  std::string resource_dir;               // Clang's builtin headers
  std::string driver = "clang++";         // argv[0]: where the driver looks for GCC's headers
  bool quiet = false;                     // drop diagnostics (fuzzing)
};

/// Parses `file` and lowers its kernels. Diagnostics go to stderr as
/// `file:line:col: error: ...` (Clang's format); remarks likewise.
/// Returns false if any error was reported.
/// `deps`, if given, receives every file the parse read (for build-system
/// dependency files).
bool lower_file(const std::string& file, const FrontendOptions& opts, std::vector<Kernel>& kernels,
                std::vector<std::string>* deps = nullptr);

/// The same for source text held in memory, named `name`; `headers` maps
/// further in-memory files (e.g. "dpgen/annotate.hpp") to their contents.
bool lower_code(const std::string& code, const std::string& name, const FrontendOptions& opts,
                std::vector<Kernel>& kernels,
                const std::vector<std::pair<std::string, std::string>>& headers = {});

} // namespace dpgen
