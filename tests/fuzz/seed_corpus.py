#!/usr/bin/env python3
"""Writes the fuzzer's seed corpus: each kernel file made self-contained.

The fuzzer hands the generator one buffer with no include path beyond
dpgen/annotate.hpp, so a seed's own headers are inlined here: a
`#include "x.hpp"` found next to the including file is replaced by that
header's text, once per seed, except the style corpus's class headers
(`include/user_views.hpp`, `include/boundary_kinds.hpp`: view and member
classes and enum parameters' types must be in a header, and
fuzz_generator.cpp maps them);
the generated-declaration headers (`*kernels.hpp`, `operators.hpp`) become
`#include "dpgen/annotate.hpp"` (they declare the kernels and include it).

  seed_corpus.py OUT_DIR kernel.cpp...
"""
import os
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"\s*$')
ANNOTATE = '#include "dpgen/annotate.hpp"'


def inline(path, seen):
    out = []
    with open(path, encoding="utf-8") as f:
        for line in f:
            m = INCLUDE.match(line)
            if not m:
                if line.strip() != "#pragma once":
                    out.append(line)
                continue
            name = m.group(1)
            if name == "dpgen/annotate.hpp" or name.endswith("kernels.hpp") or name == "operators.hpp":
                out.append(ANNOTATE + "\n")
                continue
            if name.startswith("include/"):  # (class headers: the fuzzer maps them)
                out.append(line)
                continue
            header = os.path.normpath(os.path.join(os.path.dirname(path), name))
            if not os.path.isfile(header):
                out.append(line)  # (left as written: the seed will not parse)
                continue
            if header not in seen:
                seen.add(header)
                out.append(f"// ---- {name} (inlined) ----\n")
                out.extend(inline(header, seen))
    return out


def main():
    out_dir, seeds = sys.argv[1], sys.argv[2:]
    os.makedirs(out_dir, exist_ok=True)
    for s in seeds:
        text = inline(s, set())
        with open(os.path.join(out_dir, os.path.basename(s)), "w", encoding="utf-8") as f:
            f.writelines(text)


if __name__ == "__main__":
    main()
