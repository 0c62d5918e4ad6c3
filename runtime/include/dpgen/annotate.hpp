// dpgen annotation macros: mark a kernel and its differentiable inputs/outputs.
// Under Clang (which is what the dpgen tool parses with) they become
// [[clang::annotate]] attributes; under any other compiler they expand to
// nothing, so the forward kernel builds unchanged and without warnings.
#pragma once

#if defined(__clang__)
/// Marks a function as a kernel whose adjoint dpgen generates.
#define DPGEN_KERNEL [[clang::annotate("dpgen.kernel")]]
/// Marks a pointer parameter as a differentiable input (read only).
#define DPGEN_IN [[clang::annotate("dpgen.in")]]
/// Marks a pointer parameter as an output (written, never read).
#define DPGEN_OUT [[clang::annotate("dpgen.out")]]
#else
#define DPGEN_KERNEL
#define DPGEN_IN
#define DPGEN_OUT
#endif
