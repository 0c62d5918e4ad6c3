#!/usr/bin/env bash
# Checks the adversary tests themselves, without dpgen: tests/styles/selfcheck.sh
# (the adjoint replaced by a finite-difference J^T w of the forward kernel)
# over tests/adversary/*.cpp. A FAIL is a bug in the test, not dpgen.
here=$(cd "$(dirname "$0")" && pwd)
if [ $# -eq 0 ]; then
  set -- $(ls "$here"/*.cpp | grep -v '_test\.cpp$')
fi
exec "$here/../styles/selfcheck.sh" "$@"
