#!/usr/bin/env bash
# Triage of the adversarial kernels: the style corpus's script (which passes
# --tangent and links the tangent too) over tests/adversary/*.cpp.
here=$(cd "$(dirname "$0")" && pwd)
dpgen=${1:?usage: triage.sh <dpgen-binary> [kernel.cpp ...]}
shift
if [ $# -eq 0 ]; then
  set -- $(ls "$here"/*.cpp | grep -v '_test\.cpp$')
fi
exec "$here/../styles/triage.sh" "$dpgen" "$@"
