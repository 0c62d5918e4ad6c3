#!/usr/bin/env python3
"""Tables of scripts/bench_speed.sh's runs (medians of the repetitions), in markdown.
usage: bench_speed_table.py <results-dir> <baseline-commit> [cpu]
With `cpu`, times are the process's CPU time instead of wall time, and only 1-thread figures are
shown (a 2-thread run's CPU time adds both threads): on a machine shared with other jobs, CPU
time is what a 1-thread run itself used, wall time adds the time it waited for a core."""
import json
import os
import sys


def load(path):
    data = json.load(open(path))
    rows = {}
    for b in data["benchmarks"]:
        if b.get("aggregate_name") == "median":
            rows[b["run_name"]] = b
    if not rows:
        rows = {b["name"]: b for b in data["benchmarks"]}
    return data["context"], rows


CLOCK = "real_time"


def ms(b):
    return b[CLOCK] * {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[b["time_unit"]]


def keep(rows):
    """Drops the 2-thread runs (names ending in /2) when timing by CPU time."""
    if CLOCK == "real_time":
        return rows
    return {k: v for k, v in rows.items() if not k.endswith("/2")}


def main():
    global CLOCK
    d, base = sys.argv[1], sys.argv[2]
    if len(sys.argv) > 3 and sys.argv[3] == "cpu":
        CLOCK = "cpu_time"
    flavours = {"o3": "plain -O3 (CMake Release)", "native": "-O3 -march=native"}
    for flavour, title in flavours.items():
        ctx, new = load(os.path.join(d, f"{flavour}-bench_speed.json"))
        _, old = load(os.path.join(d, f"{flavour}-bench_speed_baseline.json"))
        new, old = keep(new), keep(old)
        clock = "wall time" if CLOCK == "real_time" else "CPU time, 1 thread only"
        print(f"\n#### {title} ({clock}): {ctx.get('num_cpus')} CPUs at {ctx.get('mhz_per_cpu')} "
              f"MHz, {ctx.get('date', '')}; baseline = runtime headers of {base}\n")
        print("Unrolled upwind loop, full tape, 2^24 cell-steps (16 to 10^4 steps): "
              "gradient / forward at 1T / 2T; heap: how much the heap grew during a gradient call "
              "(sampled when the tape is complete; the workspace's calls after the first)\n")
        print("| cells | forward ms 1T / 2T | baseline 1T / 2T | workspace 1T / 2T | "
              "no workspace 1T / 2T | heap growth: workspace / baseline |")
        print("|---|---|---|---|---|---|")
        for n in (256, 4096, 65536, 1 << 20, 1 << 22):
            def r(rows, mode, t):
                g, f = rows.get(f"BM_unrolled_upwind/{n}/{mode}/{t}"), rows.get(f"BM_unrolled_upwind/{n}/0/{t}")
                return f"{ms(g) / ms(f):.2f}" if g and f else "–"
            f1, f2 = new.get(f"BM_unrolled_upwind/{n}/0/1"), new.get(f"BM_unrolled_upwind/{n}/0/2")
            if not f1:
                continue
            hw = new.get(f"BM_unrolled_upwind/{n}/1/1")
            hb = old.get(f"BM_unrolled_upwind/{n}/1/1")
            heap = f"{hw['heap_growth_bytes'] / 1e6:.2f} MB / {hb['heap_growth_bytes'] / 1e6:.2f} MB" if hw and hb else "–"
            f2ms = f"{ms(f2):.2f}" if f2 else "–"
            print(f"| {n} | {ms(f1):.2f} / {f2ms} | {r(old, 1, 1)} / {r(old, 1, 2)} | "
                  f"{r(new, 1, 1)} / {r(new, 1, 2)} | {r(new, 2, 1)} / {r(new, 2, 2)} | {heap} |")
        print("\nMG-PCG, setup + solve to 1e-8 (`-div(k grad p)`, periodic): ms at 1T / 2T, "
              "2-thread speed-up, ns per cell at 2T\n")
        print("| grid | iterations | baseline 1T / 2T ms | baseline 2T speed-up | new 1T / 2T ms | "
              "new 2T speed-up | new ns/cell 1T / 2T | new 1T / baseline 1T |")
        print("|---|---|---|---|---|---|---|---|")
        for n in (256, 512, 1024, 2048):
            o1, o2 = old.get(f"BM_mgpcg/{n}/1"), old.get(f"BM_mgpcg/{n}/2")
            n1, n2 = new.get(f"BM_mgpcg/{n}/1"), new.get(f"BM_mgpcg/{n}/2")
            if not (o1 and n1):
                continue
            t2 = lambda b: f"{ms(b):.1f}" if b else "–"
            up = lambda a, b: f"{ms(a) / ms(b):.2f}" if a and b else "–"
            cell = lambda b: f"{ms(b) * 1e6 / n / n:.0f}" if b else "–"
            print(f"| {n}² | {int(n1['cg_iterations'])} | {ms(o1):.1f} / {t2(o2)} | {up(o1, o2)} | "
                  f"{ms(n1):.1f} / {t2(n2)} | {up(n1, n2)} | {cell(n1)} / {cell(n2)} | "
                  f"{ms(n1) / ms(o1):.2f} |")
        rows = [(n, new.get(f"BM_mgpcg_parallel_forward/{n}/1"),
                 new.get(f"BM_mgpcg_parallel_forward/{n}/2"), new.get(f"BM_mgpcg/{n}/1"))
                for n in (256, 512, 1024, 2048)]
        if any(p1 for _, p1, _, _ in rows):
            print("\nThe same, the operator passed as its generated `<kernel>_parallel_forward` (the "
                  "same bits; its interior loop split from the periodic wrap and vectorized)\n")
            print("| grid | 1T / 2T ms | 2T speed-up | ns/cell 1T / 2T | 1T against the kernel as "
                  "written |")
            print("|---|---|---|---|---|")
            for n, p1, p2, n1 in rows:
                if not (p1 and n1):
                    continue
                t2 = f"{ms(p2):.1f}" if p2 else "–"
                up = f"{ms(p1) / ms(p2):.2f}" if p2 else "–"
                c2 = f"{ms(p2) * 1e6 / n / n:.0f}" if p2 else "–"
                print(f"| {n}² | {ms(p1):.1f} / {t2} | {up} | {ms(p1) * 1e6 / n / n:.0f} / {c2} | "
                      f"{ms(p1) / ms(n1):.2f} |")
        print("\nFlow solver, 4 steps (closed box, semi-Lagrangian, MG-PCG pressure to 1e-10): "
              "gradient / forward and the 2-thread speed-up of each\n")
        print("| grid | baseline forward ms 1T | baseline gradient / forward 1T / 2T | "
              "baseline 2T speed-up fwd / grad | new forward ms 1T | new gradient / forward "
              "1T / 2T | new 2T speed-up fwd / grad |")
        print("|---|---|---|---|---|---|---|")
        for n in (128, 256):
            def cols(rows):
                f1, f2 = rows.get(f"BM_flow/{n}/0/1"), rows.get(f"BM_flow/{n}/0/2")
                g1, g2 = rows.get(f"BM_flow/{n}/1/1"), rows.get(f"BM_flow/{n}/1/2")
                if not (f1 and g1):
                    return ["–"] * 3
                r = lambda a, b: f"{ms(a) / ms(b):.2f}" if a and b else "–"
                return [f"{ms(f1):.1f}", f"{r(g1, f1)} / {r(g2, f2)}", f"{r(f1, f2)} / {r(g1, g2)}"]
            print(f"| {n}² | " + " | ".join(cols(old) + cols(new)) + " |")


if __name__ == "__main__":
    main()
