#!/usr/bin/env python3
"""Turns the JSON of bench_adjoints and bench_solvers (one run) and the
generator timings into bench/results.md, and puts that table into README.md
between the '<!-- bench:begin -->' and '<!-- bench:end -->' markers.
usage: bench_table.py adjoints.json solvers.json generator.tsv vectorizes.tsv results.md README.md
                      command"""
import json
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_bandwidth import bandwidth_lines  # noqa: E402


def load(path):
    with open(path) as f:
        data = json.load(f)
    return data["context"], {b["name"]: b for b in data["benchmarks"] if b.get("run_type") != "aggregate"}


def ms(b):
    unit = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[b["time_unit"]]
    return b["real_time"] * unit


def main():
    adj_json, sol_json, gen_tsv, vec_tsv, out_md, readme, command = sys.argv[1:8]
    vectorizes = dict(line.split() for line in open(vec_tsv) if line.strip())
    ctx, adj = load(adj_json)
    _, sol = load(sol_json)
    lines = []
    lines.append(f"Measured with `{command}` on {ctx.get('num_cpus')} CPUs at "
                 f"{ctx.get('mhz_per_cpu')} MHz ({ctx.get('date', '')}); times are medians of "
                 "Google Benchmark's repetitions, ratios are taken within this one run.\n")
    lines.append("### Adjoint kernels, 1 thread (`2T`: speed-up of the generated adjoint on 2 threads)\n")
    lines.append("Goals: generated/forward <= 1.6, generated/hand <= 1.10, 2T >= 1.5. `peeled` is "
                 "the forward kernel with its boundary or periodic cases taken out of the loop, "
                 "for kernels whose forward as written does not vectorize (GCC -fopt-info-vec).\n")
    lines.append("| kernel | cells | forward as written (vectorizes?) | forward peeled | generated | "
                 "hand gather | scatter | generated / forward | generated / peeled | "
                 "generated / hand | scatter / generated | 2T |")
    lines.append("|---|---|---|---|---|---|---|---|---|---|---|---|")
    kernels = [("laplacian2d", "2048²"), ("divergence2d", "2048²"), ("upwind", "2²²"),
               ("laplacian3d", "160³"), ("burgers", "2²²")]
    for k, cells in kernels:
        def get(v, t=1):
            return adj.get(f"BM_{k}_{v}/{t}/real_time")
        f, fp, g, hg, sc, g2 = (get("forward"), get("forward_peeled"), get("generated"), get("hand"),
                                get("scatter"), get("generated", 2))
        def t(b):
            return f"{ms(b):.2f} ms" if b else "–"
        def r(a, b):
            return f"{ms(a) / ms(b):.2f}" if a and b else "–"
        row = [k, cells, f"{t(f)} ({vectorizes.get(k, '?')})", t(fp), t(g), t(hg), t(sc),
               r(g, f), r(g, fp), r(g, hg), r(sc, g), f"{ms(g) / ms(g2):.2f}x" if g2 else "–"]
        lines.append("| " + " | ".join(row) + " |")
    cache = [("laplacian2d", "128²"), ("divergence2d", "128²"), ("upwind", "2¹⁴"),
             ("laplacian3d", "24³"), ("burgers", "2¹⁴")]
    rows = []
    for k, cells in cache:
        g1, h1, g2, h2 = (adj.get(f"BM_{k}_{v}_cache/{t}/real_time")
                          for v, t in (("generated", 1), ("hand", 1), ("generated", 2), ("hand", 2)))
        if g1 and h1 and g2 and h2:
            rows.append(f"| {k} | {cells} | {ms(g1) * 1e3:.1f} / {ms(h1) * 1e3:.1f} = "
                        f"{ms(g1) / ms(h1):.2f} | {ms(g2) * 1e3:.1f} / {ms(h2) * 1e3:.1f} = "
                        f"{ms(g2) / ms(h2):.2f} |")
    if rows:
        lines.append("\n### In cache: generated / hand gather (every array within one core's L2)\n")
        lines.append("| kernel | cells | 1 thread, µs | 2 threads, µs |")
        lines.append("|---|---|---|---|")
        lines += rows
    bw = bandwidth_lines(list(adj.values()))
    if bw:
        lines.append("\n### Attained bandwidth of the 2D adjoints against a STREAM triad in the same run\n")
        lines.append("The least bytes each must move per cell (seed read, adjoints read and written; "
                     "STREAM's count): laplacian2d 24, divergence2d 40, the triad 24. Goal: >= 0.70 "
                     "of the triad.\n")
        lines += bw
    lines.append("\n### Multigrid-preconditioned CG against Jacobi-preconditioned CG (`-div(k grad p)`, periodic, tol 1e-8, 1 thread)\n")
    lines.append("Goals: MG-PCG iterations <= 20 at every n, time per cell flat, 1024² >= 10x faster "
                 "than Jacobi-PCG, backward / forward <= 1.2. The forward time includes the multigrid "
                 "setup (coefficients averaged, diagonals probed, coarsest grid factored), shown "
                 "alone too; the backward pass reuses it (A^T = A). `in A x` is the forward time "
                 "in applications of the operator kernel at that size, whose own time per cell "
                 "grows as the fields leave the caches.\n")
    lines.append("| grid | Jacobi-PCG ms (iterations) | MG setup ms | MG-PCG forward ms (iterations) | "
                 "forward ns/cell | forward in A x | MG-PCG backward ms (iterations) | "
                 "backward / forward | Jacobi-PCG / MG-PCG |")
    lines.append("|---|---|---|---|---|---|---|---|---|")
    for n in (64, 128, 256, 512, 1024):
        j, st, f, b, op = (sol.get(f"BM_cg_forward/{n}"), sol.get(f"BM_mg_setup/{n}"),
                           sol.get(f"BM_mgpcg_forward/{n}"), sol.get(f"BM_mgpcg_backward_implicit/{n}"),
                           sol.get(f"BM_operator/{n}"))
        if not (f and b):
            continue
        jac = f"{ms(j):.2f} ({int(j['cg_iterations'])})" if j else "–"
        lines.append(f"| {n}² | {jac} | {ms(st):.2f} | {ms(f):.2f} ({int(f['cg_iterations'])}) | "
                     f"{ms(f) * 1e6 / (n * n):.0f} | {ms(f) / ms(op):.0f} | "
                     f"{ms(b):.2f} ({int(b['cg_iterations'])}) | {ms(b) / ms(f):.2f} | "
                     f"{(f'{ms(j) / ms(f):.0f}x' if j else '–')} |")
    lines.append("\n### Jacobi-PCG: forward solve against the implicit backward pass (`-div(k grad p)`, periodic, tol 1e-8, 1 thread)\n")
    lines.append("| grid | forward ms | backward ms | backward / forward | CG iterations (fwd / bwd) |")
    lines.append("|---|---|---|---|---|")
    for n in (64, 128, 256, 512):
        f, b = sol.get(f"BM_cg_forward/{n}"), sol.get(f"BM_cg_backward_implicit/{n}")
        if f and b:
            lines.append(f"| {n}² | {ms(f):.2f} | {ms(b):.2f} | {ms(b) / ms(f):.2f} | "
                         f"{int(f['cg_iterations'])} / {int(b['cg_iterations'])} |")
    lines.append("\n### Heap growth during a CG gradient (128², fixed iteration count)\n")
    lines.append("| CG iterations | implicit rule | through the unrolled iterations |")
    lines.append("|---|---|---|")
    for it in (25, 100, 400):
        i, u = sol.get(f"BM_cg_gradient_memory/0/{it}/iterations:1"), sol.get(f"BM_cg_gradient_memory/1/{it}/iterations:1")
        if i and u:
            lines.append(f"| {it} | {i['peak_heap_bytes'] / 1e6:.2f} MB | {u['peak_heap_bytes'] / 1e6:.2f} MB |")
    lines.append("\n### Unrolled time loop: 10⁴ upwind steps on 256 cells, gradient w.r.t. d0 and u\n")
    f = sol.get("BM_timeloop_forward")
    lines.append(f"Forward alone: {ms(f):.2f} ms.\n")
    lines.append("| states kept | gradient ms | gradient / forward | forward steps | Revolve formula | peak state bytes |")
    lines.append("|---|---|---|---|---|---|")
    for s in (0, 8, 16, 32):
        b = sol.get(f"BM_timeloop_gradient/{s}")
        if b:
            name = "all (full tape)" if s == 0 else f"{s} snapshots (Revolve)"
            lines.append(f"| {name} | {ms(b):.2f} | {ms(b) / ms(f):.2f} | {int(b['forward_steps'])} | "
                         f"{int(b['predicted_steps'])} | {int(b['peak_state_bytes'])} |")
    lines.append("\n### The generator's own time per kernel file (median of 5 runs, includes parsing `<cmath>`/`<algorithm>`)\n")
    lines.append("| kernel file | dpgen ms |")
    lines.append("|---|---|")
    with open(gen_tsv) as fh:
        for line in fh:
            name, t = line.split()
            lines.append(f"| {name} | {float(t):.0f} |")
    table = "\n".join(lines) + "\n"
    with open(out_md, "w") as fh:
        fh.write("# Benchmark results\n\n" + table)
    with open(readme) as fh:
        text = fh.read()
    new = re.sub(r"<!-- bench:begin -->.*<!-- bench:end -->",
                 "<!-- bench:begin -->\n" + table + "<!-- bench:end -->", text, flags=re.S)
    with open(readme, "w") as fh:
        fh.write(new)


if __name__ == "__main__":
    main()
