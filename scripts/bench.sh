#!/usr/bin/env bash
# Builds the benchmarks (-O3 -march=native, OpenMP, their own build tree) and
# runs them, then writes bench/results.md and the table in README.md.
# Run it on an otherwise idle machine: ratios are measured side by side.
#   scripts/bench.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${DPGEN_BENCH_DIR:-$root/build-bench}
"$root/scripts/setup.sh"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_FLAGS="-O3 -march=native" -DDPGEN_BUILD_BENCHMARKS=ON \
  -DDPGEN_BUILD_TESTS=OFF -DDPGEN_BUILD_EXAMPLES=OFF
cmake --build "$build" -j2 --target bench_adjoints bench_solvers dpgen
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$build/bench/bench_adjoints" --benchmark_repetitions=5 --benchmark_report_aggregates_only=false \
  --benchmark_min_time=0.2 --benchmark_out="$tmp/adjoints_all.json" --benchmark_out_format=json
"$build/bench/bench_solvers" --benchmark_repetitions=3 --benchmark_min_time=0.2 \
  --benchmark_out="$tmp/solvers_all.json" --benchmark_out_format=json
# Keep the median of the repetitions as the row for each benchmark.
python3 - "$tmp" <<'PY'
import json, sys
d = sys.argv[1]
for name in ("adjoints", "solvers"):
    data = json.load(open(f"{d}/{name}_all.json"))
    rows = [b for b in data["benchmarks"] if b.get("aggregate_name") == "median"]
    for b in rows:
        b["name"] = b["run_name"]
        b["run_type"] = "iteration"
    if not rows:  # single repetition
        rows = data["benchmarks"]
    data["benchmarks"] = rows
    json.dump(data, open(f"{d}/{name}.json", "w"))
PY
# The generator on each shipped and test kernel file.
for f in "$root"/kernels/*.cpp "$root"/tests/kernels/*.cpp; do
  case "$f" in *_test.cpp|*/main.cpp) continue ;; esac
  ts=()
  for _ in 1 2 3 4 5; do
    t0=$(date +%s%N)
    "$build/tool/dpgen" "$f" --out-dir "$tmp/gen" -- -I"$root/runtime/include" -I"$(dirname "$f")" 2>/dev/null
    ts+=($(( ($(date +%s%N) - t0) / 1000000 )))
  done
  median=$(printf '%s\n' "${ts[@]}" | sort -n | sed -n 3p)
  printf '%s\t%s\n' "$(basename "$f")" "$median" >> "$tmp/generator.tsv"
done
# Does the forward kernel as written vectorize? (GCC's own report.)
for pair in laplacian2d:kernels/laplacian2d.cpp divergence2d:kernels/divergence2d.cpp \
            upwind:kernels/upwind_step.cpp laplacian3d:tests/kernels/laplacian3d.cpp \
            burgers:tests/kernels/burgers_step.cpp; do
  src=$root/${pair#*:}
  n=$(g++ -std=c++17 -O3 -march=native -I"$root/runtime/include" -I"$(dirname "$src")" -c "$src" \
        -o /dev/null -fopt-info-vec-optimized 2>&1 | grep -c "loop vectorized" || true)
  printf '%s\t%s\n' "${pair%%:*}" "$([ "$n" -gt 0 ] && echo yes || echo no)" >> "$tmp/vectorizes.tsv"
done
python3 "$root/scripts/bench_table.py" "$tmp/adjoints.json" "$tmp/solvers.json" "$tmp/generator.tsv" \
  "$tmp/vectorizes.tsv" "$root/bench/results.md" "$root/README.md" "scripts/bench.sh"
echo "wrote $root/bench/results.md and the table in README.md"
