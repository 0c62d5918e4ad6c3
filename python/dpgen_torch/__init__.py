"""dpgen's PyTorch ops: your annotated C++ kernels as autograd ops, and solvers built on them.

    import torch, dpgen_torch
    m = dpgen_torch.load("my_kernels.cpp")       # generate, compile, cache: one op per kernel
    y = m.my_kernel(x, n, h)                     # backward = the generated adjoint
    xT = dpgen_torch.rollout(m.step, x0, 100, checkpoints=8, u=u, n=n, dt=0.1)
    x = dpgen_torch.solve(m.apply_a, b, k=k, n=n)   # CG forward, implicit-gradient backward

Importing the package also loads the shipped kernels' ops (libdpgen_torch.so) as
torch.ops.dpgen.<kernel>; see _locate for where everything is found. Every generated op takes
the kernel's parameters in order without its outputs (arrays as contiguous CPU tensors of the
kernel's dtype, scalars as numbers) and, as keyword arguments, `<output>_shape` for each output
(default: the shape of the first array argument).
"""
import os

import torch

from . import _locate
from ._load import CompileError, KernelError, cache_dir, load, prune_cache
from .solvers import ConvergenceError, rollout, solve

__all__ = ["load", "KernelError", "CompileError", "cache_dir", "prune_cache", "rollout", "solve",
           "ConvergenceError", "load_library", "loaded", "ops", "upwind_rollout",
           "diffusion_solve", "generator"]
__version__ = "0.1.0"

_loaded = []


def load_library(path):
    """Loads a library of dpgen ops (lib<target>.so from dpgen_add_torch_ops) once."""
    path = os.path.abspath(path)
    if path in _loaded:
        return
    if not os.path.isfile(path):
        raise FileNotFoundError(f"dpgen_torch: no ops library at {path}")
    torch.ops.load_library(path)
    _loaded.append(path)


def loaded():
    """The ops libraries loaded so far with load_library (load()'s are in its modules)."""
    return list(_loaded)


def generator():
    """The path of the dpgen executable load() runs."""
    return _locate.generator()


for _path in _locate.shipped_libraries():
    load_library(_path)

ops = torch.ops.dpgen


def upwind_rollout(d0, u, steps, dt, dx, checkpoints=0):
    """`steps` upwind steps (kernels/upwind_step.cpp) from d0 with velocity u: rollout() of the
    shipped op torch.ops.dpgen.upwind_step (checkpoints=0 keeps every state, K >= 1 holds at
    most K states, Revolve; the gradients are the same bit for bit)."""
    return rollout(torch.ops.dpgen.upwind_step, d0, steps, checkpoints=checkpoints, u=u,
                   n=d0.numel(), dt=dt, dx=dx)


def diffusion_solve(b, k, h, rtol=1e-10, max_iterations=10000):
    """x with -d/dx(k dx/dx) = b on len(b) cells (Dirichlet walls, k: len(b) + 1 positive face
    coefficients): solve() of the shipped operator op torch.ops.dpgen.neg_div_k_grad_1d, Jacobi
    preconditioned; backward is the one transposed solve of the implicit function rule."""
    if k.dim() != 1 or k.numel() != b.numel() + 1:
        raise ValueError(f"diffusion_solve: k (face coefficients) needs {b.numel() + 1} "
                         f"elements for {b.numel()} cells, got {k.numel()}")
    if not h > 0:
        raise ValueError(f"diffusion_solve: h must be positive, got {h}")
    kd = k.detach()
    if not bool((kd > 0).all()):
        raise ValueError("diffusion_solve: every face coefficient k must be positive (A(k) is "
                         "then symmetric positive definite)")
    return solve(torch.ops.dpgen.neg_div_k_grad_1d, b, rtol=rtol, max_iterations=max_iterations,
                 diagonal=(kd[:-1] + kd[1:]) / (h * h), k=k, n=b.numel(), h=h)
