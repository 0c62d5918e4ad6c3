// PyTorch glue for the ops dpgen generates (`dpgen --torch`, CMake dpgen_add_torch_ops): the
// argument checks every op runs before it touches a data pointer, each failing with a
// c10::Error (a RuntimeError in Python) that names the op and the argument. Needs libtorch;
// nothing else in the runtime includes this header.
#pragma once

#include <torch/torch.h>

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace dpgen::torch_ops {

/// The dtype a kernel's element type needs ("double" -> float64, "int" -> int32, ...).
template <typename T> constexpr c10::ScalarType dtype_of() {
  return c10::CppTypeToScalarType<T>::value;
}

/// A tensor argument the op passes to a kernel by data pointer: defined, on the CPU, of the
/// kernel's element type (no silent conversion: a float64 kernel takes float64 tensors),
/// contiguous (no hidden copy on the hot path), and not aliasing memory the op writes.
template <typename T>
void check_array(const at::Tensor& t, const char* op, const char* arg, const char* elem) {
  TORCH_CHECK(t.defined(), op, ": argument '", arg, "' is an undefined tensor");
  TORCH_CHECK(t.device().is_cpu(), op, ": argument '", arg, "' is on ", t.device(),
              "; dpgen's kernels run on the CPU (move it with .cpu())");
  TORCH_CHECK(t.scalar_type() == dtype_of<T>(), op, ": argument '", arg, "' has dtype ",
              t.scalar_type(), " but the kernel is written for ", elem, " (", dtype_of<T>(),
              "): convert it with .to(", dtype_of<T>(), ")");
  TORCH_CHECK(t.is_contiguous(), op, ": argument '", arg, "' (sizes ", t.sizes(), ", strides ",
              t.strides(), ") is not contiguous: pass .contiguous()");
}

/// `arg` holds at least `needed` elements: one past the largest index the kernel's loops
/// reach for these sizes (computed from the kernel's index expressions).
inline void check_extent(const at::Tensor& t, std::int64_t needed, const char* op,
                         const char* arg, const char* sizes) {
  TORCH_CHECK(t.numel() >= needed, op, ": argument '", arg, "' has ", t.numel(),
              " elements (sizes ", t.sizes(), ") but the kernel reaches element ", needed - 1,
              " for ", sizes);
}

/// An integer op argument converted to the kernel's integer type, range checked.
template <typename T> T narrow(std::int64_t v, const char* op, const char* arg) {
  if constexpr (std::is_enum_v<T>) { // (an enum parameter: its underlying type's range)
    return static_cast<T>(narrow<std::underlying_type_t<T>>(v, op, arg));
  } else {
    // (a negative v is below every unsigned T's minimum; compared as unsigned only when >= 0)
    TORCH_CHECK(v >= static_cast<std::int64_t>(std::numeric_limits<T>::min()) &&
                    (v < 0 || static_cast<std::uint64_t>(v) <=
                                  static_cast<std::uint64_t>(std::numeric_limits<T>::max())),
                op, ": argument '", arg, "' = ", v, " does not fit the kernel's ", sizeof(T) * 8,
                "-bit ", std::numeric_limits<T>::is_signed ? "signed" : "unsigned", " type");
    return static_cast<T>(v);
  }
}

/// The shape of an output: the one given (`<name>_shape=`), else `fallback`'s shape.
inline std::vector<std::int64_t> output_shape(const c10::optional<std::vector<std::int64_t>>& given,
                                              const at::Tensor& fallback, const char* op,
                                              const char* arg) {
  if (!given)
    return fallback.sizes().vec();
  for (std::int64_t s : *given)
    TORCH_CHECK(s >= 0, op, ": ", arg, "_shape ", c10::IntArrayRef(*given),
                " has a negative size");
  return *given;
}

/// The number of elements of a tensor of that shape.
inline std::int64_t numel_of(const std::vector<std::int64_t>& shape) {
  std::int64_t n = 1;
  for (std::int64_t s : shape)
    n *= s;
  return n;
}

/// A new output, zero-filled (elements the kernel does not write read as 0; `+=` outputs start
/// from 0), or left as allocated where `writes_every_element` (the generated op's test, from
/// the loop bounds and the store's index, that the kernel writes each element once): a fresh
/// zero fill costs as much as the kernel itself at large sizes.
inline at::Tensor new_output(const std::vector<std::int64_t>& shape, const at::Tensor& like,
                             bool writes_every_element = false) {
  const at::TensorOptions options = like.options().requires_grad(false);
  return writes_every_element ? at::empty(shape, options) : at::zeros(shape, options);
}

/// The seed of an output's adjoint in backward: the incoming gradient, contiguous (a copy only
/// where autograd hands a strided one), or zeros where that output was not used.
inline at::Tensor seed(const at::Tensor& grad, const std::vector<std::int64_t>& shape,
                       const at::TensorOptions& options) {
  if (!grad.defined())
    return at::zeros(shape, options);
  return grad.contiguous();
}

/// The adjoints are not themselves differentiable: refuse create_graph=True rather than
/// return second derivatives that silently miss terms.
inline void no_double_backward(const char* op) {
  TORCH_CHECK(!at::GradMode::is_enabled(), op,
              ": second derivatives (backward with create_graph=True) are not supported; the "
              "generated adjoint is a plain kernel");
}

inline c10::optional<std::vector<std::int64_t>> shape_arg(at::OptionalIntArrayRef s) {
  if (!s.has_value())
    return c10::nullopt;
  return s->vec();
}

} // namespace dpgen::torch_ops
