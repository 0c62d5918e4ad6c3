#!/usr/bin/env bash
# Triage of the style corpus against a dpgen binary:
#   tests/styles/triage.sh <dpgen-binary> [kernel.cpp ...]
# For each kernel file (default: every tests/styles/*.cpp that is not a test)
# runs dpgen on that file alone and prints one line:
#   <name>  ACCEPTED|REJECTED|CRASH  [PASS|FAIL|COMPILE-ERROR]  <first relevant line>
# Accepted kernels are compiled with their generated adjoint and their
# doctest (g++ -O1, no CMake) and run. Env: JOBS (default 2), CXX (g++),
# KEEP=1 keeps the work directory.
set -u
dpgen=${1:?usage: triage.sh <dpgen-binary> [kernel.cpp ...]}
shift
dpgen=$(readlink -f "$dpgen")
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
CXX=${CXX:-g++}
JOBS=${JOBS:-2}
work=$(mktemp -d /tmp/dpgen-triage.XXXXXX)
[ "${KEEP:-0}" = 1 ] && echo "work dir: $work" >&2 || trap 'rm -rf "$work"' EXIT

if [ $# -gt 0 ]; then kernels=("$@"); else
  kernels=()
  for f in "$here"/*.cpp; do
    case "$f" in *_test.cpp) continue ;; esac
    kernels+=("$f")
  done
fi

# The doctest main, once.
$CXX -std=c++17 -O1 -c "$root/tests/kernels/main.cpp" -o "$work/main.o" || exit 2

triage_one() {
  local src=$1 stem out line rc
  src=$(readlink -f "$src")
  stem=$(basename "$src" .cpp)
  out=$work/$stem
  mkdir -p "$out/gen"
  timeout 120 "$dpgen" "$src" --tangent --out-dir "$out/gen" -- -std=c++17 -I"$root/runtime/include" \
    -I"$(dirname "$src")" >"$out/dpgen.log" 2>&1
  rc=$?
  if [ $rc -ge 124 ] || grep -qiE 'Stack dump|Assertion|Segmentation|terminate called|PLEASE submit' "$out/dpgen.log"; then
    line=$(grep -m1 -iE 'Assertion|error|Segmentation|terminate|Stack dump' "$out/dpgen.log")
    printf '%-30s %-9s %-14s rc=%d %s\n' "$stem" CRASH "" "$rc" "${line:0:200}"
    return
  fi
  if [ $rc -ne 0 ]; then
    line=$(grep -m1 'error:' "$out/dpgen.log" || head -1 "$out/dpgen.log")
    line=${line#"$src":}
    printf '%-30s %-9s %-14s %s\n' "$stem" REJECTED "" "${line:0:200}"
    return
  fi
  if [ ! -f "$out/gen/${stem}_adjoint.cpp" ]; then
    printf '%-30s %-9s %-14s %s\n' "$stem" CRASH "" "exit 0 but no ${stem}_adjoint.cpp"
    return
  fi
  local srcdir; srcdir=$(cd "$(dirname "$src")" && pwd)
  local test=$srcdir/${stem}_test.cpp
  if ! $CXX -std=c++17 -O1 -fopenmp -I"$root/runtime/include" -I"$root/tests" -I"$srcdir" \
      -I"$out/gen" "$src" "$out/gen/${stem}_adjoint.cpp" $(ls "$out/gen/${stem}_tangent.cpp" 2>/dev/null) "$test" "$work/main.o" \
      -o "$out/t" >"$out/cxx.log" 2>&1; then
    line=$(grep -m1 'error' "$out/cxx.log")
    line=${line#"$work"/}
    printf '%-30s %-9s %-14s %s\n' "$stem" ACCEPTED COMPILE-ERROR "${line:0:200}"
    return
  fi
  # Files with identical kernels (twin_*): the adjoint bodies must be the same
  # text up to the kernel name (issue 9, defect 3: names from a static counter).
  local note=""
  case "$stem" in twin_*)
    local fns f0 b0 fb
    fns=$(grep -oE '^void [A-Za-z0-9_]+_adjoint\(' "$out/gen/${stem}_adjoint.cpp" | sed 's/^void //; s/_adjoint($//')
    f0=$(echo "$fns" | head -1)
    b0=$(awk "/^void ${f0}_adjoint\\(/,/^}/" "$out/gen/${stem}_adjoint.cpp" | sed "s/${f0}/KERNEL/g")
    for f in $fns; do
      fb=$(awk "/^void ${f}_adjoint\\(/,/^}/" "$out/gen/${stem}_adjoint.cpp" | sed "s/${f}/KERNEL/g")
      [ "$fb" = "$b0" ] || note="NOT-PURE: adjoints of identical kernels ${f0}/${f} differ beyond the name"
    done ;;
  esac
  if OMP_NUM_THREADS=2 timeout 120 "$out/t" >"$out/run.log" 2>&1; then
    printf '%-30s %-9s %-14s %s\n' "$stem" ACCEPTED PASS "$note"
  else
    line=$(grep -m1 -E 'ERROR|FATAL|finite difference|overwrote|disagree|Jv,w' "$out/run.log" || tail -1 "$out/run.log")
    local capt
    capt=$(grep -m3 -E '^  [A-Za-z_0-9]+ := ' "$out/run.log" | tr -s ' \n' ' ')
    printf '%-30s %-9s %-14s %s\n' "$stem" ACCEPTED FAIL "${capt}${line:0:160}"
  fi
}
export -f triage_one
export dpgen here root CXX work

printf '%s\0' "${kernels[@]}" | xargs -0 -P "$JOBS" -I{} bash -c 'triage_one "$1" > "$work/$(basename "$1" .cpp).line"' _ {}
cat "$work"/*.line | sort
echo "---"
for s in ACCEPTED REJECTED CRASH PASS FAIL COMPILE-ERROR; do
  printf '%s=%d ' "$s" "$(cat "$work"/*.line | awk '{print $2, $3}' | grep -cw -- "$s")"
done
echo "total=${#kernels[@]}"
