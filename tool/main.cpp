// dpgen: generate gather-form adjoint kernels from annotated C++ stencil
// kernels. Thin driver: parse options, run the pipeline (tool/lib), exit.
//
//   dpgen [options] <kernel.cpp>... --out-dir <dir> [-- <compiler flags>]
#include "lib/generate.hpp"

#include <llvm/Support/CommandLine.h>
#include <llvm/Support/FileSystem.h>
#include <llvm/Support/raw_ostream.h>

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
static cl::opt<bool> verbose("v", cl::desc("report written and unchanged files"),
                             cl::cat(category));

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
  cl::HideUnrelatedOptions(category);
  cl::SetVersionPrinter([](llvm::raw_ostream& os) { os << "dpgen " DPGEN_VERSION "\n"; });
  if (!cl::ParseCommandLineOptions(tool_argc, argv,
                                   "dpgen: adjoint (reverse-mode) kernels for annotated C++ "
                                   "stencil kernels\n\n"
                                   "  dpgen [options] <kernel.cpp>... --out-dir <dir> "
                                   "[-- <compiler flags>]\n",
                                   &llvm::errs()))
    return 2;
  if (!llvm::sys::fs::is_directory(resource_dir + "/include")) {
    llvm::errs() << "dpgen: error: Clang resource directory '" << resource_dir
                 << "' has no include/ (pass --resource-dir=$(clang-19 -print-resource-dir))\n";
    return 2;
  }
  dpgen::GenerateOptions opts;
  opts.frontend.compiler_args = compiler_args;
  opts.frontend.resource_dir = resource_dir;
  opts.frontend.driver = DPGEN_CLANG_DRIVER;
  opts.out_dir = out_dir;
  opts.verbose = verbose;
  opts.stamp = stamp;
  return dpgen::generate(std::vector<std::string>(inputs.begin(), inputs.end()), opts);
}
