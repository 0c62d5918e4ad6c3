#!/usr/bin/env python3
"""Name-clash fuzzing of the generator (issue 20, defect 2).

No identifier dpgen makes up (accumulators, cell counters, loop bounds, sizes,
lambdas, the locals its derivative rules introduce) may ever be one of the
user's. For randomly chosen kernel files of the repository, this renames one
identifier the kernel declares (a parameter, a local, a loop counter) to a
name the generated code of that kernel uses for something of its own, runs
dpgen (adjoint, tangent), and compiles what it wrote with -Wshadow -Werror:
a clash is a redeclaration (a compile error) or a shadowed name (the
warning), the way a silently wrong adjoint would come about. A renamed
kernel must also be accepted exactly when the original is, unless the new
name is one the signature rule gives to an adjoint (<array>_adj, <array>_dot),
which dpgen rejects with a message that says so.

  name_clash_fuzz.py --dpgen D --include I --cases N --seed S [--keep DIR]
"""
import argparse
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DIRS = ["kernels", "tests/kernels", "tests/styles", "tests/adversary", "examples/kernels"]
# Type words before a declared name: `double s`, `const int n`, `double* u`.
DECL = re.compile(r"\b(?:double|float|int|long|unsigned|size_t|std::size_t|std::ptrdiff_t|bool)"
                  r"\s*(?:const\s*)?[*&]?\s*(?:__restrict__|restrict)?\s*([A-Za-z_]\w*)\s*[,;=)\[]")
IDENT = re.compile(r"\b[A-Za-z_]\w*\b")
CXX_DECL = re.compile(r"\b(?:const\s+)?(?:double|float|int|bool|auto|std::ptrdiff_t|std::size_t|size_t)"
                      r"\s*\*?\s+([A-Za-z_]\w*)\b")


# Words of the language, never a name the generated code makes up.
KEYWORDS = {"const", "restrict", "volatile", "auto", "int", "long", "short", "unsigned", "signed",
            "double", "float", "bool", "char", "void", "static", "inline", "return", "if", "else",
            "for", "while", "do", "switch", "case", "break", "continue", "struct", "class",
            "template", "typename", "namespace", "using", "new", "delete", "this", "true", "false",
            "nullptr", "operator", "sizeof", "std", "constexpr", "extern"}


def run(cmd, cwd=None):
    return subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          text=True)


def kernel_files():
    out = []
    for d in DIRS:
        full = os.path.join(ROOT, d)
        if not os.path.isdir(full):
            continue
        for f in sorted(os.listdir(full)):
            if f.endswith(".cpp") and not f.endswith("_test.cpp") and f != "main.cpp":
                path = os.path.join(full, f)
                with open(path) as fh:
                    if "DPGEN_KERNEL" in fh.read():
                        out.append(path)
    return out


def generate(dpgen, include, src, out_dir, flags, src_dir=None):
    """dpgen on `src`; headers beside the original kernel come from src_dir."""
    os.makedirs(out_dir, exist_ok=True)
    return run([dpgen] + flags + [src, "--out-dir", out_dir, "--", "-I" + include,
                                  "-I" + (src_dir or os.path.dirname(src)), "-std=c++17"])


def compiles(cxx, out_dir, include, extra):
    for f in sorted(os.listdir(out_dir)):
        if f.endswith(".cpp"):
            r = run([cxx, "-std=c++17", "-fopenmp", "-Wshadow", "-Werror", "-fsyntax-only",
                     "-I" + out_dir, "-I" + include] + extra + [os.path.join(out_dir, f)])
            if r.returncode != 0:
                return f, r.stdout
    return None, ""


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--dpgen", required=True)
    ap.add_argument("--include", required=True)
    ap.add_argument("--cases", type=int, default=40)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--cxx", default="g++")
    ap.add_argument("--keep", help="keep failing cases here")
    args = ap.parse_args()
    rng = random.Random(args.seed)
    work = tempfile.mkdtemp(prefix="dpgen-names-")
    files = kernel_files()
    passed = failed = tried = 0
    cache = {}  # file -> (victims, pool), or None where nothing can be renamed

    def candidates(src):
        if src not in cache:
            text = open(src).read()
            base_dir = os.path.join(work, "base")
            shutil.rmtree(base_dir, ignore_errors=True)
            cache[src] = None
            if generate(args.dpgen, args.include, src, base_dir, ["--tangent"]).returncode == 0:
                user = set(IDENT.findall(text))
                generated = set()
                for f in os.listdir(base_dir):
                    generated |= set(CXX_DECL.findall(open(os.path.join(base_dir, f)).read()))
                # The generated code's own names: not the user's, not contract names.
                pool = sorted(n for n in generated - user
                              if not n.endswith("_adj") and not n.endswith("_dot")
                              and not n.startswith("dpgen_") and not n.startswith("__")
                              and n not in KEYWORDS)
                victims = sorted(set(DECL.findall(text)) & user)
                if pool and victims:
                    cache[src] = (victims, pool)
        return cache[src]

    try:
        attempts = 0
        while tried < args.cases and attempts < 20 * args.cases:
            attempts += 1
            src = rng.choice(files)
            c = candidates(src)
            if c is None:
                continue
            victims, pool = c
            text = open(src).read()
            victim, target = rng.choice(victims), rng.choice(pool)
            tried += 1
            renamed = re.sub(r"\b%s\b" % re.escape(victim), target, text)
            case_dir = os.path.join(work, "case")
            shutil.rmtree(case_dir, ignore_errors=True)
            os.makedirs(case_dir)
            case_src = os.path.join(case_dir, os.path.basename(src))
            with open(case_src, "w") as fh:
                fh.write(renamed)
            # Headers next to the kernel (helpers) are found through -I<its folder>.
            gen_dir = os.path.join(case_dir, "gen")
            r = generate(args.dpgen, args.include, case_src, gen_dir, ["--tangent"],
                         os.path.dirname(src))
            what = "%s: '%s' renamed '%s'" % (os.path.relpath(src, ROOT), victim, target)
            problem = None
            if r.returncode != 0:
                # the user's names are free: renaming must not change acceptance
                r2 = run([args.dpgen, src, "--out-dir", os.path.join(case_dir, "x"), "--",
                          "-I" + args.include, "-I" + os.path.dirname(src), "-std=c++17"])
                problem = "rejected after the rename:\n" + r.stdout if r2.returncode == 0 else None
            else:
                bad, log = compiles(args.cxx, gen_dir, args.include, ["-I" + os.path.dirname(src)])
                if bad:
                    problem = "generated %s does not compile cleanly:\n%s" % (bad, log[:3000])
            if problem:
                failed += 1
                print("FAIL %s: %s" % (what, problem))
                if args.keep:
                    dst = os.path.join(args.keep, "case%d" % tried)
                    shutil.copytree(case_dir, dst, dirs_exist_ok=True)
            else:
                passed += 1
                print("ok   %s" % what)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print("name clash fuzz: %d passed, %d failed" % (passed, failed))
    return 1 if failed or passed == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
