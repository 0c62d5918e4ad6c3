// libFuzzer target over the generator's front half: mutated kernel sources go
// through lowering, scheduling and emission of the adjoint and the tangent
// files. The tool must never crash or hang, and every kernel it accepts must
// produce code that compiles: each generated file is parsed by Clang, and a
// failure aborts (a finding).
//
// Environment (run_seeds.py sets it to run the tree's kernels as seeds):
//   DPGEN_FUZZ_EXPECT     accept | reject: an input the generator rejects
//                         (accepts) is a finding: a seed that stopped being
//                         accepted, or a truncated one, cannot pass unseen
//                         (and each input is generated once, unless
//                         DPGEN_FUZZ_RECHECK=1; without DPGEN_FUZZ_EXPECT, a
//                         second time, to check that the output repeats);
//   DPGEN_FUZZ_RECHECK    1: with DPGEN_FUZZ_EXPECT, generate a second time all
//                         the same (run_seeds.py sets it for a sample of seeds);
//   DPGEN_FUZZ_NAME       the input's file name (default fuzz.cpp; fuzz.c
//                         lowers it as C);
//   DPGEN_FUZZ_STD        the C++ standard of the kernel and of the check that
//                         the generated code compiles (default c++17);
//   DPGEN_FUZZ_MAX_BYTES  larger inputs are skipped (default 8192: mutations);
//   DPGEN_FUZZ_COMPILE    0: no parse of the generated files (run_seeds.py, for
//                         the seeds whose generated code the test build compiles
//                         anyway, but a sample; default 1).
#include "lib/derive.hpp"
#include "lib/emit_file.hpp"
#include "lib/emit_tangent.hpp"
#include "lib/find.hpp"
#include "lib/hoist.hpp"
#include "lib/loop_plan.hpp"
#include "lib/schedule.hpp"
#include "lib/share.hpp"

#include <clang/Frontend/FrontendActions.h>
#include <clang/Tooling/Tooling.h>
#include <llvm/Support/raw_ostream.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace {

std::string read_file(const std::string& path) {
  std::ifstream f(path);
  if (!f) {
    std::fprintf(stderr, "fuzz_generator: cannot read %s\n", path.c_str());
    std::abort();
  }
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

const std::string& annotate_header() {
  static const std::string text =
      read_file(std::string(DPGEN_RUNTIME_INCLUDE_DIR) + "/dpgen/annotate.hpp");
  return text;
}

// The headers the kernels may include: annotate.hpp, and the style corpus's
// class headers (array views, member-kernel classes), by the names the seeds
// use ("include/user_views.hpp") and the names they use among themselves;
// and the runtime headers generated code includes (view_buffer.hpp: a staged
// adjoint's view outputs; row_pointers.hpp: rows as nested vectors;
// checked_probe.hpp: the checked entry point's probe of data-dependent
// accesses). A header missing here makes every seed whose generated code
// includes it fail to parse.
const std::vector<std::pair<std::string, std::string>>& headers() {
  static const std::vector<std::pair<std::string, std::string>> h = [] {
    std::vector<std::pair<std::string, std::string>> out = {
        {"dpgen/annotate.hpp", annotate_header()}};
    for (const char* name :
         {"dpgen/view_buffer.hpp", "dpgen/row_pointers.hpp", "dpgen/checked_probe.hpp"})
      out.push_back({name, read_file(std::string(DPGEN_RUNTIME_INCLUDE_DIR) + "/" + name)});
    for (const char* name : {"user_views.hpp", "member_classes.hpp", "boundary_kinds.hpp"}) {
      std::string text = read_file(std::string(DPGEN_STYLE_INCLUDE_DIR) + "/" + name);
      out.push_back({name, text});
      out.push_back({std::string("include/") + name, text});
    }
    return out;
  }();
  return h;
}

std::string env(const char* name, const char* fallback) {
  const char* v = std::getenv(name);
  return v && *v ? v : fallback;
}

struct Settings {
  std::string expect = env("DPGEN_FUZZ_EXPECT", "");
  bool recheck = expect.empty() || env("DPGEN_FUZZ_RECHECK", "0") == "1";
  std::string name = env("DPGEN_FUZZ_NAME", "fuzz.cpp");
  std::string std = env("DPGEN_FUZZ_STD", "c++17");
  size_t max_bytes = bytes(env("DPGEN_FUZZ_MAX_BYTES", "8192"));
  bool compile = env("DPGEN_FUZZ_COMPILE", "1") != "0";

  static size_t bytes(const std::string& v) {
    char* end = nullptr;
    const unsigned long long n = std::strtoull(v.c_str(), &end, 10);
    if (v.empty() || *end || v[0] == '-' || n == 0) {
      llvm::errs() << "fuzz: DPGEN_FUZZ_MAX_BYTES=" << v << " is not a positive byte count\n";
      std::abort();
    }
    return static_cast<size_t>(n);
  }
};

const Settings& settings() {
  static const Settings s;
  return s;
}

dpgen::FrontendOptions options(bool quiet = true) {
  dpgen::FrontendOptions o;
  o.resource_dir = DPGEN_CLANG_RESOURCE_DIR;
  o.driver = DPGEN_CLANG_DRIVER;
  o.quiet = quiet;
  // (lowering a .c file drops a C++ -std=: find.cpp, language_flag's caller)
  o.compiler_args = {"-std=" + settings().std};
  return o;
}

// Parses a generated source with its header (`fuzz_<form>.hpp`, the name the
// source includes); true when it compiles.
bool compiles(const dpgen::EmittedFile& f, const std::string& form) {
  // (-I.: the mapped headers include each other by these names, as
  // include/member_classes.hpp includes "dpgen/annotate.hpp")
  std::vector<std::string> args = {"-std=" + settings().std, "-w", "-I.",
                                   "-resource-dir=" DPGEN_CLANG_RESOURCE_DIR};
  clang::tooling::FileContentMappings files = {{"fuzz_" + form + ".hpp", f.header}};
  for (const auto& [name, text] : headers())
    files.push_back({name, text});
  return clang::tooling::runToolOnCodeWithArgs(
      std::make_unique<clang::SyntaxOnlyAction>(), f.source, args, "fuzz_" + form + ".cpp",
      DPGEN_CLANG_DRIVER, std::make_shared<clang::PCHContainerOperations>(), files);
}

struct Generated {
  dpgen::EmittedFile adjoint, tangent;
};

// The phases after lowering, as generate.cpp runs them: derive, schedule,
// plan the loops, hoist their invariants, share values along strips, emit;
// and the tangent file.
Generated generate(const std::vector<dpgen::Kernel>& kernels) {
  std::vector<dpgen::AdjointPlan> plans;
  plans.reserve(kernels.size()); // the loop plans point into this vector
  for (const auto& k : kernels) {
    dpgen::Partials partials = dpgen::derive(k);
    plans.push_back(dpgen::schedule(k, partials));
  }
  std::vector<dpgen::LoopPlan> loops;
  for (const auto& p : plans) {
    loops.push_back(dpgen::plan_loops(p));
    dpgen::hoist_invariants(loops.back());
    dpgen::share_shifted_values(loops.back());
  }
  std::vector<const dpgen::Kernel*> ks;
  for (const auto& k : kernels)
    ks.push_back(&k);
  return {dpgen::emit_file(loops, settings().name, "fuzz"),
          dpgen::emit_tangent_file(ks, settings().name, "fuzz")};
}

bool same(const dpgen::EmittedFile& a, const dpgen::EmittedFile& b) {
  return a.source == b.source && a.header == b.header;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const Settings& set = settings();
  if (size > set.max_bytes) {
    if (set.expect.empty())
      return 0; // (a mutation grown too large)
    llvm::errs() << "fuzz: a seed of " << size << " bytes is over DPGEN_FUZZ_MAX_BYTES ("
                 << set.max_bytes << ")\n";
    std::abort();
  }
  std::string code(reinterpret_cast<const char*>(data), size);
  std::vector<dpgen::Kernel> kernels;
  const bool accepted = dpgen::lower_code(code, set.name, options(), kernels, headers());
  if (!accepted && set.expect == "accept") {
    llvm::errs() << "fuzz: a seed expected to be accepted was rejected:\n";
    std::vector<dpgen::Kernel> ignored;
    dpgen::lower_code(code, set.name, options(/*quiet=*/false), ignored, headers());
    std::abort();
  }
  if (accepted && set.expect == "reject") {
    llvm::errs() << "fuzz: a seed expected to be rejected was accepted:\n" << code << "\n";
    std::abort();
  }
  if (!accepted)
    return 0; // rejected with a diagnostic: fine
  Generated f = generate(kernels);
  // The output is a function of the kernel alone: the same input again, in
  // the same process, gives the same text (no counters that survive a run).
  // Checked on every input of the fuzz run and on a sample of the seeds
  // (DPGEN_FUZZ_RECHECK): on all of them it doubled the seed runs' time.
  if (set.recheck) {
    std::vector<dpgen::Kernel> again;
    dpgen::lower_code(code, set.name, options(), again, headers());
    Generated f2 = generate(again);
    if (!same(f2.adjoint, f.adjoint) || !same(f2.tangent, f.tangent)) {
      llvm::errs() << "fuzz: the same kernel generated different code on a second run:\n"
                   << code << "\n";
      std::abort();
    }
  }
  if (!set.compile)
    return 0;
  for (const auto& [form, file] : {std::pair{"adjoint", &f.adjoint}, {"tangent", &f.tangent}}) {
    if (!compiles(*file, form)) {
      llvm::errs() << "fuzz: accepted kernel produced " << form << " code that does not compile:\n"
                   << file->source << "\n--- input ---\n"
                   << code << "\n";
      std::abort();
    }
  }
  return 0;
}
