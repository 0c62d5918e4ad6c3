#!/usr/bin/env python3
"""Runs the tree's kernels once each through the instrumented generator.

The ctest tests fuzz.generator_seeds_<k> call it: the kernels that the build
generates from, and the ones that must be rejected, made self-contained
(seed_corpus.py) and handed to the libFuzzer binary as files, each run once.
fuzz_generator.cpp's environment says what is expected of each group
(DPGEN_FUZZ_EXPECT), so a seed that stops being accepted, or is cut short,
fails instead of passing as "rejected: fine".

  run_seeds.py --fuzzer BIN --out DIR --part K --parts N [--recheck-every M]
               [--group EXPECT:STD[:built] FILE...]...

EXPECT is accept or reject, STD the C++ standard (c++17, c++20); files ending
in .c are lowered as C. `built`: the test build compiles these kernels' generated
adjoint and tangent itself (g++), so the fuzzer's parse of its own output (two
Clang parses with the standard headers, about two thirds of a seed's time) is
done only for the seeds generated twice (DPGEN_FUZZ_COMPILE=0 for the others).
The files of all groups, in order, are dealt to the N parts; this run takes part K (0-based). Every M-th seed of the part (by
position, from its first; default 1: all) is generated twice in the same
process, and the two outputs must be the same (DPGEN_FUZZ_RECHECK); the fuzz
run checks that on all its inputs.
"""
import argparse
import os
import re
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from seed_corpus import inline  # noqa: E402


def parse_groups(argv):
    """Splits `--group E:S f...` runs out of argv (argparse has no repeated nargs='+').
    The groups come last: a token starting with -- after one is an error."""
    groups, rest, cur = [], [], None
    it = iter(argv)
    for a in it:
        if a == "--group":
            spec = next(it, None)
            expect, std, built = ((spec or "").split(":") + ["", ""])[:3]
            if (expect not in ("accept", "reject") or not std or (spec or "").count(":") > 2
                    or built not in ("", "built") or (built and expect != "accept")):
                sys.exit(f"run_seeds.py: --group {spec}: expected accept:STD, reject:STD or "
                         f"accept:STD:built")
            cur = (expect, std, built == "built", [])
            groups.append(cur)
        elif cur is not None:
            if a.startswith("--"):
                sys.exit(f"run_seeds.py: {a} after a --group: the groups come last")
            cur[3].append(a)
        else:
            rest.append(a)
    return groups, rest


def main():
    groups, rest = parse_groups(sys.argv[1:])
    ap = argparse.ArgumentParser()
    ap.add_argument("--fuzzer", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--part", type=int, default=0)
    ap.add_argument("--parts", type=int, default=1)
    ap.add_argument("--timeout", type=int, default=600, help="seconds per seed")
    ap.add_argument("--recheck-every", type=int, default=1,
                    help="generate every M-th seed twice (0: none)")
    args = ap.parse_args(rest)
    if args.recheck_every < 0:
        sys.exit(f"run_seeds.py: --recheck-every {args.recheck_every} is negative")
    if not 0 <= args.part < args.parts:
        sys.exit(f"run_seeds.py: --part {args.part} is not in [0, {args.parts})")

    # Deal every seed to a part; each (expect, std, language, recheck, parse) batch is one
    # fuzzer run.
    dealt = [(i, e, s, b, f) for i, (e, s, b, f) in
             enumerate((e, s, b, f) for e, s, b, files in groups for f in files)]
    if not dealt:
        sys.exit("run_seeds.py: no seeds given")
    mine = dealt[args.part::args.parts]
    if not mine:
        print(f"run_seeds.py: part {args.part} of {args.parts}: no seeds ({len(dealt)} in all)")
        return 0
    batches = {}
    out = os.path.join(args.out, f"part{args.part}")
    for j, (i, expect, std, built, path) in enumerate(mine):
        if not os.path.isfile(path):
            sys.exit(f"run_seeds.py: no seed file {path}")
        # unique over the tree (kernels/, tests/kernels/, examples/kernels/ share a
        # folder name): the seed's position, its folder and its file name
        name = f"{i:04d}_{os.path.basename(os.path.dirname(path))}__{os.path.basename(path)}"
        dest = os.path.join(out, expect, name)
        os.makedirs(os.path.dirname(dest), exist_ok=True)
        with open(dest, "w", encoding="utf-8") as f:
            f.writelines(inline(path, set()))
        lang = "c" if path.endswith(".c") else "c++"
        recheck = args.recheck_every > 0 and j % args.recheck_every == 0
        batches.setdefault((expect, std, lang, recheck, recheck or not built), []).append(dest)

    status = 0
    slowest = []
    for (expect, std, lang, recheck, compile), files in sorted(batches.items()):
        env = dict(os.environ)
        env.update({
            "DPGEN_FUZZ_RECHECK": "1" if recheck else "0",
            "DPGEN_FUZZ_COMPILE": "1" if compile else "0",
            "DPGEN_FUZZ_EXPECT": expect,
            "DPGEN_FUZZ_STD": std,
            "DPGEN_FUZZ_NAME": "fuzz.c" if lang == "c" else "fuzz.cpp",
            "DPGEN_FUZZ_MAX_BYTES": str(1 << 20),
            # ASan's allocation stack traces cost most in the allocating phases;
            # 5 frames still name the caller (the user's own options come after, and win)
            "ASAN_OPTIONS": "malloc_context_size=5:" + os.environ.get("ASAN_OPTIONS", ""),
        })
        cmd = [args.fuzzer, f"-timeout={args.timeout}", "-rss_limit_mb=6000"] + files
        print(f"== {len(files)} seeds, expected to be {expect}ed ({lang}, {std})"
              + (", each generated twice" if recheck else "")
              + ("" if compile else ", output not parsed (the build compiles it)"), flush=True)
        start = time.time()
        proc = subprocess.run(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                              text=True, errors="replace")
        out = proc.stdout
        runs = re.findall(r"^Executed (.+) in (\d+) ms$", out, re.M)
        slowest += [(int(ms), os.path.basename(f)) for f, ms in runs]
        if proc.returncode != 0 or len(runs) != len(files):
            status = 1
            print(out)
            print(f"run_seeds.py: FAILED (exit {proc.returncode}; {len(runs)} of {len(files)} "
                  f"seeds ran)", flush=True)
        else:
            print(f"   all {len(files)} ran ({time.time() - start:.0f} s)", flush=True)
    slowest.sort(reverse=True)
    print("slowest: " + ", ".join(f"{n} {ms / 1000:.1f} s" for ms, n in slowest[:5]))
    return status


if __name__ == "__main__":
    sys.exit(main())
