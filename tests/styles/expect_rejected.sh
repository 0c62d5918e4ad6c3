#!/usr/bin/env bash
# expect_rejected.sh <dpgen> <runtime-include> <kernel.cpp>...
# Each kernel must be rejected cleanly: exit status 1, a "file:line:col:
# error:" diagnostic naming the kernel file, and no file written.
set -u
dpgen=$1 inc=$2
shift 2
bad=0
for k in "$@"; do
  out=$(mktemp -d)
  msg=$("$dpgen" "$k" --out-dir "$out" -- -std=c++17 -I"$inc" 2>&1)
  rc=$?
  name=$(basename "$k")
  if [ "$rc" -ne 1 ] || ! grep -qE "^[^ ]*${name}:[0-9]+:[0-9]+: error: " <<<"$msg" ||
     [ -n "$(ls -A "$out")" ]; then
    echo "NOT CLEANLY REJECTED: $name (exit $rc)"; echo "$msg" | head -5; bad=1
  else
    echo "rejected: $name: $(grep -m1 -E 'error: ' <<<"$msg" | sed 's/.*error: //' | cut -c1-120)"
  fi
  rm -rf "$out"
done
exit $bad
