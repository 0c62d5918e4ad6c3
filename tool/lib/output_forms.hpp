// The output forms: what dpgen writes for one input file. Each form (the
// adjoint files, the tangent files, the PyTorch ops) is one implementation of
// `OutputForm`: it takes what the passes handed on for the file's kernels
// (their IR and adjoint plans), plans the loops it prints (loop_plan.hpp) and
// returns its files. generate.cpp runs the forms the command line asks for,
// through this interface only. Within the adjoint files, the functions printed
// for each kernel (the adjoint, its checked entry, the parallel forward) are
// `KernelForm`s (emit_file.cpp).
#pragma once

#include "ir.hpp"
#include "output.hpp"
#include "schedule.hpp"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace dpgen {

/// What the passes handed on for one input file, and the hooks a form calls.
struct FileIR {
  std::string input;       // the kernel file as given
  std::string source_name; // its file name (in the banners)
  std::string stem;        // the generated files' prefix
  std::string out_dir;
  const std::vector<Kernel>* kernels = nullptr;
  const std::vector<AdjointPlan>* plans = nullptr; // one per kernel, in order
  /// Called as a form enters a pass (its name in "this is a bug in dpgen"
  /// reports) for one kernel (nullptr: all of the file's kernels).
  std::function<void(const char* pass, const Kernel* kernel)> enter;
  /// Prints `text` as the IR after `pass` where --print-after asks for it.
  std::function<void(const char* pass, const std::function<std::string()>& text)> print_after;
};

class OutputForm {
public:
  virtual ~OutputForm() = default;
  /// The form's name ("adjoint", "tangent", "torch").
  virtual const char* name() const = 0;
  /// The files of this form for one input file, appended to `files`; false
  /// (with the errors reported on stderr, "file:line:col: error: ...") where a
  /// kernel cannot take this form.
  virtual bool add_files(const FileIR& ir, std::vector<PendingFile>& files) const = 0;
};

/// The forms to write: the PyTorch ops (`torch`), else the adjoint files and,
/// with `tangent`, the tangent files. `share`: the adjoint files' loops go
/// through the pass `share` (share.hpp).
std::vector<std::unique_ptr<OutputForm>> output_forms(bool torch, bool tangent, bool share = true);

} // namespace dpgen
