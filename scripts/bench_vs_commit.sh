#!/usr/bin/env bash
# Did the generator's output get slower? Builds bench_adjoints twice in one
# tree, with today's generated adjoints of the seed kernels and with the ones
# a past commit's golden files hold (tests/golden/<kernel>.test: the whole
# generated .cpp), and runs the two side by side, alternating, 3 rounds.
#   scripts/bench_vs_commit.sh <commit> [build-dir]
# Needs a build dir configured with -DDPGEN_BUILD_BENCHMARKS=ON (default:
# build). Compiles with -O3 -march=native like scripts/bench.sh, or with the
# flags in DPGEN_BENCH_FLAGS (DPGEN_BENCH_FLAGS=-O3: a CMake Release build's).
# Runs each kernel's generated and hand-written adjoints far beyond the caches
# and in them (_cache), on 1 and 2 threads.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
commit=${1:?usage: bench_vs_commit.sh <commit> [build-dir]}
build=$(cd "${2:-$root/build}" && pwd)
cmake --build "$build" -j2 --target bench_adjoints >/dev/null
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
kernels="upwind_step divergence2d laplacian2d"
mkdir -p "$work/old"
for k in $kernels; do
  git -C "$root" show "$commit:tests/golden/$k.test" | grep -E '^// CPP(-NEXT|-EMPTY)?:' |
    sed -E 's#^// CPP-EMPTY:##; s#^// CPP(-NEXT)?: ?##' >"$work/old/${k}_adjoint.cpp"
done
gk=$build/kernels/dpgen_kernels_generated
gb=$build/bench/dpgen_bench_kernels_generated
common=("$root/bench/bench_adjoints.cpp" "$root"/kernels/*.cpp "$root/tests/kernels/burgers_step.cpp"
        "$root/tests/kernels/laplacian3d.cpp" "$gb"/*.cpp)
for f in "$gk"/*.cpp; do
  case " $kernels " in *" $(basename "$f" _adjoint.cpp) "*) continue ;; esac
  common+=("$f")
done
read -r -a opt <<<"${DPGEN_BENCH_FLAGS:--O3 -march=native}"
flags=(-std=c++17 "${opt[@]}" -DNDEBUG -fopenmp -I"$gk" -I"$root/kernels" -I"$root/runtime/include"
       -I"$gb" -I"$root/tests/kernels" -I"$root/bench")
for v in new old; do
  own=()
  for k in $kernels; do
    if [ $v = new ]; then own+=("$gk/${k}_adjoint.cpp"); else own+=("$work/old/${k}_adjoint.cpp"); fi
  done
  objs=()
  for s in "${common[@]}" "${own[@]}"; do
    o=$work/$v.$(echo "$s" | tr / _).o
    objs+=("$o")
    g++ "${flags[@]}" -c "$s" -o "$o"
  done
  g++ -fopenmp -o "$work/bench_$v" "${objs[@]}" -lbenchmark -lpthread
done
filter='(laplacian2d|divergence2d|upwind)_(generated|hand)(_cache)?/[12]/'
for r in 1 2 3; do
  for v in new old; do
    "$work/bench_$v" --benchmark_filter="$filter" --benchmark_min_time=0.2 --benchmark_repetitions=3 \
      --benchmark_report_aggregates_only=true 2>/dev/null | grep median | sed "s/^/$v (round $r) /"
  done
done
