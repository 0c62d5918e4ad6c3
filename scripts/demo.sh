#!/usr/bin/env bash
# The README's main command: installs what is missing, configures, builds
# with -j2 and runs the main example (the seed's advection inverse problem),
# then says where its pictures are.
#   scripts/demo.sh [example options, e.g. --checkpoints 16]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${DPGEN_BUILD_DIR:-$root/build}
"$root/scripts/setup.sh"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" -j2 --target advection_inverse
out=$root/out/advection_inverse
"$build/examples/advection_inverse" --out "$out" --csv "$out/loss.csv" "$@"
echo
echo "Pictures and log of this run are in $out:"
echo "  loss.svg (loss per iteration), density.svg (d(T) against its target),"
echo "  velocity.svg (the recovered velocity), loss.csv (iter,loss,grad_norm,seconds)"
