#!/usr/bin/env bash
# Runs what two builds of dpgen write, not just reads it: for each kernel file,
# the adjoints and tangents each dpgen generates are compiled (with plain -O3
# and with -O3 -march=native, OpenMP), called on the same seeded random inputs
# (every flat entry point with pointer and scalar parameters; integer
# parameters = $DPGEN_COMPARE_N, default 101, so 2D loops run in parallel)
# and a hash of every array they write is compared. A change meant to keep
# results bit-identical (hoisting, reordering independent statements) must
# print only "same" lines. Usage:
#   scripts/compare_results.sh OLD_DPGEN NEW_DPGEN kernel.cpp...
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
old=$(realpath "$1") new=$(realpath "$2")
shift 2
resource=$(clang-19 -print-resource-dir)
cxx=${CXX:-g++}
w=$(mktemp -d)
trap 'rm -rf "$w"' EXIT
status=0
for k in "$@"; do
  src=$(realpath "$k")
  stem=$(basename "$src" .cpp)
  for mode in adjoint tangent; do
    flag=""
    [ $mode = tangent ] && flag=--tangent
    for side in old new; do
      exe=$old
      [ $side = new ] && exe=$new
      rm -rf "${w:?}/$side" && mkdir -p "$w/$side"
      "$exe" $flag --resource-dir="$resource" "$src" --out-dir "$w/$side" \
        -- -I"$root/runtime/include" -I"$(dirname "$src")" 2>/dev/null
    done
    python3 "$root/scripts/compare_results_driver.py" "$w/old/${stem}_$mode.hpp" "_$mode" \
      "${DPGEN_COMPARE_N:-101}" >"$w/driver.cpp"
    for flags in "-O3" "-O3 -march=native"; do
      for side in old new; do
        # shellcheck disable=SC2086
        if ! "$cxx" -std=c++17 $flags -fopenmp -I"$w/$side" -I"$root/runtime/include" \
          "$w/driver.cpp" "$w/$side/${stem}_$mode.cpp" -o "$w/$side.exe" 2>"$w/err"; then
          echo "compile failed: $k $mode ($side)"
          head -5 "$w/err"
          status=1
          continue 2
        fi
        OMP_NUM_THREADS=2 "$w/$side.exe" >"$w/$side.out"
      done
      n=$(grep -c . "$w/old.out")
      if [ "$n" -gt 0 ] && cmp -s "$w/old.out" "$w/new.out"; then
        echo "same   $k $mode [$flags] ($n arrays)"
      else
        echo "DIFFER $k $mode [$flags]"
        diff "$w/old.out" "$w/new.out" | head -5
        status=1
      fi
    done
  done
done
exit $status
