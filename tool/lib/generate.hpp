// The whole pipeline for a set of kernel files: find -> lower (and check) ->
// derive -> schedule -> plan -> emit, then output. Used by the dpgen driver and by tests.
#pragma once

#include "find.hpp"

#include <set>
#include <string>
#include <vector>

namespace dpgen {

struct GenerateOptions {
  FrontendOptions frontend;
  std::string out_dir;
  bool verbose = false; // report which files were written / unchanged
  bool tangent = false; // also <stem>_tangent.{hpp,cpp} (forward mode)
  /// If set: after a successful run, touch this file and write `<stamp>.d`,
  /// a make-style dependency file listing every file the kernels include.
  std::string stamp;
  bool torch = false; // write <stem>_torch.{hpp,cpp} (PyTorch ops) instead of the adjoints
  /// Run the pass `share` (share.hpp); --no-share: every cell computes the
  /// values itself, for comparing results.
  bool share = true;
  /// Passes (pass_names(), ir_text.hpp) after which the IR is printed to
  /// stdout in its text form.
  std::set<std::string> print_after;
};

/// Generates <out_dir>/<stem>_adjoint.{hpp,cpp} (and, with `tangent`,
/// <stem>_tangent.{hpp,cpp}) for each input. If any input
/// has an error, nothing is written at all. Diagnostics go to stderr.
/// Returns the process exit code (0 on success).
int generate(const std::vector<std::string>& inputs, const GenerateOptions& opts);

} // namespace dpgen
