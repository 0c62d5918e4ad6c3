// Lower (phase 2): what find.cpp calls to turn one DPGEN_KERNEL function of
// the Clang AST into kernel IR (lower.cpp), checked against the output rules
// (check.hpp).
#pragma once

#include "ir.hpp"

#include <string>

namespace clang {
class ASTContext;
class Decl;
class FunctionDecl;
} // namespace clang

namespace dpgen {

/// The dpgen annotation of a declaration ("dpgen.kernel" for DPGEN_KERNEL,
/// "dpgen.in", ...), or "" if it has none.
std::string annotation(const clang::Decl* d);

/// Lowers kernel `fn` into `out` and checks it. Errors go to the context's
/// diagnostics (`file:line:col: error: ...`): every error in the kernel's
/// statements, or else every rule the lowered kernel breaks. Returns
/// false if any error was reported.
bool lower_kernel(clang::ASTContext& ctx, const clang::FunctionDecl* fn, Kernel& out);

} // namespace dpgen
