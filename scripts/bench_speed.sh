#!/usr/bin/env bash
# Issue 23's benchmarks (bench/bench_speed.cpp): the unrolled upwind loop with and without a
# reused CheckpointWorkspace, MG-PCG and the flow solver, each at 1 and 2 threads. Builds
# bench_speed, and bench_speed_baseline against the runtime headers of a baseline commit
# (default: 321dd86, the runtime before this work), twice: with plain -O3 (what a CMake Release
# build gives) and with -O3 -march=native; runs new and baseline alternately and prints the
# tables (markdown) on stdout. Run it on a quiet machine; it prints the load average.
#   scripts/bench_speed.sh [baseline-commit]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
base=${1:-321dd86}
reps=${DPGEN_BENCH_REPETITIONS:-3}
out=${DPGEN_BENCH_OUT:-$root/build-speed-results}
mkdir -p "$out"
for flavour in o3 native; do
  build=$root/build-speed-$flavour
  flags=""
  [ "$flavour" = native ] && flags="-march=native"
  mkdir -p "$build/baseline-headers"
  git -C "$root" archive "$base" runtime | tar -x -C "$build/baseline-headers"
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS="$flags" \
    -DDPGEN_BUILD_BENCHMARKS=ON -DDPGEN_BUILD_TESTS=OFF -DDPGEN_BUILD_EXAMPLES=OFF \
    -DDPGEN_INSTALL=OFF \
    "-DDPGEN_BENCH_BASELINE_INCLUDE=$build/baseline-headers/runtime/include;$build/baseline-headers/runtime/solvers/include" \
    > "$out/cmake-$flavour.log"
  cmake --build "$build" -j2 --target bench_speed bench_speed_baseline > "$out/build-$flavour.log"
done
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)" | tee "$out/load.txt"
for flavour in o3 native; do
  for bin in bench_speed_baseline bench_speed; do
    "$root/build-speed-$flavour/bench/$bin" --benchmark_repetitions="$reps" \
      --benchmark_min_time=0.1 --benchmark_out="$out/$flavour-$bin.json" \
      --benchmark_out_format=json > /dev/null
    echo "load average after $flavour $bin: $(cut -d' ' -f1-3 /proc/loadavg)" | tee -a "$out/load.txt"
  done
done
python3 "$root/scripts/bench_speed_table.py" "$out" "$base"        # wall time, 1 and 2 threads
python3 "$root/scripts/bench_speed_table.py" "$out" "$base" cpu    # CPU time, 1 thread (a busy machine)
