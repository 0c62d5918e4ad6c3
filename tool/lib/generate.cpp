// The pipeline driver: the passes by name, for every input file: lower (with
// its checks) -> derive -> schedule -> plan -> emit -> output. All inputs are
// analysed before anything is written. `--print-after=<pass>` prints the IR
// a pass hands on (ir_text.hpp).
#include "generate.hpp"

#include "derive.hpp"
#include "ir_text.hpp"
#include "output.hpp"
#include "output_forms.hpp"
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
  const auto forms = output_forms(opts.torch, opts.tangent, opts.share);
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
      for (auto& k : kernels) {
        current = &k;
        print_after("lower", print_ir(k));
        pass = "derive";
        test_internal_error("derive");
        Partials partials = derive(k, &k.names); // 3. derive: each partial once
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
    // 5-6. plan and emit: each output form (output_forms.hpp) plans the loops
    // it prints and prints its files.
    FileIR ir;
    ir.input = input;
    ir.source_name = llvm::sys::path::filename(input).str();
    ir.stem = stem;
    ir.out_dir = opts.out_dir;
    ir.kernels = &kernels;
    ir.plans = &plans;
    ir.enter = [&](const char* name, const Kernel* k) {
      pass = name;
      current = k;
    };
    ir.print_after = [&](const char* name, const std::function<std::string()>& text) {
      if (opts.print_after.count(name))
        print_after(name, text());
    };
    try {
      for (const auto& form : forms)
        ok = form->add_files(ir, pending) && ok;
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
    // (sorted, so that the same inputs give the same file)
    std::string d = opts.stamp + ":";
    for (const auto& dep : std::set<std::string>(deps.begin(), deps.end())) {
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
