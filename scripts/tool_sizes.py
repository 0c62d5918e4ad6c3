#!/usr/bin/env python3
"""Sizes of the generator's files and classes (issue 21's bars: no file in tool/ over 1,000
lines, no class over 600). A class's size is its definition (`class X {` ... `};` at column 0,
comments included) plus the out-of-line definitions of its members in any file (`... X::f(...)
{` ... `}` at column 0, with the comment lines just above them).

  scripts/tool_sizes.py [--check] [--top N]

Prints the largest files and classes; with --check exits 1 when a bar is passed."""
import argparse
import collections
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
FILE_BAR, CLASS_BAR = 1000, 600


def sources():
    for ext in ('*.cpp', '*.hpp', '*.h'):
        yield from (ROOT / 'tool').rglob(ext)


def class_sizes(files):
    sizes = collections.Counter()
    head = re.compile(r'^(?:class|struct) (\w+)(?: final)?(?: : [^{;]*)? \{')
    member = re.compile(r'^[^\s/#].*?\b(\w+)::~?\w+\(')
    for path in files:
        lines = path.read_text().split('\n')
        i = 0
        while i < len(lines):
            line = lines[i]
            start, closer = i, None
            m = head.match(line)
            if m:
                closer = '};'  # a class: its definition
            else:
                m = member.match(line)
                if m and not line.rstrip().endswith(';'):
                    closer = '}'  # a member defined out of line, with its comment
                    while start > 0 and lines[start - 1].startswith('//'):
                        start -= 1
            if closer is None:
                i += 1
                continue
            j = i
            while j < len(lines) and lines[j] != closer:
                j += 1
            sizes[m.group(1)] += j - start + 1
            i = j + 1
    return sizes


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--check', action='store_true', help='exit 1 when a bar is passed')
    ap.add_argument('--top', type=int, default=10)
    args = ap.parse_args()
    files = sorted(sources())
    lengths = {p: len(p.read_text().split('\n')) - 1 for p in files}
    classes = class_sizes(files)
    print(f'largest files (bar {FILE_BAR} lines):')
    for p, n in sorted(lengths.items(), key=lambda kv: -kv[1])[:args.top]:
        print(f'  {n:5d}  {p.relative_to(ROOT)}')
    print(f'largest classes (bar {CLASS_BAR} lines: definition and out-of-line members):')
    for name, n in classes.most_common(args.top):
        print(f'  {n:5d}  {name}')
    over = [f'file {p.relative_to(ROOT)}: {n} lines' for p, n in lengths.items() if n > FILE_BAR]
    over += [f'class {name}: {n} lines' for name, n in classes.items() if n > CLASS_BAR]
    for o in over:
        print(f'over the bar: {o}', file=sys.stderr)
    return 1 if args.check and over else 0


if __name__ == '__main__':
    sys.exit(main())
