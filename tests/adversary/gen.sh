#!/usr/bin/env bash
# gen.sh <dpgen> kernel.cpp...: runs dpgen (with --tangent) on each kernel into /tmp/adv/<stem>, prints ACCEPTED or the first error.
d=$(readlink -f "$1"); shift
root=$(cd "$(dirname "$0")/../.." && pwd)
for k in "$@"; do s=$(basename "$k" .cpp); rm -rf /tmp/adv/$s; mkdir -p /tmp/adv/$s
  if "$d" "$k" --tangent --out-dir /tmp/adv/$s -- -std=c++17 -I"$root/runtime/include" > /tmp/adv/$s.log 2>&1; then
    printf '%-28s ACCEPTED\n' "$s"; else printf '%-28s REJECTED %s\n' "$s" "$(grep -m1 'error' /tmp/adv/$s.log | sed 's/.*error: //' | cut -c1-150)"; fi
done
