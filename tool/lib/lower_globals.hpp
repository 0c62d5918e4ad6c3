// Lowering, the globals (lower_globals.cpp): the variables of namespace
// scope the kernel body reads, as Params (Param::global) bound in
// Signature::header like parameters. Included by lower_impl.hpp only.
#pragma once

namespace clang {
class Stmt;
} // namespace clang

namespace dpgen::lowering {

class Lowerer;

class Globals {
public:
  explicit Globals(Lowerer& lowerer) : L(lowerer) {}
  // Finds the globals `body` reads and binds each (a read-only scalar or a
  // constant table: a constant; a DPGEN_IN array: differentiated; a write
  // or an unannotated array: an error).
  void lower(const clang::Stmt* body);

private:
  Lowerer& L;
};

} // namespace dpgen::lowering
