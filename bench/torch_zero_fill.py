"""What a fresh, zero-filled adjoint costs the ops' backward (torch.zeros_like, as the generated
backward allocates its input adjoints) against an allocation alone (torch.empty_like), at 2048²
float32 and float64 on 1 and 2 threads; medians of --reps calls, in ms.

  /usr/bin/python3 bench/torch_zero_fill.py

torch's fill runs on its intra-op threads, so the second thread halves it; a float64 2048² tensor
(32 MiB) is above glibc's largest mmap threshold, so every call maps fresh pages and faults each
one in (the float32 one, 16 MiB, is reused from the heap after the first call).
"""
import argparse
import statistics
import time

import torch


def median_ms(fn, reps):
    ts = []
    for _ in range(reps):
        t = time.perf_counter()
        z = fn()
        ts.append(time.perf_counter() - t)
        del z
    return statistics.median(ts) * 1e3


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--reps", type=int, default=31)
    p.add_argument("--side", type=int, default=2048)
    a = p.parse_args()
    print("| dtype | threads | zeros_like ms | empty_like ms |")
    print("|---|---|---|---|")
    for dtype in (torch.float32, torch.float64):
        x = torch.rand(a.side * a.side, dtype=dtype)
        for threads in (1, 2):
            torch.set_num_threads(threads)
            z = median_ms(lambda: torch.zeros_like(x), a.reps)
            e = median_ms(lambda: torch.empty_like(x), a.reps)
            print(f"| {str(dtype).replace('torch.', '')} | {threads} | {z:.3f} | {e:.4f} |")


if __name__ == "__main__":
    main()
