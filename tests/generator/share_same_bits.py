#!/usr/bin/env python3
"""The pass `share` changes no bit of an adjoint's result (share.hpp).

Generates the adjoints of kernels whose interiors share values along strips
(kernels/upwind_step.cpp, tests/styles/shifted_quotients.cpp,
tests/styles/twin_limiter_kernels.cpp) twice, with the pass and with
`dpgen --no-share`; checks that the first has strip buffers and the second
none; compiles tests/generator/share_bits_driver.cpp against each, with the
flags of a CMake Release build (-O3: for generic x86-64, no fused
multiply-add) on 1 and 2 threads: the outputs (every element as a
hexadecimal float) must be equal. With -O3 -march=native the compiler
contracts multiply-adds in its vector loops but not always in their scalar
prologue and epilogue, whose cells move with the alignment of the arrays and
with the threads' ranges, in the adjoints with the pass and without it alike;
there the two must agree to rounding (relative 1e-5, float's few ulps).

(scripts/compare_results.sh compares two dpgen builds on any kernel file, but
at one size, N = 101: below one strip. This test runs the sizes around a strip
of 256 cells and the threaded loop's threshold, on 1 and 2 threads.)

  share_same_bits.py --dpgen D --include I [--cxx g++] [--keep DIR]
"""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
KERNELS = ["kernels/upwind_step.cpp", "tests/styles/shifted_quotients.cpp",
           "tests/styles/twin_limiter_kernels.cpp"]
DRIVER = os.path.join(ROOT, "tests/generator/share_bits_driver.cpp")


def run(cmd, env=None):
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
    if r.returncode != 0:
        sys.exit(f"share_same_bits: failed ({r.returncode}): {' '.join(cmd)}\n{r.stderr}")
    return r.stdout


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--dpgen", required=True)
    ap.add_argument("--include", required=True)
    ap.add_argument("--cxx", default="g++")
    ap.add_argument("--keep", help="generate and build here (kept) instead of a temporary folder")
    args = ap.parse_args()
    work = args.keep or tempfile.mkdtemp(prefix="dpgen-share-bits-")
    try:
        outputs = {}
        for variant, flag in (("share", []), ("no-share", ["--no-share"])):
            gen = os.path.join(work, variant)
            os.makedirs(gen, exist_ok=True)
            for k in KERNELS:
                src = os.path.join(ROOT, k)
                run([args.dpgen, *flag, src, "--out-dir", gen, "--",
                     "-I" + args.include, "-I" + os.path.dirname(src)])
            text = "".join(open(os.path.join(gen, f)).read()
                           for f in sorted(os.listdir(gen)) if f.endswith("_adjoint.cpp"))
            buffers = text.count("// the interior in strips of")
            if (buffers == 0) != (variant == "no-share"):
                sys.exit(f"share_same_bits: {variant}: {buffers} strip loops in the generated "
                         "adjoints (expected some with the pass, none without)")
            sources = [DRIVER] + [os.path.join(gen, f) for f in sorted(os.listdir(gen))
                                  if f.endswith("_adjoint.cpp")]
            for opt in ("-O3", "-O3 -march=native"):
                exe = os.path.join(gen, "driver" + opt.replace(" ", "").replace("=", "_"))
                run([args.cxx, "-std=c++17", *opt.split(), "-fopenmp", "-I" + gen,
                     "-I" + args.include, *sources, "-o", exe])
                for threads in ("1", "2") if opt == "-O3" else ("1",):
                    env = dict(os.environ, OMP_NUM_THREADS=threads)
                    outputs[(variant, opt, threads)] = run([exe], env=env)
        failed = False
        for (variant, opt, threads), out in sorted(outputs.items()):
            if variant != "share":
                continue
            other = outputs[("no-share", opt, threads)]
            lines, other_lines = out.splitlines(), other.splitlines()
            exact = opt == "-O3"
            differ, worst, first = 0, 0.0, None
            label = ""
            for a, b in zip(lines, other_lines):
                if not a.startswith("0x") and not a.startswith("-0x"):
                    label = a
                    if a != b:
                        first = first or f"{a} vs {b}"
                        differ += 1
                    continue
                if a == b:
                    continue
                x, y = float.fromhex(a), float.fromhex(b)
                rel = abs(x - y) / max(1.0, abs(x), abs(y))
                worst = max(worst, rel)
                if exact or rel > 1e-5:
                    differ += 1
                    first = first or f"{label}: {a} (share) vs {b} (no-share)"
            differ += abs(len(lines) - len(other_lines))
            print(f"{opt}, {threads} thread(s): {len(lines)} lines, "
                  + ("the same" if lines == other_lines else
                     f"largest relative difference {worst:.2g}") +
                  (f"; {differ} FAIL, first {first}" if differ else ""))
            failed = failed or differ > 0
        if failed:
            sys.exit(1)
    finally:
        if not args.keep:
            shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
