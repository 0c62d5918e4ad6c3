#!/usr/bin/env bash
# The pass `share` against `dpgen --no-share` (bench/bench_share.cpp): generates the adjoints of
# kernels/upwind_step.cpp, tests/styles/twin_limiter_kernels.cpp and
# tests/styles/shifted_quotients.cpp both ways, links both into one program (each variant's
# functions renamed), and times them alternately, with the flags of a CMake Release build (-O3)
# and with -O3 -march=native, on 1 and 2 threads. Prints markdown.
#   scripts/bench_share.sh [dpgen]        (default: build/tool/dpgen)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
dpgen=${1:-$root/build/tool/dpgen}
[ -x "$dpgen" ] ||
  { echo "error: $dpgen not built (cmake --build build --target dpgen)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
inc=$root/runtime/include
for v in share noshare; do
  flag=()
  [ $v = noshare ] && flag=(--no-share)
  mkdir -p "$work/$v"
  for k in kernels/upwind_step.cpp tests/styles/twin_limiter_kernels.cpp \
           tests/styles/shifted_quotients.cpp; do
    "$dpgen" "${flag[@]}" "$root/$k" --out-dir "$work/$v" -- -I"$inc" >/dev/null
  done
done
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg); $(nproc) CPUs; $(date -u +%FT%TZ)"
for opt in "-O3" "-O3 -march=native"; do
  objs=()
  for v in share noshare; do
    # Every function of the generated files gets the variant's suffix (one program holds both).
    renames=()
    for f in $(grep -ohE '^void [A-Za-z0-9_]+\(' "$work/$v"/*_adjoint.hpp | sed 's/^void //; s/($//' |
               sort -u); do
      renames+=("-D$f=${f}_$v")
    done
    for src in "$work/$v"/*_adjoint.cpp; do
      # shellcheck disable=SC2086
      g++ -std=c++17 $opt -fopenmp -c -I"$work/$v" -I"$inc" "${renames[@]}" "$src" \
        -o "$src.$v.o"
      objs+=("$src.$v.o")
    done
  done
  # shellcheck disable=SC2086
  g++ -std=c++17 $opt -fopenmp "$root/bench/bench_share.cpp" "${objs[@]}" -o "$work/bench_share"
  for threads in 1 2; do
    echo
    echo "#### $opt, $threads thread(s)"
    OMP_NUM_THREADS=$threads "$work/bench_share" | tail -n +3
  done
done
echo
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
