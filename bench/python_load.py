"""How long dpgen_torch.load takes (the README's "Python quick start" numbers): the first call
on a kernel (generate + compile + link, into an empty cache) and then cache hits, each in a
new process, timing the load() call and the whole process (Python start, import torch and
dpgen_torch, load). Run with the interpreter dpgen_torch is installed in:

    env/bin/python bench/python_load.py [--hits 5]
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

KERNEL = r'''
#include "dpgen/annotate.hpp"
DPGEN_KERNEL void blur(DPGEN_IN const double* a, DPGEN_IN const double* w, DPGEN_OUT double* out, int n) {
  for (int i = 1; i < n - 1; ++i) out[i] = w[i] * (a[i - 1] + a[i + 1]) + (1 - 2 * w[i]) * a[i];
}'''

CHILD = f"""
import json, time
t0 = time.perf_counter()
import torch, dpgen_torch
t1 = time.perf_counter()
m = dpgen_torch.load({KERNEL!r}, name="blur")
t2 = time.perf_counter()
print(json.dumps({{"import": t1 - t0, "load": t2 - t1}}))
"""


def child(cache):
    env = dict(os.environ, DPGEN_TORCH_CACHE=cache)
    started = time.perf_counter()
    out = subprocess.run([sys.executable, "-c", CHILD], env=env, check=True,
                         stdout=subprocess.PIPE, text=True).stdout
    r = json.loads(out.strip().splitlines()[-1])
    r["process"] = time.perf_counter() - started
    return r


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--hits", type=int, default=5)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="dpgen-load-bench-") as cache:
        first = child(cache)
        hits = [child(cache) for _ in range(args.hits)]
    med = {k: statistics.median(h[k] for h in hits) for k in ("import", "load", "process")}
    print(f"first load (generate + compile): load() {first['load']:.1f} s, "
          f"process {first['process']:.1f} s")
    print(f"cache hit, new process (median of {args.hits}): load() {med['load'] * 1e3:.1f} ms, "
          f"import torch + dpgen_torch {med['import']:.2f} s, process {med['process']:.2f} s")
    print(f"cpus {os.cpu_count()}, load average {os.getloadavg()[0]:.1f}")


if __name__ == "__main__":
    main()
