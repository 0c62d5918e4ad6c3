#!/usr/bin/env python3
# Writes tests/adversary/<name>.cpp and <name>_test.cpp from the specs in
# specs.py. Params: ("in", name, size[, cast]) ("out", name, size[, cast])
# ("val", expr), ("io", name, size): a DPGEN_INOUT array (round r5; an input
# and an output of the Problem: the forward copies it, the adjoint adds the
# returned adjoint of the old values, the tangent copies value and direction).
# "cases": raw test cases appended (hand-computed ties: name them "... ties").
# reject=True: dpgen must refuse the kernel (no test run).
import os, re, sys
here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, here)
import importlib
SPECS = importlib.import_module(os.environ.get("ADV_SPECS", "specs")).SPECS

def cst(c, const):
    if not c: return ""
    return "(const %s)" % c if const else "(%s)" % c

def emit(s):
    name = s["name"]; src = s["src"].strip() + "\n"
    head = '#include "dpgen/annotate.hpp"\n' + s.get("includes", "")
    open(os.path.join(here, name + ".cpp"), "w").write("// adversary: %s\n%s\n%s" % (s.get("why", ""), head, src))
    if s.get("handtest"): return
    if s.get("reject"):
        open(os.path.join(here, name + "_test.cpp"), "w").write(
            "// %s: dpgen must reject this kernel (no test).\n" % name)
        return
    protos = re.findall(r"DPGEN_KERNEL[^{;]*?\)(?=\s*\{)", src, re.S)
    P = s["params"]; fname = s.get("kernel", name)
    ins = [p for p in P if p[0] in ("in", "inr", "io")]; outs = [p for p in P if p[0] in ("out", "outr", "io")]
    fw, ad, tg = [], [], []
    pf, pa, pt = [], [], []  # row-pointer tables built inside each lambda
    ki = ko = 0
    post_a = []
    T = s.get("T", "double")
    for p in P:
        if p[0] == "io":
            S = "size_t(%s)" % p[2]
            pf.append("std::copy(in[%d], in[%d] + %s, out[%d]);" % (ki, ki, S, ko)); fw.append("out[%d]" % ko)
            pa.append("std::vector<%s> t%d(seed[%d], seed[%d] + %s);" % (T, ko, ko, ko, S)); ad += ["in[%d]" % ki, "t%d.data()" % ko]
            post_a.append("for (size_t z = 0; z < t%d.size(); ++z) adj[%d][z] += t%d[z];" % (ko, ki, ko))
            pt += ["std::copy(in[%d], in[%d] + %s, out[%d]);" % (ki, ki, S, ko), "std::copy(dir[%d], dir[%d] + %s, outd[%d]);" % (ki, ki, S, ko)]
            tg += ["out[%d]" % ko, "outd[%d]" % ko]
            ki += 1; ko += 1
            continue
        if p[0] in ("inr", "outr"):
            # ("inr"/"outr", name, rows, cols): double** over a flat rows x cols buffer
            R, C = p[2], p[3]
            def rw(v, src): return "auto %s = styles::rows(%s, size_t(%s), size_t(%s));" % (v, src, R, C)
            if p[0] == "inr":
                pf.append(rw("ri%d" % ki, "in[%d]" % ki)); fw.append("ri%d.data()" % ki)
                pa += [rw("ri%d" % ki, "in[%d]" % ki), rw("ai%d" % ki, "adj[%d]" % ki)]; ad += ["ri%d.data()" % ki, "ai%d.data()" % ki]
                pt += [rw("ri%d" % ki, "in[%d]" % ki), rw("di%d" % ki, "dir[%d]" % ki)]; tg += ["ri%d.data()" % ki, "di%d.data()" % ki]
                ki += 1
            else:
                pf.append(rw("ro%d" % ko, "out[%d]" % ko)); fw.append("ro%d.data()" % ko)
                pa.append(rw("so%d" % ko, "seed[%d]" % ko)); ad.append("so%d.data()" % ko)
                pt += [rw("ro%d" % ko, "out[%d]" % ko), rw("do%d" % ko, "outd[%d]" % ko)]; tg += ["ro%d.data()" % ko, "do%d.data()" % ko]
                ko += 1
            continue
        if p[0] == "in":
            c = p[3] if len(p) > 3 else None
            fw.append("%sin[%d]" % (cst(c, 1), ki)); ad += ["%sin[%d]" % (cst(c, 1), ki), "%sadj[%d]" % (cst(c, 0), ki)]
            tg += ["%sin[%d]" % (cst(c, 1), ki), "%sdir[%d]" % (cst(c, 1), ki)]; ki += 1
        elif p[0] == "out":
            c = p[3] if len(p) > 3 else None
            fw.append("%sout[%d]" % (cst(c, 0), ko)); ad.append("%sseed[%d]" % (cst(c, 1), ko))
            tg += ["%sout[%d]" % (cst(c, 0), ko), "%soutd[%d]" % (cst(c, 0), ko)]; ko += 1
        else:
            fw.append(p[1]); ad.append(p[1]); tg.append(p[1])
    rng = s.get("ranges", "")
    sz = lambda p: "size_t(%s) * size_t(%s)" % (p[2], p[3]) if p[0] in ("inr", "outr") else "size_t(%s)" % p[2]
    t = ['#include "support/adjoint_check.hpp"', '#include "styles/styles_support.hpp"', '#include <algorithm>', '#include <stdexcept>', head.strip(),
         '#include "%s_adjoint.hpp"' % name, '#include "%s_tangent.hpp"' % name, ""]
    t += [p + ";" for p in protos]
    t += ['TEST_CASE("adversary: %s") {' % name, "  %s {" % s.get("loop", "for (int n : {0, 1, 2, 3, 4, 7, 16})")]
    t += ["    " + l for l in s.get("pre", "").splitlines()]
    t += ["    CAPTURE(n);", "    dpgen_test::Problem<%s> p;" % T,
          "    p.in_sizes = {%s};" % ", ".join(sz(p) for p in ins),
          "    p.out_sizes = {%s};" % ", ".join(sz(p) for p in outs)]
    if rng: t.append("    p.in_ranges = {%s};" % rng)
    if s.get("linear"): t.append("    p.linear = true;")
    t += ["    p.forward = [&](auto in, auto out) { %s%s(%s); };" % (" ".join(pf + [""]), fname, ", ".join(fw)),
          "    p.adjoint = [&](auto in, auto adj, auto seed) { %s%s_adjoint(%s);%s };" % (" ".join(pa + [""]), fname, ", ".join(ad), "".join(" " + x for x in post_a))]
    if not s.get("notangent"):
        t.append("    p.tangent = [&](auto in, auto dir, auto out, auto outd) { %s%s_tangent(%s); };" % (" ".join(pt + [""]), fname, ", ".join(tg)))
    t += ["    dpgen_test::check_adjoint(p);", "  }"]
    t += ["  " + l for l in s.get("extra", "").splitlines()]
    t += ["}", ""]
    if s.get("cases"): t += [s["cases"].strip(), ""]
    open(os.path.join(here, name + "_test.cpp"), "w").write("\n".join(t))

only = sys.argv[1:]
for s in SPECS:
    if not only or s["name"] in only:
        emit(s)
