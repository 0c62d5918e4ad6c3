#!/usr/bin/env bash
# Checks the corpus tests themselves, without dpgen: each <stem>_test.cpp is
# built against tests/styles/selfcheck/support/adjoint_check.hpp, which swaps
# the generated adjoint for a finite-difference J^T w of the forward kernel
# (tangent and checked entry points are dropped), and stub generated headers
# (a no-op template per generated name). A FAIL here is a bug in the test or
# forward kernel, not in dpgen. Test cases named *throws* (exceptions from
# run-time checks) are skipped. Tests that call the adjoint directly
# (hand-computed values: two_loops_minimal) or through a ternary of two
# adjoints (twin_*) are expected to fail here.
# Usage: selfcheck.sh [kernel.cpp ...]  (default: every kernel in tests/styles)
# SELFCHECK_SKIP: more test-case patterns to skip (doctest -tce), e.g. '*ties*'.
set -u
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
CXX=${CXX:-g++}
work=$(mktemp -d /tmp/dpgen-selfcheck.XXXXXX)
trap 'rm -rf "$work"' EXIT
$CXX -std=c++17 -O1 -c "$root/tests/kernels/main.cpp" -o "$work/main.o" || exit 2
one() {
  local src=$1 stem out srcdir
  stem=$(basename "$src" .cpp); out=$work/$stem; mkdir -p "$out"
  srcdir=$(cd "$(dirname "$src")" && pwd)
  { echo '#pragma once'
    grep -oE '\b[A-Za-z0-9_]+_(adjoint|tangent|adjoint_checked)\b *\(' "$srcdir/${stem}_test.cpp" |
      sed 's/ *($//' | sort -u |
      while read -r f; do echo "template <typename... A> void $f(A&&...) {}"; done
  } > "$out/${stem}_adjoint.hpp"
  echo '#pragma once' > "$out/${stem}_tangent.hpp"
  if ! $CXX -std=c++17 -O1 -fopenmp -I"$root/runtime/include" -I"$here/selfcheck" -I"$srcdir" \
      -I"$root/tests" -I"$out" "$src" "$srcdir/${stem}_test.cpp" "$work/main.o" -o "$out/t" \
      > "$out/cxx.log" 2>&1; then
    printf '%-30s COMPILE-ERROR %s\n' "$stem" "$(grep -m1 error "$out/cxx.log")"; return; fi
  if timeout 300 "$out/t" -tce="*throws*${SELFCHECK_SKIP:+,$SELFCHECK_SKIP}" > "$out/run.log" 2>&1; then printf '%-30s PASS\n' "$stem"
  else printf '%-30s FAIL %s\n' "$stem" "$(grep -m1 -E 'ERROR|disagree|overwrote' "$out/run.log")"; fi
}
export -f one; export here root CXX work
if [ $# -gt 0 ]; then printf '%s\n' "$@"; else ls "$here"/*.cpp | grep -v '_test\.cpp$'; fi |
  xargs -P "${JOBS:-2}" -I{} bash -c 'one {}' | sort
