// dpgen: generate gather-form adjoint kernels from annotated C++ stencil
// kernels. Thin driver: parse options, run the pipeline (tool/lib), exit.
//
//   dpgen [options] <kernel.cpp>... --out-dir <dir> [-- <compiler flags>]
#include "lib/generate.hpp"
#include "lib/ir_text.hpp"

#include <llvm/Support/CommandLine.h>
#include <llvm/Support/FileSystem.h>
#include <llvm/Support/Path.h>
#include <llvm/Support/raw_ostream.h>

#include <algorithm>

namespace cl = llvm::cl;

static cl::OptionCategory category("dpgen options");
static cl::list<std::string> inputs(cl::Positional, cl::desc("<kernel.cpp>..."), cl::OneOrMore,
                                    cl::cat(category));
static cl::opt<std::string> out_dir("out-dir", cl::desc("directory for <stem>_adjoint.{hpp,cpp}"),
                                    cl::value_desc("dir"), cl::Required, cl::cat(category));
static cl::opt<std::string> resource_dir("resource-dir",
                                         cl::desc("Clang resource directory (builtin headers)"),
                                         cl::init(DPGEN_CLANG_RESOURCE_DIR), cl::cat(category));
static cl::opt<std::string> stamp("stamp",
                                  cl::desc("after success, touch <file> and write <file>.d (a "
                                           "make-style list of every file read)"),
                                  cl::value_desc("file"), cl::cat(category));
static cl::opt<bool> tangent("tangent",
                             cl::desc("also write <stem>_tangent.{hpp,cpp}: forward-mode "
                                      "(Jacobian-vector product) kernels"),
                             cl::cat(category));
static cl::opt<bool> torch("torch",
                           cl::desc("write <stem>_torch.{hpp,cpp} (PyTorch autograd ops calling the "
                                    "kernels and their adjoints) instead of the adjoint files"),
                           cl::cat(category));
static cl::opt<bool> no_share("no-share",
                              cl::desc("leave out the pass share: each adjoint cell computes the "
                                       "values it reads at neighbouring iterations itself instead "
                                       "of reading them from its strip's buffer (the same "
                                       "results; for comparing)"),
                              cl::cat(category));
static cl::opt<bool> verbose("v",
                             cl::desc("report written and unchanged files, and where "
                                      "dpgen/annotate.hpp is found"),
                             cl::cat(category));

// The folder holding dpgen/annotate.hpp, added to the compiler flags so that
// kernels include it without -I: installed, <this executable's folder>/
// DPGEN_INCLUDE_FROM_BIN (<prefix>/bin/../include); in the build tree, the
// source tree's runtime/include. Empty if neither has it.
static std::string runtime_include_dir(const char* argv0) {
  auto has_annotate = [](const std::string& dir) {
    return llvm::sys::fs::exists(dir + "/dpgen/annotate.hpp");
  };
  std::string exe = llvm::sys::fs::getMainExecutable(argv0, (void*)&runtime_include_dir);
  if (!exe.empty()) {
    llvm::SmallString<256> dir(llvm::sys::path::parent_path(exe));
    llvm::sys::path::append(dir, DPGEN_INCLUDE_FROM_BIN);
    llvm::sys::path::remove_dots(dir, /*remove_dot_dot=*/true);
    if (has_annotate(std::string(dir)))
      return std::string(dir);
  }
  return has_annotate(DPGEN_SOURCE_INCLUDE_DIR) ? DPGEN_SOURCE_INCLUDE_DIR : "";
}

int main(int argc, const char** argv) {
  // Everything after `--` goes to the compiler.
  std::vector<std::string> compiler_args;
  int tool_argc = argc;
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]) == "--") {
      tool_argc = i;
      for (int j = i + 1; j < argc; ++j)
        compiler_args.push_back(argv[j]);
      break;
    }
  // --print-after=<pass>[,<pass>] is read here, not by llvm::cl: LLVM's own
  // libraries register an option of that name (for its pass manager).
  std::vector<std::string> print_after;
  std::vector<const char*> tool_argv(argv, argv + tool_argc);
  for (size_t i = 1; i < tool_argv.size();) {
    std::string a = tool_argv[i];
    std::string value;
    size_t erase = 0;
    for (const char* flag : {"--print-after", "-print-after"})
      if (a == flag && i + 1 < tool_argv.size()) {
        value = tool_argv[i + 1];
        erase = 2;
      } else if (a.rfind(std::string(flag) + "=", 0) == 0) {
        value = a.substr(std::string(flag).size() + 1);
        erase = 1;
      }
    if (!erase) {
      ++i;
      continue;
    }
    for (size_t from = 0, to; from <= value.size(); from = to + 1) {
      to = value.find(',', from);
      if (to == std::string::npos)
        to = value.size();
      print_after.push_back(value.substr(from, to - from));
    }
    tool_argv.erase(tool_argv.begin() + i, tool_argv.begin() + i + erase);
  }
  tool_argc = int(tool_argv.size());
  cl::HideUnrelatedOptions(category);
  cl::SetVersionPrinter([](llvm::raw_ostream& os) { os << "dpgen " DPGEN_VERSION "\n"; });
  if (!cl::ParseCommandLineOptions(tool_argc, tool_argv.data(),
                                   "dpgen: adjoint (reverse-mode) kernels for annotated C++ "
                                   "stencil kernels\n\n"
                                   "  dpgen [options] <kernel.cpp>... --out-dir <dir> "
                                   "[-- <compiler flags>]\n\n"
                                   "  --print-after=<pass>[,<pass>...]: print the IR after "
                                   "the passes lower, derive, schedule, plan, hoist (stdout)\n",
                                   &llvm::errs()))
    return 2;
  if (!llvm::sys::fs::is_directory(resource_dir + "/include")) {
    llvm::errs() << "dpgen: error: Clang resource directory '" << resource_dir
                 << "' has no include/ (pass --resource-dir=$(clang-19 -print-resource-dir))\n";
    return 2;
  }
  // After the user's flags: an -I of theirs comes first in the search order.
  const std::string runtime_include = runtime_include_dir(argv[0]);
  if (!runtime_include.empty())
    compiler_args.push_back("-I" + runtime_include);
  if (verbose)
    llvm::errs() << "dpgen: dpgen/annotate.hpp from "
                 << (runtime_include.empty() ? "the compiler flags only" : runtime_include) << "\n";
  dpgen::GenerateOptions opts;
  for (const auto& p : print_after) {
    const auto& known = dpgen::pass_names();
    if (std::find(known.begin(), known.end(), p) == known.end()) {
      std::string list;
      for (const auto& n : known)
        list += (list.empty() ? "" : ", ") + n;
      llvm::errs() << "dpgen: error: --print-after: no pass '" << p << "' (the passes: " << list
                   << ")\n";
      return 2;
    }
    opts.print_after.insert(p);
  }
  opts.frontend.compiler_args = compiler_args;
  opts.frontend.resource_dir = resource_dir;
  opts.frontend.driver = DPGEN_CLANG_DRIVER;
  opts.out_dir = out_dir;
  opts.verbose = verbose;
  opts.tangent = tangent;
  opts.stamp = stamp;
  opts.torch = torch;
  opts.share = !no_share;
  return dpgen::generate(std::vector<std::string>(inputs.begin(), inputs.end()), opts);
}
