// Find (phase 1): Clang parses a kernel file (the compiler arguments are
// assembled here), an AST matcher finds the DPGEN_KERNEL function
// definitions of the main file, and each goes to lower.hpp. The front end's
// entry points, lower_file and lower_code (find.hpp).
#include "find.hpp"
#include "lower.hpp"

#include <clang/AST/ASTConsumer.h>
#include <clang/AST/ASTContext.h>
#include <clang/AST/Attr.h>
#include <clang/ASTMatchers/ASTMatchFinder.h>
#include <clang/ASTMatchers/ASTMatchers.h>
#include <clang/Basic/SourceManager.h>
#include <clang/Frontend/CompilerInstance.h>
#include <clang/Frontend/FrontendActions.h>
#include <clang/Tooling/Tooling.h>
#include <llvm/Support/MemoryBuffer.h>
#include <llvm/Support/Path.h>
#include <llvm/Support/VirtualFileSystem.h>

#include <cctype>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace dpgen {

namespace {

using namespace clang;
using namespace clang::ast_matchers;

// Matches every function definition carrying an annotation; the callback
// keeps those marked DPGEN_KERNEL in the main file.
class KernelCollector : public MatchFinder::MatchCallback {
public:
  KernelCollector(std::vector<Kernel>& out, bool& ok, std::string file)
      : out_(out), ok_(ok), file_(std::move(file)) {}

  void run(const MatchFinder::MatchResult& r) override {
    const auto* fn = r.Nodes.getNodeAs<FunctionDecl>("kernel");
    if (!fn || annotation(fn) != "dpgen.kernel")
      return;
    if (!r.SourceManager->isInMainFile(r.SourceManager->getExpansionLoc(fn->getLocation()))) {
      if (!fn->isTemplateInstantiation())
        elsewhere_.push_back(fn);
      return;
    }
    if (fn->isTemplateInstantiation())
      return; // lowered from its template (below)
    found_ = true;
    if (const FunctionTemplateDecl* t = fn->getDescribedFunctionTemplate()) {
      lower_instantiations(*r.Context, t);
      return;
    }
    Kernel k;
    if (lower_kernel(*r.Context, fn, k)) {
      k.file = file_;
      k.c_linkage = !r.Context->getLangOpts().CPlusPlus;
      out_.push_back(std::move(k));
    } else {
      ok_ = false;
    }
  }
  bool found() const { return found_; }
  /// Kernels defined in a file the main file includes.
  const std::vector<const FunctionDecl*>& elsewhere() const { return elsewhere_; }

private:
  // A template kernel: each instantiation the file makes (explicitly, or by
  // a call) is a kernel of its own, named uniquely (Kernel::template_name).
  void lower_instantiations(ASTContext& ctx, const FunctionTemplateDecl* t) {
    PrintingPolicy policy(ctx.getLangOpts());
    policy.SuppressTagKeyword = true;
    std::string head;
    llvm::raw_string_ostream hs(head);
    t->getTemplateParameters()->print(hs, ctx);
    head = hs.str();
    while (!head.empty() && head.back() == ' ')
      head.pop_back();
    // Each parameter's element (or scalar) type as the template spells it.
    std::map<std::string, std::string> generic, generic_scalars;
    for (const ParmVarDecl* p : t->getTemplatedDecl()->parameters()) {
      generic_scalars[p->getNameAsString()] = p->getType().getAsString(policy);
      QualType q = p->getType().getNonReferenceType();
      while (q->isPointerType() || q->isArrayType())
        q = q->isPointerType() ? q->getPointeeType() : QualType(q->getArrayElementTypeNoTypeQual(), 0);
      generic[p->getNameAsString()] = q.getUnqualifiedType().getAsString(policy);
    }
    std::set<std::string> names;
    bool any = false;
    for (const FunctionDecl* spec : t->specializations()) {
      if (!spec->doesThisDeclarationHaveABody())
        continue; // declared, not instantiated (or instantiated elsewhere)
      any = true;
      std::string args;
      llvm::raw_string_ostream as(args);
      printTemplateArgumentList(as, spec->getTemplateSpecializationArgs()->asArray(), policy);
      args = as.str();
      std::string suffix;
      for (char c : args)
        if (std::isalnum(static_cast<unsigned char>(c)))
          suffix += c;
        else if (c == '-')
          suffix += "m";
        else if (!suffix.empty() && suffix.back() != '_')
          suffix += '_';
      while (!suffix.empty() && suffix.back() == '_')
        suffix.pop_back();
      std::string name = t->getNameAsString() + "_" + suffix;
      while (!names.insert(name).second)
        name += "_";
      Kernel k;
      if (!lower_kernel(ctx, spec, k)) {
        ok_ = false;
        continue;
      }
      k.file = file_;
      k.template_name = k.name;
      k.name = name;
      k.template_head = head;
      k.template_args = args;
      k.generic_types = generic;
      k.generic_scalars = generic_scalars;
      out_.push_back(std::move(k));
    }
    if (!any) {
      auto& d = ctx.getDiagnostics();
      unsigned id = d.getCustomDiagID(
          DiagnosticsEngine::Error,
          "template kernel '%0' is not instantiated in this file: dpgen writes an adjoint per "
          "instantiation, so instantiate it here (template void %0<double>(...);) or call it "
          "[dpgen-signature]");
      d.Report(t->getLocation(), id) << t->getNameAsString();
      ok_ = false;
    }
  }

  std::vector<Kernel>& out_;
  bool& ok_;
  std::string file_;
  bool found_ = false;
  std::vector<const FunctionDecl*> elsewhere_;
};

class Consumer : public ASTConsumer {
public:
  Consumer(std::vector<Kernel>& out, bool& ok, std::string file, std::vector<std::string>* deps)
      : collector_(out, ok, file), ok_(ok), deps_(deps) {
    // A kernel: an annotated function definition (DPGEN_KERNEL).
    auto kernel = functionDecl(isDefinition(), hasAttr(attr::Annotate)).bind("kernel");
    finder_.addMatcher(kernel, &collector_);
  }

  void HandleTranslationUnit(ASTContext& ctx) override {
    if (deps_) {
      const auto& sm = ctx.getSourceManager();
      for (auto it = sm.fileinfo_begin(); it != sm.fileinfo_end(); ++it)
        deps_->push_back(it->first.getName().str());
    }
    if (ctx.getDiagnostics().hasErrorOccurred()) {
      ok_ = false;
      return; // a syntax error was reported by Clang already
    }
    finder_.matchAST(ctx);
    auto& d = ctx.getDiagnostics();
    const auto& sm = ctx.getSourceManager();
    // A kernel defined in an included file gets no adjoint from this run: said,
    // not silently left out.
    const auto main_file = sm.getFileEntryRefForID(sm.getMainFileID());
    const std::string main_name =
        main_file ? llvm::sys::path::filename(main_file->getName()).str() : "this file";
    for (const FunctionDecl* fn : collector_.elsewhere())
      d.Report(fn->getLocation(),
               d.getCustomDiagID(DiagnosticsEngine::Warning,
                                 "kernel '%0' is defined in a file that '%1' includes: dpgen "
                                 "writes adjoints for the kernels defined in the file it is run "
                                 "on; run it on the file that defines this kernel as well "
                                 "[dpgen-kernel-elsewhere]"))
          << fn->getQualifiedNameAsString() << main_name;
    if (!collector_.found() && ok_) {
      unsigned id = d.getCustomDiagID(DiagnosticsEngine::Error,
                                      "no DPGEN_KERNEL function in this file (mark a kernel "
                                      "with DPGEN_KERNEL from dpgen/annotate.hpp) [dpgen-no-kernel]");
      d.Report(sm.getLocForStartOfFile(sm.getMainFileID()), id);
      ok_ = false;
    }
  }

private:
  KernelCollector collector_;
  MatchFinder finder_;
  bool& ok_;
  std::vector<std::string>* deps_;
};

class Action : public ASTFrontendAction {
public:
  Action(std::vector<Kernel>& out, bool& ok, std::string file, std::vector<std::string>* deps)
      : out_(out), ok_(ok), file_(std::move(file)), deps_(deps) {}
  std::unique_ptr<ASTConsumer> CreateASTConsumer(CompilerInstance&, llvm::StringRef) override {
    return std::make_unique<Consumer>(out_, ok_, file_, deps_);
  }

private:
  std::vector<Kernel>& out_;
  bool& ok_;
  std::string file_;
  std::vector<std::string>* deps_;
};

} // namespace

namespace {

bool is_c_file(const std::string& file) {
  return file.size() > 2 && file.compare(file.size() - 2, 2, ".c") == 0;
}

// The language the user's flags name (`-x c`, `-xc++`, `--language=c`,
// `--language c`; the last one wins), or "" where they name none.
std::string language_flag(const std::vector<std::string>& flags) {
  std::string lang;
  for (size_t i = 0; i < flags.size(); ++i) {
    const std::string& a = flags[i];
    if ((a == "-x" || a == "--language") && i + 1 < flags.size())
      lang = flags[++i];
    else if (a.rfind("--language=", 0) == 0)
      lang = a.substr(11);
    else if (a.rfind("-x", 0) == 0 && a.size() > 2)
      lang = a.substr(2);
  }
  return lang;
}

// The kernel file's language: what the user's flags say (they win), else C
// for a `.c` file and C++ for any other. Its standard: the user's -std= for
// that language, else C11 / C++17; -std= flags for the other language (meant
// for the rest of a mixed build) are dropped. dpgen adds `-x` only where the
// user gave none.
std::vector<std::string> compiler_args(const FrontendOptions& opts, const std::string& file) {
  const std::string lang = language_flag(opts.compiler_args);
  bool c = lang.empty() ? is_c_file(file) : (lang == "c" || lang == "c-header");
  std::vector<std::string> args = {opts.driver, "-fsyntax-only"};
  if (!opts.resource_dir.empty())
    args.push_back("-resource-dir=" + opts.resource_dir);
  std::vector<std::string> rest;
  bool has_std = false;
  for (const auto& a : opts.compiler_args) {
    if (a.rfind("-std=", 0) == 0 || a.rfind("--std=", 0) == 0) {
      bool cxx_std = a.find("++") != std::string::npos;
      if (cxx_std == c)
        continue; // the other language's standard
      has_std = true;
    }
    if (a == "-ansi")
      has_std = true; // -ansi is C89 in C, C++98 in C++: the user's choice
    rest.push_back(a);
  }
  if (!has_std)
    args.push_back(c ? "-std=c11" : "-std=c++17");
  if (lang.empty())
    args.push_back(c ? "-xc" : "-xc++");
  args.insert(args.end(), rest.begin(), rest.end());
  return args;
}

bool run(std::vector<std::string> args, const std::string& file, const FrontendOptions& opts,
         std::vector<Kernel>& kernels, std::vector<std::string>* deps,
         llvm::IntrusiveRefCntPtr<llvm::vfs::FileSystem> files) {
  args.push_back(file);
  bool ok = true;
  std::vector<Kernel> found;
  auto fm = llvm::makeIntrusiveRefCnt<FileManager>(FileSystemOptions(), files);
  tooling::ToolInvocation inv(args, std::make_unique<Action>(found, ok, file, deps), fm.get());
  IgnoringDiagConsumer ignore;
  if (opts.quiet)
    inv.setDiagnosticConsumer(&ignore);
  if (!inv.run())
    ok = false;
  kernels.insert(kernels.end(), found.begin(), found.end());
  return ok;
}

} // namespace

bool lower_file(const std::string& file, const FrontendOptions& opts, std::vector<Kernel>& kernels,
                std::vector<std::string>* deps) {
  return run(compiler_args(opts, file), file, opts, kernels, deps, llvm::vfs::getRealFileSystem());
}

bool lower_code(const std::string& code, const std::string& name, const FrontendOptions& opts,
                std::vector<Kernel>& kernels,
                const std::vector<std::pair<std::string, std::string>>& headers) {
  // The real file system (for <cmath>) under an in-memory one with the code.
  auto memory = llvm::makeIntrusiveRefCnt<llvm::vfs::InMemoryFileSystem>();
  memory->addFile("/dpgen-memory/" + name, 0, llvm::MemoryBuffer::getMemBufferCopy(code));
  for (const auto& [path, text] : headers)
    memory->addFile("/dpgen-memory/include/" + path, 0, llvm::MemoryBuffer::getMemBufferCopy(text));
  auto overlay =
      llvm::makeIntrusiveRefCnt<llvm::vfs::OverlayFileSystem>(llvm::vfs::getRealFileSystem());
  overlay->pushOverlay(memory);
  auto args = compiler_args(opts, name);
  args.push_back("-I/dpgen-memory/include");
  return run(args, "/dpgen-memory/" + name, opts, kernels, nullptr, overlay);
}

} // namespace dpgen
