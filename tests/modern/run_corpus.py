#!/usr/bin/env python3
"""Acceptance corpus of issue 22 (modern C++ kernels): run dpgen on every
kernel file under tests/modern/kernels/, and for each accepted file compile
and run its harness (tests/modern/harness/<stem>_test.cpp: dot-product test
against the forward code, FD gradient, += contract, guard cells, and the
tangent: J v against central differences, <w, J v> = <v, J^T w>).

Prints one row per kernel (a harness TEST_CASE, or a DPGEN_KERNEL of a file
expected to be rejected):

  kernel | file | form | expected | generator | harness

generator: accepted / rejected: <first error> / CRASH / timeout
harness:   pass / WRONG: <first failure> / does not compile: <first error> /
           (adjoint only: "pass, tangent does not compile" when the harness
           compiles without its tangent part only) / - (not run)
An expected-reject file that dpgen accepts is flagged "ACCEPTED (expected reject)".

  run_corpus.py [--dpgen PATH] [--forms f1,f2] [--only stem ...] [--jobs N]
                [--strict] [--selfcheck] [--keep] [--markdown FILE]

--selfcheck checks the harnesses and forward kernels without dpgen: the
adjoint is replaced by finite differences of the forward kernel
(tests/styles/selfcheck/support/adjoint_check.hpp), the generated headers by
stubs; every harness must pass (a failure is a bug in the corpus, not in dpgen).
--strict exits 1 unless every selected expected-accept kernel passes and every
expected-reject file is rejected (what the optional ctest runs, per form).
"""
import argparse
import concurrent.futures as cf
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
KDIR = os.path.join(HERE, "kernels")
HDIR = os.path.join(HERE, "harness")
IDIR = os.path.join(HERE, "include")
RUNTIME_INC = os.path.join(ROOT, "runtime", "include")
TESTS = os.path.join(ROOT, "tests")
SELFCHECK_INC = os.path.join(ROOT, "tests", "styles", "selfcheck")
DEFAULT_DPGEN = next((p for p in (os.path.join(ROOT, "build", "tool", "dpgen"),
                                   "/work/main/build/tool/dpgen") if os.access(p, os.X_OK)),
                     os.path.join(ROOT, "build", "tool", "dpgen"))


def meta(path):
    """`// corpus: form=X expect=accept|reject` on the first line; for a
    reject, `// reason: ...` (continued on `//   ...` lines)."""
    form, expect, reason = "?", "accept", []
    lines = open(path).read().splitlines()[:12]
    in_reason = False
    for line in lines:
        m = re.match(r"\s*//\s*corpus:\s*(.*)", line)
        if m:
            for kv in m.group(1).split():
                k, _, v = kv.partition("=")
                if k == "form":
                    form = v
                elif k == "expect":
                    expect = v
            continue
        m = re.match(r"\s*//\s*reason:\s*(.*)", line)
        if m:
            reason, in_reason = [m.group(1)], True
            continue
        m = re.match(r"\s*//   +(\S.*)", line)
        if in_reason and m:
            reason.append(m.group(1))
            continue
        in_reason = False
    return form, expect, " ".join(reason)


def kernel_names(path):
    text = open(path).read()
    names = []
    for m in re.finditer(r"DPGEN_KERNEL\b([^;{]*?)\(", text, re.S):
        head = m.group(1).split()
        if head:
            names.append(re.sub(r"^.*::", "", head[-1]))
    return names or ["?"]


def test_cases(harness):
    return re.findall(r'TEST_CASE\("([^"]+)"\)', open(harness).read())


def run(cmd, timeout, cwd=None, env=None):
    try:
        p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=timeout,
                           cwd=cwd, env=env, text=True, errors="replace")
        return p.returncode, p.stdout
    except subprocess.TimeoutExpired as e:
        out = e.stdout if isinstance(e.stdout, str) else (e.stdout or b"").decode("utf8", "replace")
        return 124, out


def first(pattern, text, default=""):
    for line in text.splitlines():
        if re.search(pattern, line):
            return line.strip()
    return default


def short(msg, n=150):
    msg = re.sub(r"^\S*/", "", msg)  # drop the directory of a file:line:col
    return msg if len(msg) <= n else msg[: n - 3] + "..."


STUB_RE = re.compile(r"\b([A-Za-z_]\w*_(?:adjoint|tangent)(?:_checked)?)\s*(<)?")


def write_stubs(harness, gen, stem):
    """Selfcheck: a do-nothing template for each generated name the harness
    calls without explicit template arguments (those with them the harness
    stubs itself under CORPUS_SELFCHECK)."""
    text = open(harness).read()
    names, templated = set(), set()
    for m in STUB_RE.finditer(text):
        (templated if m.group(2) else names).add(m.group(1))
    for name in sorted(names - templated):
        if not re.search(r"\b" + name + r"\s*\(", text):
            names.discard(name)
    body = "".join("template <class... T, class... A> double %s(A&&...) { return 0; }\n" % n
                   for n in sorted(names - templated))
    with open(os.path.join(gen, "%s_adjoint.hpp" % stem), "w") as f:
        f.write("#pragma once\n" + body)
    with open(os.path.join(gen, "%s_tangent.hpp" % stem), "w") as f:
        f.write("#pragma once\n")


class Ctx:
    pass


def one_file(ctx, kpath):
    stem = os.path.basename(kpath)[:-4]
    form, expect, reason = meta(kpath)
    harness = os.path.join(HDIR, stem + "_test.cpp")
    has_h = os.path.exists(harness)
    names = test_cases(harness) if has_h else []
    rows_names = [n.replace("modern: ", "") for n in names] if names else kernel_names(kpath)
    work = os.path.join(ctx.work, stem)
    gen = os.path.join(work, "gen")
    os.makedirs(gen, exist_ok=True)
    base = dict(file=stem + ".cpp", form=form, expect=expect, reason=reason)

    def rows(gen_res, h_res):
        if isinstance(h_res, dict):
            return [dict(base, kernel=n, generator=gen_res, harness=h_res.get(n, "-"))
                    for n in rows_names]
        return [dict(base, kernel=n, generator=gen_res, harness=h_res) for n in rows_names]

    # 1. the generator
    if ctx.selfcheck:
        gen_res = "(selfcheck)"
        if not has_h:
            return rows(gen_res, "-")
        write_stubs(harness, gen, stem)
    else:
        cmd = [ctx.dpgen, kpath, "--tangent", "--out-dir", gen, "--", "-std=c++17",
               "-I" + RUNTIME_INC, "-I" + IDIR, "-I" + KDIR]
        rc, out = run(cmd, 180)
        with open(os.path.join(work, "dpgen.log"), "w") as f:
            f.write(out)
        if rc >= 124 or rc < 0 or re.search(r"Stack dump|Assertion|Segmentation|terminate called|"
                                            r"PLEASE submit", out):
            return rows("CRASH rc=%d: %s" % (rc, short(first(r"error|Assert|Segm", out))), "-")
        if rc != 0:
            err = first(r"error:", out, first(r".", out))
            err = re.sub(r"^.*?error:\s*", "", err)
            where = first(r"error:", out)
            m = re.match(r"^(\S+?):(\d+):\d+:", where)
            loc = ("%s:%s " % (os.path.basename(m.group(1)), m.group(2))) if m else ""
            written = os.listdir(gen)
            note = " [but wrote %s]" % ",".join(written) if written else ""
            nerr = len(re.findall(r"error:", out))
            ctx.all_errors.extend((stem, re.sub(r"^.*?error:\s*", "", l).strip())
                                  for l in out.splitlines() if "error:" in l)
            more = " (+%d more)" % (nerr - 1) if nerr > 1 else ""
            return rows("rejected%s: %s%s%s" % (more, loc, short(err), note), "-")
        if not os.path.exists(os.path.join(gen, stem + "_adjoint.cpp")):
            return rows("CRASH: exit 0, no %s_adjoint.cpp" % stem, "-")
        warn = out.count("warning:")
        gen_res = "accepted" + (" (%d warning%s)" % (warn, "s" * (warn > 1)) if warn else "")
        if expect == "reject":
            gen_res = "ACCEPTED (expected reject)"
        if not has_h:
            return rows(gen_res, "-")

    # 2. the harness: with its tangent part, else adjoint only
    srcs = [harness, ctx.main_o]
    for kind in ("adjoint", "tangent"):
        g = os.path.join(gen, "%s_%s.cpp" % (stem, kind))
        if os.path.exists(g):
            srcs.append(g)
    incs = (["-I" + SELFCHECK_INC] if ctx.selfcheck else []) + [
        "-I" + HDIR, "-I" + IDIR, "-I" + KDIR, "-I" + gen, "-I" + RUNTIME_INC, "-I" + TESTS]
    # (the checker's one compiled copy is in main.o: tests/kernels/main.cpp)
    flags = [ctx.cxx, "-std=c++17", "-O1", "-fopenmp", "-DDPGEN_TEST_CHECKER_COMPILED_ONCE"] + incs
    if ctx.selfcheck:
        flags.append("-DCORPUS_SELFCHECK=1")
    # What dpgen writes must build in a user's strict build (-Wall -Wextra
    # -Werror), headers included; the harness and the kernel are not ours to hold to it.
    # Each generated file is compiled once, to the object the harness links.
    objs = []
    for g in srcs[2:]:
        strict = [] if ctx.selfcheck else ["-Wall", "-Wextra", "-Werror"]
        rc, out = run(flags + strict + ["-c", g, "-o", g + ".o"], 600)
        if rc != 0:
            return rows(gen_res, "does not compile: " + ("generated code warns under -Wall "
                        "-Wextra -Werror: " if strict else "") +
                        short(first(r"error", out, first(r".", out))))
        objs.append(g + ".o")
    srcs = srcs[:2] + objs
    exe = os.path.join(work, "t")
    note = ""
    rc, out = run(flags + ["-DCORPUS_TANGENT=1"] + srcs + ["-o", exe], 600)
    if rc != 0:
        log1 = out
        rc, out = run(flags + ["-DCORPUS_TANGENT=0"] + srcs + ["-o", exe], 600)
        with open(os.path.join(work, "cxx.log"), "w") as f:
            f.write(log1 + "\n---- without the tangent ----\n" + out)
        if rc != 0:
            return rows(gen_res, "does not compile: " + short(first(r"error", out, first(r".", out))))
        note = ", tangent does not compile: " + short(first(r"error", log1), 90)
    res = {}
    env = dict(os.environ, OMP_NUM_THREADS="2")
    for n in names:
        rc, out = run([exe, "-tc=" + n, "--no-colors"], 600, env=env)
        with open(os.path.join(work, "run_%s.log" % n.replace("modern: ", "")), "w") as f:
            f.write(out)
        key = n.replace("modern: ", "")
        if rc == 0:
            res[key] = "pass" + note
        elif rc >= 124 or rc < 0:
            res[key] = "CRASH/timeout rc=%d" % rc + note
        else:
            msg = ""
            for pat in (r"disagree", r"overwrote", r"differ from", r"wrote outside",
                        r"exception|threw|what\(\)", r"<Jv,w> =|<w, J v>", r"ERROR", r"FAIL"):
                msg = first(pat, out)
                if msg:
                    break
            msg = re.sub(r"^(logged|ERROR|MESSAGE):\s*", "", msg)
            res[key] = "WRONG: " + short(msg, 110) + note
    return rows(gen_res, res)


def main():
    signal.signal(signal.SIGPIPE, signal.SIG_DFL)
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--dpgen", default=os.environ.get("DPGEN", DEFAULT_DPGEN),
                    help="default: $DPGEN, else <repo>/build/tool/dpgen, else /work/main/build/tool/dpgen")
    ap.add_argument("--forms", default="", help="comma-separated forms to run (default: all)")
    ap.add_argument("--only", nargs="*", default=[], help="kernel file stems")
    ap.add_argument("--jobs", type=int, default=int(os.environ.get("JOBS", "2")))
    ap.add_argument("--cxx", default=os.environ.get("CXX", "g++"))
    ap.add_argument("--strict", action="store_true")
    ap.add_argument("--selfcheck", action="store_true")
    ap.add_argument("--keep", action="store_true")
    ap.add_argument("--markdown", help="also write the table as markdown to this file")
    args = ap.parse_args()

    ctx = Ctx()
    ctx.selfcheck = args.selfcheck
    ctx.dpgen = os.path.abspath(args.dpgen)
    ctx.cxx = args.cxx
    if not args.selfcheck and not os.access(ctx.dpgen, os.X_OK):
        sys.exit("run_corpus.py: no dpgen at %s (--dpgen PATH)" % ctx.dpgen)
    ctx.work = tempfile.mkdtemp(prefix="dpgen-modern.")
    ctx.all_errors = []
    forms = set(f for f in args.forms.split(",") if f)
    files = []
    for f in sorted(os.listdir(KDIR)):
        if not f.endswith(".cpp"):
            continue
        if args.only and f[:-4] not in args.only:
            continue
        if forms and meta(os.path.join(KDIR, f))[0] not in forms:
            continue
        files.append(os.path.join(KDIR, f))
    ctx.main_o = os.path.join(ctx.work, "main.o")
    rc, out = run([ctx.cxx, "-std=c++17", "-O1", "-DDPGEN_TEST_CHECKER_COMPILED_ONCE", "-I" + TESTS,
                   "-c", os.path.join(TESTS, "kernels", "main.cpp"), "-o", ctx.main_o], 300)
    if rc != 0:
        sys.exit("cannot build the doctest main:\n" + out)

    rows = []
    with cf.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as ex:
        for r in ex.map(lambda k: one_file(ctx, k), files):
            rows.extend(r)

    cols = ["kernel", "file", "form", "expected", "generator", "harness"]
    table = [[r["kernel"], r["file"], r["form"], r["expect"], r["generator"], r["harness"]]
             for r in rows]
    w = [max(len(c), *(len(t[i]) for t in table)) if table else len(c) for i, c in enumerate(cols)]
    w = [min(x, 60) for x in w[:4]] + w[4:]
    line = lambda t: "  ".join(str(x).ljust(w[i]) if i < 4 else str(x) for i, x in enumerate(t))
    print(line(cols))
    for t in table:
        print(line(t))

    # The expected-reject files: why, and what dpgen said.
    shown = set()
    rej = [r for r in rows if r["expect"] == "reject" and r["file"] not in shown
           and not shown.add(r["file"])]
    if rej and not args.selfcheck:
        print("\nexpected rejections: the reason (kernel file), then what dpgen did")
        for r in rej:
            print("  %s: %s\n      -> %s" % (r["file"], r["reason"], r["generator"]))

    # Summary per form.
    print()
    summary = {}
    for r in rows:
        s = summary.setdefault(r["form"], dict(n=0, acc=0, rej=0, crash=0, ok=0, wrong=0, nocomp=0,
                                               bad_accept=0))
        s["n"] += 1
        g = r["generator"]
        if g.startswith("accepted") or g.startswith("ACCEPTED") or (
                g == "(selfcheck)" and r["expect"] == "accept"):
            s["acc"] += 1
        elif g.startswith("rejected"):
            s["rej"] += 1
        elif g != "(selfcheck)":
            s["crash"] += 1
        if g.startswith("ACCEPTED"):
            s["bad_accept"] += 1
        h = r["harness"]
        if h.startswith("pass"):
            s["ok"] += 1
        elif h.startswith("WRONG") or h.startswith("CRASH"):
            s["wrong"] += 1
        elif h.startswith("does not compile"):
            s["nocomp"] += 1
    print("form          kernels  accepted  rejected  crash  pass  wrong  no-compile  accepted-but-expected-reject")
    for f in sorted(summary):
        s = summary[f]
        print("%-13s %7d  %8d  %8d  %5d  %4d  %5d  %10d  %d" % (
            f, s["n"], s["acc"], s["rej"], s["crash"], s["ok"], s["wrong"], s["nocomp"],
            s["bad_accept"]))
    if not args.selfcheck:
        def norm(m):
            m = re.sub(r"'[^']*'", "'X'", m)
            m = re.sub(r"\(\w+ = [^)]*\)", "(...)", m)
            return m[:110]
        firsts, seen = {}, set()
        for r in rows:
            if r["generator"].startswith("rejected") and r["file"] not in seen:
                seen.add(r["file"])
                m = re.sub(r"^rejected[^:]*: \S+:\d+ ", "", r["generator"])
                firsts[norm(m)] = firsts.get(norm(m), 0) + 1
        if firsts:
            print("\nfirst error of each rejected file (names replaced by 'X'), by count of files:")
            for m, c in sorted(firsts.items(), key=lambda kv: -kv[1]):
                print("%4d  %s" % (c, m))
        alls = {}
        for stem, m in ctx.all_errors:
            alls.setdefault(norm(m), set()).add(stem)
        if alls:
            print("\nevery error reported (dpgen reports all errors of a file), by count of files:")
            for m, files in sorted(alls.items(), key=lambda kv: -len(kv[1])):
                print("%4d  %s" % (len(files), m))

    if args.markdown:
        with open(args.markdown, "w") as f:
            f.write("| " + " | ".join(cols) + " |\n|" + "---|" * len(cols) + "\n")
            for t in table:
                f.write("| " + " | ".join(x.replace("|", "\\|") for x in t) + " |\n")

    if args.keep:
        print("\nwork dir: " + ctx.work)
    else:
        shutil.rmtree(ctx.work, ignore_errors=True)

    if args.strict:
        bad = [r for r in rows
               if (r["expect"] == "accept" and not r["harness"].startswith("pass"))
               or (r["expect"] == "reject" and not r["generator"].startswith("rejected")
                   and not args.selfcheck)]
        if bad:
            print("\n%d kernel(s) not as expected" % len(bad))
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
