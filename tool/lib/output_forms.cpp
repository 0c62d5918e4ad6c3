// The output forms (output_forms.hpp): the adjoint files, the tangent files
// and the PyTorch ops, each planned and printed from the IR of one input file.
#include "output_forms.hpp"

#include "emit_file.hpp"
#include "emit_tangent.hpp"
#include "emit_torch.hpp"
#include "hoist.hpp"
#include "ir_text.hpp"
#include "loop_plan.hpp"
#include "share.hpp"

#include <llvm/ADT/SmallString.h>
#include <llvm/Support/Path.h>

namespace dpgen {

namespace {

std::string out_path(const FileIR& ir, const std::string& suffix) {
  llvm::SmallString<256> p(ir.out_dir);
  llvm::sys::path::append(p, ir.stem + suffix);
  return std::string(p);
}

// <stem>_adjoint.{hpp,cpp} and <stem>_kernels.hpp: the adjoints in gather form
// (with their checked entries and parallel forwards), planned by plan_loops,
// their loop invariants hoisted (hoist_invariants), values shared along
// strips of cells (share_shifted_values).
class AdjointFiles : public OutputForm {
public:
  explicit AdjointFiles(bool share) : share_(share) {}
  const char* name() const override { return "adjoint"; }

  bool add_files(const FileIR& ir, std::vector<PendingFile>& files) const override {
    std::vector<LoopPlan> loops;
    for (const auto& p : *ir.plans) {
      ir.enter("plan", p.kernel);
      test_internal_error("plan");
      loops.push_back(plan_loops(p));
      ir.print_after("plan", [&] { return print_plan(loops.back()); });
      ir.print_after("plan", [&] { return print_forward_plan(loops.back().forward); });
      ir.enter("hoist", p.kernel);
      hoist_invariants(loops.back());
      ir.print_after("hoist", [&] { return print_hoisted(loops.back()); });
      if (share_) {
        ir.enter("share", p.kernel);
        share_shifted_values(loops.back());
        ir.print_after("share", [&] { return print_shared(loops.back()); });
      }
    }
    ir.enter("emit", nullptr);
    EmittedFile f = emit_file(loops, ir.source_name, ir.stem);
    files.push_back({out_path(ir, "_adjoint.hpp"), f.header});
    files.push_back({out_path(ir, "_adjoint.cpp"), f.source});
    files.push_back({out_path(ir, "_kernels.hpp"), f.kernels});
    return true;
  }

private:
  bool share_;
};

// <stem>_tangent.{hpp,cpp}: forward mode (Jacobian-vector products), the
// kernels' own nests (plan_forward) printed with their tangents.
class TangentFiles : public OutputForm {
public:
  const char* name() const override { return "tangent"; }

  bool add_files(const FileIR& ir, std::vector<PendingFile>& files) const override {
    std::vector<const Kernel*> ks;
    for (const auto& k : *ir.kernels)
      ks.push_back(&k);
    ir.enter("tangent", nullptr);
    EmittedFile t = emit_tangent_file(ks, ir.source_name, ir.stem);
    files.push_back({out_path(ir, "_tangent.hpp"), t.header});
    files.push_back({out_path(ir, "_tangent.cpp"), t.source});
    return true;
  }
};

// <stem>_torch.{hpp,cpp}: each kernel as a PyTorch op, its backward the adjoint.
class TorchFiles : public OutputForm {
public:
  const char* name() const override { return "torch"; }

  bool add_files(const FileIR& ir, std::vector<PendingFile>& files) const override {
    ir.enter("torch", nullptr);
    return add_torch_files(*ir.plans, ir.input, ir.out_dir, files);
  }
};

} // namespace

std::vector<std::unique_ptr<OutputForm>> output_forms(bool torch, bool tangent, bool share) {
  std::vector<std::unique_ptr<OutputForm>> forms;
  if (torch) {
    forms.push_back(std::make_unique<TorchFiles>());
    return forms;
  }
  forms.push_back(std::make_unique<AdjointFiles>(share));
  if (tangent)
    forms.push_back(std::make_unique<TangentFiles>());
  return forms;
}

} // namespace dpgen
