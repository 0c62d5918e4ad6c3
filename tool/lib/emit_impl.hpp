// Emit (phase 6), the adjoint's parts shared by emit.cpp (the gather and
// scatter loops, the entry points) and emit_staged.cpp (kernels with work
// arrays, in-place arrays).
#pragma once

#include "emit_util.hpp"
#include "loop_plan.hpp"

#include <map>
#include <string>

namespace dpgen::adjoint {

// emit.cpp

/// The adjoint's parameters. `shaped`: arrays of rows as the kernel declares
/// them (`const double (*a)[64]`); otherwise every array is a flat pointer.
std::string param_list(const Kernel& k, bool shaped = true);
/// The body of one adjoint function: its gather and scatter loops as `plan` says.
void emit_body(Code& out, const LoopPlan& plan);
/// The copy of an in-place array's seed (emit_inout_prologue).
std::string seed_buffer(const Kernel& k, const std::string& array);

// emit_staged.cpp

/// The names under which an adjoint reads the shape of an output view: its
/// seed's (`un` -> `un_adj`); in a stage of a staged adjoint a work array's
/// seed is a buffer, laid out like the seed's view (`flux_adj.view()`).
std::map<std::string, std::string> seed_names(const Kernel& k, bool stage);
/// A kernel with work arrays: one adjoint per nest, and `fn_name`, the driver
/// that recomputes the work arrays and runs them backwards.
void emit_staged(Code& code, const LoopPlan& plan, const std::string& fn_name);
/// An in-place array's seed handling at the top of its adjoint's entry point.
void emit_inout_prologue(Code& code, const Kernel& k);

} // namespace dpgen::adjoint
