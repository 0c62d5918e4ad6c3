// The pipeline driver: the passes by name, for every input file: lower (with
// its checks) -> derive -> schedule -> plan -> emit -> output. All inputs are
// analysed before anything is written. `--print-after=<pass>` prints the IR
// a pass hands on (ir_text.hpp).
#include "generate.hpp"

#include "derive.hpp"
#include "emit_file.hpp"
#include "emit_tangent.hpp"
#include "emit_torch.hpp"
#include "ir_text.hpp"
#include "loop_plan.hpp"
#include "output.hpp"
#include "schedule.hpp"

#include <fmt/format.h>
#include <llvm/Support/FileSystem.h>
#include <llvm/Support/Path.h>
#include <llvm/Support/raw_ostream.h>

#include <set>

namespace dpgen {

int generate(const std::vector<std::string>& inputs, const GenerateOptions& opts) {
  bool ok = true;
  std::vector<PendingFile> pending;
  std::set<std::string> stems;
  std::vector<std::string> deps;
  for (const auto& input : inputs) {
    std::vector<Kernel> kernels;
    if (!llvm::sys::fs::exists(input)) {
      llvm::errs() << input << ": error: no such file\n";
      ok = false;
      continue;
    }
    // 1-2. find, lower and check (find.hpp)
    if (!lower_file(input, opts.frontend, kernels, &deps)) {
      ok = false;
      continue;
    }
    // The passes, each a function over the IR (ir_text.hpp prints what each
    // hands on): lower (with its checks) -> derive -> schedule -> plan.
    auto print_after = [&](const char* pass, const std::string& text) {
      if (opts.print_after.count(pass))
        llvm::outs() << "// -- IR after " << pass << "\n" << text;
    };
    // A broken invariant in a pass (an exception) is reported at the kernel,
    // as a bug in dpgen; nothing is written.
    std::string pass;
    const Kernel* current = nullptr;
    auto internal = [&](const std::exception& e) {
      SourcePos at = current ? current->pos : SourcePos{input, 1, 1};
      llvm::errs() << fmt::format("{}:{}:{}: error: {} [dpgen-internal]\n", at.file, at.line,
                                  at.col,
                                  internal_error_message(current ? current->name : "in " + input, pass,
                                                         e.what()));
      ok = false;
    };
    std::vector<AdjointPlan> plans;
    try {
      for (const auto& k : kernels) {
        current = &k;
        print_after("lower", print_ir(k));
        pass = "derive";
        test_internal_error("derive");
        Partials partials = derive(k); // 3. derive: each partial once
        if (opts.print_after.count("derive"))
          print_after("derive", print_partials(k, partials));
        pass = "schedule";
        plans.push_back(schedule(k, partials)); // 4. schedule
        print_after("schedule", print_schedule(plans.back()));
        for (const auto& r : plans.back().remarks)
          llvm::errs() << fmt::format("{}:{}:{}: remark: {}\n", r.pos.file, r.pos.line,
                                      r.pos.col, r.text);
      }
    } catch (const std::exception& e) {
      internal(e);
      continue;
    }
    std::string stem = llvm::sys::path::stem(input).str();
    if (!stems.insert(stem).second) {
      llvm::errs() << input << ": error: another input has the same name '" << stem
                   << "'; generated files would collide\n";
      ok = false;
      continue;
    }
    try {
      current = nullptr; // the passes below work on all of the file's kernels
      pass = "emit";
      if (opts.torch) { // PyTorch ops instead of the adjoints (emit_torch.hpp)
        pass = "torch";
        ok = add_torch_files(plans, input, opts.out_dir, pending) && ok;
        continue;
      }
      std::vector<LoopPlan> loops; // 5. plan the loops
      for (const auto& p : plans) {
        current = p.kernel;
        pass = "plan";
        test_internal_error("plan");
        loops.push_back(plan_loops(p));
        print_after("plan", print_plan(loops.back()));
        if (opts.print_after.count("plan"))
          print_after("plan", print_forward_plan(plan_forward(*p.kernel)));
      }
      current = nullptr;
      pass = "emit";
      EmittedFile f = emit_file(loops, llvm::sys::path::filename(input).str(), stem); // 6. emit
      llvm::SmallString<256> hpp(opts.out_dir), cpp(opts.out_dir);
      llvm::sys::path::append(hpp, stem + "_adjoint.hpp");
      llvm::sys::path::append(cpp, stem + "_adjoint.cpp");
      pending.push_back({std::string(hpp), f.header});
      pending.push_back({std::string(cpp), f.source});
      llvm::SmallString<256> khpp(opts.out_dir);
      llvm::sys::path::append(khpp, stem + "_kernels.hpp");
      pending.push_back({std::string(khpp), f.kernels});
      if (opts.tangent) {
        std::vector<const Kernel*> ks;
        for (const auto& k : kernels)
          ks.push_back(&k);
        pass = "tangent";
        EmittedFile t = emit_tangent_file(ks, llvm::sys::path::filename(input).str(), stem);
        llvm::SmallString<256> thpp(opts.out_dir), tcpp(opts.out_dir);
        llvm::sys::path::append(thpp, stem + "_tangent.hpp");
        llvm::sys::path::append(tcpp, stem + "_tangent.cpp");
        pending.push_back({std::string(thpp), t.header});
        pending.push_back({std::string(tcpp), t.source});
      }
    } catch (const std::exception& e) {
      internal(e);
    }
  }
  if (!ok) {
    llvm::errs() << "dpgen: errors found; no file written\n";
    return 1;
  }
  if (auto ec = llvm::sys::fs::create_directories(opts.out_dir)) {
    llvm::errs() << opts.out_dir << ": error: cannot create output directory: " << ec.message()
                 << "\n";
    return 1;
  }
  std::string error; // 7. output
  int written = 0;
  if (!write_if_changed(pending, error, &written)) {
    llvm::errs() << "error: " << error << "\n";
    return 1;
  }
  if (!opts.stamp.empty()) {
    // Make-style depfile: "<stamp>: <dep> <dep> ...", spaces escaped.
    std::string d = opts.stamp + ":";
    std::set<std::string> seen;
    for (const auto& dep : deps)
      if (seen.insert(dep).second) {
        std::string esc;
        for (char c : dep)
          esc += c == ' ' ? std::string("\\ ") : std::string(1, c);
        d += " \\\n  " + esc;
      }
    d += "\n";
    if (!write_if_changed({{opts.stamp + ".d", d}}, error)) {
      llvm::errs() << "error: " << error << "\n";
      return 1;
    }
    std::error_code ec;
    llvm::raw_fd_ostream stamp(opts.stamp, ec); // (re)written: a new timestamp
    if (ec) {
      llvm::errs() << opts.stamp << ": error: " << ec.message() << "\n";
      return 1;
    }
  }
  if (opts.verbose)
    llvm::errs() << fmt::format("dpgen: {} file(s) written, {} unchanged\n", written,
                                pending.size() - written);
  return 0;
}

} // namespace dpgen
