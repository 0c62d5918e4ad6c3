#!/usr/bin/env bash
# Regression guard for the gather form's main property: the branch-free
# interior loop of every generated adjoint given as an argument vectorizes
# (GCC -fopt-info-vec), each interior of each file, not just one per file; so
# does the interior of each <kernel>_parallel_forward split from its boundary
# conditions (an `interior` lambda capturing by reference).
# Timing is for bench/; this only asks the compiler.
#   vectorization_check.sh [--flags="<compiler flags>"] <c++ compiler> <generated_adjoint.cpp>...
# The flags default to -O3 -march=native; --flags=-O3 checks what a user's
# Release build (generic x86-64) gets.
set -euo pipefail
flags="-O3 -march=native"
case "${1:-}" in
--flags=*)
  flags=${1#--flags=}
  shift
  ;;
esac
cxx=$1
shift
status=0
for f in "$@"; do
  # shellcheck disable=SC2086
  report=$("$cxx" -std=c++17 $flags -fopenmp -I"$(dirname "$f")" \
             -c "$f" -o /dev/null -fopt-info-vec-optimized 2>&1 || true)
  vectorized=$(grep -oE "^[^:]*:[0-9]+:[0-9]+: optimized: loop vectorized" <<<"$report" |
                 cut -d: -f2 | sort -u)
  # Each interior lambda (the adjoint's [=], the forward's [&]): "<its line> <a
  # line of it>..." — its body, and the loops that call it (GCC reports an
  # inlined body at either place).
  interiors=$(awk '
    /auto interior_* = \[[=&]\]/ { if (start) print start, lines; start = NR; lines = ""; body = 1 }
    start && body { lines = lines " " NR }
    start && body && (/^ *};/ || (NR == start && /\};[[:space:]]*$/)) { body = 0 }
    /for \(/ { f = NR }
    start && !body && /[^_[:alnum:]]interior_*\(/ { lines = lines " " f }
    END { if (start) print start, lines }' "$f")
  total=0 bad=()
  while read -r start lines; do
    [ -n "$start" ] || continue
    total=$((total + 1))
    found=0
    for l in $lines; do
      if grep -qx "$l" <<<"$vectorized"; then
        found=1
        break
      fi
    done
    [ "$found" = 1 ] || bad+=("$start")
  done <<<"$interiors"
  if [ "$total" = 0 ]; then
    echo "NO interior loop in $(basename "$f")" >&2
    status=1
  elif [ "${#bad[@]}" = 0 ]; then
    echo "vectorized ($flags): all $total interior loops of $(basename "$f")"
  else
    echo "NOT vectorized ($flags): the interior loops at lines ${bad[*]} of $(basename "$f")" \
         "(of $total)" >&2
    status=1
  fi
done
exit $status
