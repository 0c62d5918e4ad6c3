#!/usr/bin/env python3
"""Compares two training logs (iter,loss,grad_norm,seconds) row by row: the same iterations,
and every loss within a tolerance of the reference's,
    row TOL:    |loss - ref| <= TOL * |ref|      (relative to each row's loss)
    first TOL:  |loss - ref| <= TOL * |ref[0]|   (relative to the first loss)
Prints the largest differences; exit status 1 when a row differs more, or the rows differ.

usage: compare_loss.py REFERENCE.csv OTHER.csv row|first TOL"""
import csv
import sys


def read(path):
    with open(path, newline="") as f:
        return [(int(r["iter"]), float(r["loss"])) for r in csv.DictReader(f)]


def main():
    if len(sys.argv) != 5 or sys.argv[3] not in ("row", "first"):
        sys.exit(__doc__)
    ref, other = read(sys.argv[1]), read(sys.argv[2])
    mode, tol = sys.argv[3], float(sys.argv[4])
    if not ref or [i for i, _ in ref] != [i for i, _ in other]:
        print(f"different iterations: {len(ref)} rows against {len(other)}")
        return 1
    first = abs(ref[0][1])
    pairs = [(a, b) for (_, a), (_, b) in zip(ref, other)]
    of_first = max(abs(a - b) for a, b in pairs) / first
    of_row = max(abs(a - b) / abs(a) if a else abs(b) for a, b in pairs)
    print(f"{len(ref)} rows, first loss {first:.6e}: largest difference {of_row:.3e} of the "
          f"row's loss, {of_first:.3e} of the first loss (tolerance {mode} {tol:g})")
    return 0 if (of_row if mode == "row" else of_first) <= tol else 1


if __name__ == "__main__":
    sys.exit(main())
