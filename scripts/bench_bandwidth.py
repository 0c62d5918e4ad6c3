#!/usr/bin/env python3
"""Attained memory bandwidth of the 2D adjoints against a STREAM triad measured in
the same run (bench/bench_adjoints.cpp: BM_triad; the adjoints' bytes per cell
are the least they must move, STREAM's count; the triad's stores also read
their lines first (write-allocate), 32 bytes per cell moved where 24 are
counted, which the adjoints' read-modify-write does not pay: multiply a share
by 0.75 to count what the triad really moves). Issue 23's goal: >= 70% at
2048 x 2048. Used by scripts/bench_table.py; alone:
  bench_adjoints --benchmark_filter='triad|2d_generated|2d_hand' --benchmark_out=x.json \\
      --benchmark_out_format=json --benchmark_repetitions=5
  scripts/bench_bandwidth.py x.json [label]"""
import json
import statistics
import sys

KERNELS = [("laplacian2d", "generated"), ("laplacian2d", "hand"),
           ("divergence2d", "generated"), ("divergence2d", "hand")]


def gbs(benchmarks, name):
    """Median bytes per second over the repetitions of `name`, in GB/s (None if absent)."""
    runs = [b["bytes_per_second"] for b in benchmarks
            if b.get("run_type") != "aggregate" and b.get("run_name", b["name"]) == name
            and "bytes_per_second" in b]
    return statistics.median(runs) / 1e9 if runs else None


def bandwidth_lines(benchmarks):
    """Markdown lines of the table, or [] when the run has no triad."""
    if gbs(benchmarks, "BM_triad/1/real_time") is None:
        return []
    lines = ["| kernel (2048²) | 1T GB/s | 1T / triad | 2T GB/s | 2T / triad |",
             "|---|---|---|---|---|"]
    tri = {t: gbs(benchmarks, f"BM_triad/{t}/real_time") for t in (1, 2)}
    lines.append("| STREAM triad | " + " | ".join(
        f"{tri[t]:.1f} | 1.00" if tri[t] else "– | –" for t in (1, 2)) + " |")
    for k, form in KERNELS:
        row = [f"{k} {form}"]
        for t in (1, 2):
            v = gbs(benchmarks, f"BM_{k}_{form}/{t}/real_time")
            row += [f"{v:.1f}", f"{v / tri[t]:.2f}"] if v and tri[t] else ["–", "–"]
        lines.append("| " + " | ".join(row) + " |")
    return lines


def main():
    with open(sys.argv[1]) as f:
        data = json.load(f)
    label = sys.argv[2] if len(sys.argv) > 2 else sys.argv[1]
    ctx = data["context"]
    print(f"{label}: {ctx.get('num_cpus')} CPUs at {ctx.get('mhz_per_cpu')} MHz, {ctx.get('date', '')}\n")
    print("\n".join(bandwidth_lines(data["benchmarks"])))


if __name__ == "__main__":
    main()
