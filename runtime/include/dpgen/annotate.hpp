// dpgen annotation macros: mark a kernel and its differentiable inputs/outputs.
// Under Clang (which is what the dpgen tool parses with) they become
// annotate attributes ([[clang::annotate]] in C++, the GNU spelling in C, so
// the header serves .c kernels too); under any other compiler they expand to
// nothing, so the forward kernel builds unchanged and without warnings.
#pragma once

#if defined(__clang__) && defined(__cplusplus)
/// Marks a function as a kernel whose adjoint dpgen generates.
#define DPGEN_KERNEL [[clang::annotate("dpgen.kernel")]]
/// Marks a pointer parameter as a differentiable input (read only).
#define DPGEN_IN [[clang::annotate("dpgen.in")]]
/// Marks a pointer parameter as an output (written; read back only where the
/// same iteration or an earlier loop nest stored it).
#define DPGEN_OUT [[clang::annotate("dpgen.out")]]
/// Marks an array parameter as constant: not differentiated, no adjoint in
/// the generated signature (what an unmarked array is, said explicitly).
#define DPGEN_CONST [[clang::annotate("dpgen.const")]]
/// Marks a pointer parameter updated in place, element by element (each
/// iteration reads and writes its own elements: u[i] += dt * f[i]).
#define DPGEN_INOUT [[clang::annotate("dpgen.inout")]]
#elif defined(__clang__)
#define DPGEN_KERNEL __attribute__((annotate("dpgen.kernel")))
#define DPGEN_IN __attribute__((annotate("dpgen.in")))
#define DPGEN_OUT __attribute__((annotate("dpgen.out")))
#define DPGEN_CONST __attribute__((annotate("dpgen.const")))
#define DPGEN_INOUT __attribute__((annotate("dpgen.inout")))
#else
#define DPGEN_KERNEL
#define DPGEN_IN
#define DPGEN_OUT
#define DPGEN_CONST
#define DPGEN_INOUT
#endif
