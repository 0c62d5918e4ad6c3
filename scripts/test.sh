#!/usr/bin/env bash
# The README's test command: installs what is missing, configures, builds with
# -j2 and runs every test (ctest: kernel adjoints, generator golden and
# diagnostic tests, runtime, examples).
#   scripts/test.sh            (build tree: build/)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${DPGEN_BUILD_DIR:-$root/build}
"$root/scripts/setup.sh"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" -j2
ctest --test-dir "$build" --output-on-failure -j2
