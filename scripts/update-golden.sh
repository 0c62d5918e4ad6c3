#!/usr/bin/env bash
# Regenerates the golden tests in tests/golden/ from the tool's current output,
# for the seed kernels. Run after an intended change to the generated code and
# review the diff: it is exactly what changed in what dpgen writes.
#   scripts/update-golden.sh [build-dir]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
dpgen=$build/tool/dpgen
[ -x "$dpgen" ] || { echo "error: $dpgen not built (cmake --build $build --target dpgen)" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# FileCheck reads {{ and [[ as regex/variable syntax: escape them.
checks() { # prefix file
  local prefix=$1 file=$2 first=1
  while IFS= read -r line || [ -n "$line" ]; do
    line=${line//\{\{/\{\{\[\{\]\[\{\]\}\}}
    line=${line//\[\[/\{\{\\\[\\\[\}\}}
    if [ $first = 1 ]; then
      printf '// %s: %s\n' "$prefix" "$line"; first=0
    elif [ -z "$line" ]; then
      printf '// %s-EMPTY:\n' "$prefix"
    else
      printf '// %s-NEXT: %s\n' "$prefix" "$line"
    fi
  done < "$file"
}

for kernel in upwind_step divergence2d laplacian2d; do
  "$dpgen" "$root/kernels/$kernel.cpp" --out-dir "$tmp" -- -I"$root/runtime/include" -I"$root/kernels"
  out=$root/tests/golden/$kernel.test
  {
    echo "// Golden test: what dpgen writes for kernels/$kernel.cpp (the gather form a"
    echo "// reviewer should see). Regenerate with scripts/update-golden.sh after an"
    echo "// intended change to the emitter, and review the diff."
    echo "// RUN: rm -rf %t && mkdir -p %t"
    echo "// RUN: %dpgen %kernels/$kernel.cpp --out-dir %t -- -I%runtime_inc -I%kernels"
    echo "// RUN: FileCheck %s --check-prefix=HPP --match-full-lines --input-file %t/${kernel}_adjoint.hpp"
    echo "// RUN: FileCheck %s --check-prefix=CPP --match-full-lines --input-file %t/${kernel}_adjoint.cpp"
    echo
    checks HPP "$tmp/${kernel}_adjoint.hpp"
    echo
    checks CPP "$tmp/${kernel}_adjoint.cpp"
  } > "$out"
  echo "wrote $out"
done

# Per-rule golden files: tests/golden/rules/<rule>.cpp holds a small kernel
# that shows one rule, its RUN lines, and (after the marker) the CHECK lines of
# the generated source, side by side.
marker="// ---- generated code (scripts/update-golden.sh writes what follows) ----"
for input in "$root"/tests/golden/rules/*.cpp; do
  [ -e "$input" ] || continue
  stem=$(basename "$input" .cpp)
  # A rule file whose RUN line asks for --tangent shows the tangent kernel.
  kind=adjoint flag=
  if grep -q -- "--tangent" "$input"; then kind=tangent flag=--tangent; fi
  "$dpgen" "$input" $flag --out-dir "$tmp" -- -I"$root/runtime/include" -I"$root/tests/styles" \
    2>/dev/null
  head=$(sed "/^\/\/ ---- generated code/,\$d" "$input")
  {
    printf '%s\n' "$head"
    echo "$marker"
    checks CPP "$tmp/${stem}_${kind}.cpp"
  } > "$input.new"
  mv "$input.new" "$input"
  echo "wrote $input"
done
