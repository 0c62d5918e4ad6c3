#!/usr/bin/env bash
# Runs two builds of dpgen over every kernel file in the repository (every
# .cpp/.c that uses DPGEN_KERNEL, tests/diagnostics included) and reports any
# difference in what they write: the generated files (adjoint, tangent,
# checked entry points, torch ops, declarations) and the diagnostics. A
# refactoring of the generator that is meant to change nothing must print
# "0 differ". Usage:
#   scripts/compare_generated.sh OLD_DPGEN NEW_DPGEN [file...]
# With COMPARE_IGNORE_IDS=1 the diagnostics' ids (" [dpgen-...]") are removed
# from both sides first: for comparing with a dpgen from before they existed.
# COMPARE_STRIP=<perl regex> deletes what it matches (whole files, /s) from
# every generated file of both sides first: for a change meant to add one
# block everywhere and change nothing else, e.g.
#   COMPARE_STRIP='#if defined\(__GNUC__\)\n// Each generated.*?#endif\n\n'
# (the -Wunused pragmas of 2026-11-28).
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
old=$(realpath "$1") new=$(realpath "$2")
shift 2
resource=$(clang-19 -print-resource-dir)
if [ $# -gt 0 ]; then
  files=("$@")
else
  mapfile -t files < <(cd "$root" && grep -rlE 'DPGEN_KERNEL' --include='*.cpp' --include='*.c' \
    kernels examples tests | grep -v '_test\.cpp$' | sort)
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
differ=0 same=0
for f in "${files[@]}"; do
  src="$root/$f"
  [ -f "$f" ] && src=$(realpath "$f")
  args=(-I"$root/runtime/include" -I"$(dirname "$src")")
  case "$src" in */kernels20/*) args+=(-std=c++20) ;; esac
  for flag in "" --tangent --torch; do
    for side in old new; do
      exe=$old
      [ $side = new ] && exe=$new
      d="$work/$side"
      rm -rf "$d" && mkdir -p "$d"
      # shellcheck disable=SC2086
      (cd "$(dirname "$src")" && "$exe" $flag --resource-dir="$resource" "$src" --out-dir "$d" \
        -- "${args[@]}") >"$d.out" 2>&1
      echo "exit $?" >>"$d.out"
      # Paths of the temporary folders differ between the two runs.
      sed -i "s|$work/$side|OUT|g" "$d.out"
      if [ "${COMPARE_IGNORE_IDS:-0}" = 1 ]; then
        sed -i -E 's/ \[dpgen-[a-z-]+\]//' "$d.out"
      fi
      if [ -n "${COMPARE_STRIP:-}" ]; then
        find "$d" -type f -exec perl -0pi -e 's/$ENV{COMPARE_STRIP}//gs' {} +
      fi
    done
    if diff -r "$work/old" "$work/new" >"$work/diff" 2>&1 && diff "$work/old.out" "$work/new.out" >>"$work/diff" 2>&1; then
      same=$((same + 1))
    else
      differ=$((differ + 1))
      echo "== $f ${flag:-(adjoint)}"
      head -40 "$work/diff"
    fi
  done
done
echo "compare_generated: $same same, $differ differ"
[ "$differ" -eq 0 ]
