#!/usr/bin/env python3
"""Forward + backward of a dpgen op (generated kernel + generated adjoint) against the same
stencil written with torch tensor slicing, at sizes 64² to 2048² (--sides), float32 and float64, 1 and 2 threads,
measured side by side in one run; prints a Markdown table (and writes it to --out).

  cmake -S . -B build -DDPGEN_WITH_TORCH=ON && cmake --build build -j2
  PYTHONPATH=python DPGEN_TORCH_LIBRARY=build/torch/libdpgen_torch.so:\\
    build/torch/libdpgen_torch_bench.so /usr/bin/python3 bench/torch_ops.py
"""
import argparse
import os
import platform
import statistics
import time

import torch

import dpgen_torch  # noqa: F401

ops = torch.ops.dpgen


def upwind_torch(d, u, dt, dx):
    up = torch.clamp(u / dx, max=0)
    um = torch.clamp(u / dx, min=0)
    return d - dt * (up * (torch.roll(d, -1) - d) + um * (d - torch.roll(d, 1)))


def laplacian_torch(a, h):
    out = torch.zeros_like(a)
    out[1:-1, 1:-1] = (a[1:-1, :-2] + a[1:-1, 2:] + a[:-2, 1:-1] + a[2:, 1:-1]
                       - 4 * a[1:-1, 1:-1]) / (h * h)
    return out


def cases(dtype, side):
    n = side * side
    d = torch.rand(n, dtype=dtype)
    u = torch.rand(n, dtype=dtype) - 0.5
    a = torch.rand(side, side, dtype=dtype)
    f64 = dtype == torch.float64
    up_op = ops.upwind_step if f64 else ops.upwind_step_f
    lap_op = ops.laplacian2d if f64 else ops.laplacian2d_f
    return [
        ("upwind (1D, periodic)", n, (d, u),
         lambda d, u: up_op(d, u, n, 0.1, 1.0), lambda d, u: upwind_torch(d, u, 0.1, 1.0)),
        (f"laplacian2d ({side}²)", side * side, (a,),
         lambda a: lap_op(a, side, side, 0.5), lambda a: laplacian_torch(a, 0.5)),
    ]


def time_fb(fn, inputs, reps):
    xs = [x.clone().requires_grad_() for x in inputs]
    g = torch.rand_like(fn(*inputs))
    ts = []
    for _ in range(reps + 2):
        for x in xs:
            x.grad = None
        t = time.perf_counter()
        fn(*xs).backward(g)
        ts.append(time.perf_counter() - t)
    return statistics.median(ts[2:]) * 1e3


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--reps", type=int, default=15)
    p.add_argument("--out", default="")
    p.add_argument("--sides", type=int, nargs="+", default=[64, 256, 1024, 2048],
                   help="grid sides: the upwind op gets side² cells, the Laplacian side x side")
    a = p.parse_args()
    rows = []
    for dtype in (torch.float32, torch.float64):
        for name, cells, inputs, op, ref in (c for side in a.sides for c in cases(dtype, side)):
            # the same result first: the comparison is of equal work
            y_op, y_ref = op(*inputs), ref(*inputs)
            tol = 1e-4 if dtype == torch.float32 else 1e-10
            torch.testing.assert_close(y_op, y_ref, rtol=tol, atol=tol)
            for threads in (1, 2):
                torch.set_num_threads(threads)
                t_op = time_fb(op, inputs, a.reps)
                t_ref = time_fb(ref, inputs, a.reps)
                rows.append((name, cells, str(dtype).replace("torch.", ""), threads, t_op, t_ref))
    lines = [
        f"Measured with `bench/torch_ops.py` on {os.cpu_count()} CPUs ({platform.processor() or platform.machine()}), "
        f"torch {torch.__version__}, {time.strftime('%Y-%m-%d')}; medians of {a.reps} runs of "
        "forward + backward (`y = f(x); y.backward(g)`), both columns in the same run.",
        "",
        "| stencil | cells | dtype | threads | dpgen op ms | torch slicing ms | speed-up |",
        "|---|---|---|---|---|---|---|",
    ]
    for name, cells, dt, th, t_op, t_ref in rows:
        lines.append(f"| {name} | {cells:.0e} | {dt} | {th} | {t_op:.2f} | {t_ref:.2f} | "
                     f"{t_ref / t_op:.1f}x |")
    text = "\n".join(lines)
    print(text)
    if a.out:
        with open(a.out, "w") as f:
            f.write(text + "\n")


if __name__ == "__main__":
    main()
