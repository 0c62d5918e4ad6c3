"""dpgen's PyTorch ops: generated kernel ops and whole-solver ops as torch.ops.dpgen.*.

Importing this package loads the ops library built with -DDPGEN_WITH_TORCH=ON
(libdpgen_torch.so): the path in $DPGEN_TORCH_LIBRARY (several separated by os.pathsep), else
the first build*/torch/libdpgen_torch.so of this source tree. More libraries made with the CMake
function dpgen_add_torch_ops (your own kernels) load with load_library(path).

    import torch, dpgen_torch
    d1 = torch.ops.dpgen.upwind_step(d, u, n, dt, dx)        # one kernel, backward = adjoint
    dT = dpgen_torch.upwind_rollout(d0, u, 100, dt, dx, checkpoints=8)
    x = dpgen_torch.diffusion_solve(b, k, h)                 # CG, implicit-gradient backward

Every generated op takes the kernel's parameters in order without its outputs (arrays as
contiguous CPU tensors of the kernel's dtype, scalars as numbers) and, as keyword arguments,
`<output>_shape` for each output (default: the shape of the first array argument).
"""
import glob
import os

import torch

__all__ = ["load_library", "loaded", "ops", "upwind_rollout", "diffusion_solve"]

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
    """The ops libraries loaded so far."""
    return list(_loaded)


def _default_libraries():
    env = os.environ.get("DPGEN_TORCH_LIBRARY")
    if env:
        return [p for p in env.split(os.pathsep) if p]
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    found = sorted(glob.glob(os.path.join(root, "build*", "torch", "libdpgen_torch.so")))
    if not found:
        raise ImportError(
            "dpgen_torch: libdpgen_torch.so not found; build with -DDPGEN_WITH_TORCH=ON and set "
            "DPGEN_TORCH_LIBRARY to its path")
    return found[:1]


for _path in _default_libraries():
    load_library(_path)

ops = torch.ops.dpgen


def upwind_rollout(d0, u, steps, dt, dx, checkpoints=0):
    """`steps` upwind steps from d0 with velocity u as one op; backward is the adjoint rollout
    (every state kept with checkpoints=0, else binomial checkpointing with that many
    snapshots: the same gradient)."""
    return torch.ops.dpgen.upwind_rollout(d0, u, steps, dt, dx, checkpoints)


def diffusion_solve(b, k, h, rtol=1e-10, max_iterations=10000):
    """x with -d/dx(k dx/dx) = b on len(b) cells (Dirichlet walls, k: len(b) + 1 positive face
    coefficients) by CG; backward is the transposed solve (implicit function rule)."""
    return torch.ops.dpgen.diffusion_solve(b, k, h, rtol, max_iterations)
