#!/usr/bin/env bash
# Regression guard for the gather form's main property: the branch-free
# interior of every generated adjoint given as an argument vectorizes
# (GCC -O3 -march=native -fopt-info-vec). Timing is for bench/; this only
# asks the compiler.
#   vectorization_check.sh <c++ compiler> <generated_adjoint.cpp>...
set -euo pipefail
cxx=$1
shift
status=0
for f in "$@"; do
  report=$("$cxx" -std=c++17 -O3 -march=native -fopenmp -I"$(dirname "$f")" \
             -c "$f" -o /dev/null -fopt-info-vec-optimized 2>&1 || true)
  # The interior's lines: the lambda's body, and the loops that call it (GCC
  # reports an inlined body at either place).
  lines=$(awk '/auto interior = /{s=NR} s {print NR} s && /^ *};/{s=0}
               /for \(/{f=NR} /interior\(c_/{print f}' "$f")
  found=0
  for l in $(grep -oE "^[^:]*:[0-9]+:[0-9]+: optimized: loop vectorized" <<<"$report" | cut -d: -f2); do
    if grep -qx "$l" <<<"$lines"; then
      found=1
    fi
  done
  if [ "$found" = 1 ]; then
    echo "vectorized: $(basename "$f")"
  else
    echo "NOT vectorized: the interior loop of $(basename "$f")" >&2
    status=1
  fi
done
exit $status
