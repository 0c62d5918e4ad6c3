#!/usr/bin/env bash
# Weak- and strong-scaling tables of the distributed examples (advection_inverse_mpi,
# pressure_optimization_mpi) with 1, 2 and 4 ranks, written to bench/mpi_scaling.md and into
# README.md between '<!-- mpi-scaling:begin -->' and '<!-- mpi-scaling:end -->'.
# Time per gradient (forward + backward, slowest rank), best of DPGEN_SCALING_REPEATS runs
# (default 3), one OpenMP thread per rank. On a 2-core machine 4 ranks are oversubscribed.
#   scripts/mpi_scaling.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${DPGEN_BUILD_DIR:-$root/build}
repeats=${DPGEN_SCALING_REPEATS:-3}
"$root/scripts/setup.sh"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DDPGEN_WITH_MPI=ON -DDPGEN_WITH_PETSC=ON >/dev/null
cmake --build "$build" -j2 --target advection_inverse_mpi pressure_optimization_mpi
export OMP_NUM_THREADS=1
mpirun=(mpirun --allow-run-as-root --oversubscribe -np)
adv="$build/examples/mpi/advection_inverse_mpi"
prs="$build/examples/mpi/pressure_optimization_mpi"

# best_ms NP PROGRAM ARGS...: the smallest "X ms per gradient" of $repeats runs.
best_ms() {
  local np=$1 best=""
  shift
  for _ in $(seq "$repeats"); do
    local t
    t=$("${mpirun[@]}" "$np" "$@" --quiet 1 | sed -nE 's/.* ([0-9.]+) ms per gradient.*/\1/p')
    [ -n "$t" ] || { echo "mpi_scaling: no timing from $*" >&2; exit 1; }
    if [ -z "$best" ] || awk -v a="$t" -v b="$best" 'BEGIN { exit !(a < b) }'; then best=$t; fi
  done
  echo "$best"
}

tsv=$(mktemp)
trap 'rm -f "$tsv"' EXIT
# kind problem np grid ms
adv_cells=65536 # per rank (weak) and in all (strong)
prs_side=256    # 256x256 per rank (weak: 256x256, 512x256, 512x512) and in all (strong)
for np in 1 2 4; do
  echo "mpi_scaling: $np ranks" >&2
  cells=$((adv_cells * np))
  echo -e "weak\tadvection\t$np\t$cells cells\t$(best_ms "$np" "$adv" --cells $cells --iters 4)" >>"$tsv"
  nx=$prs_side ny=$prs_side
  [ "$np" -ge 2 ] && nx=$((2 * prs_side))
  [ "$np" -ge 4 ] && ny=$((2 * prs_side))
  echo -e "weak\tpressure\t$np\t${nx}x${ny}\t$(best_ms "$np" "$prs" --nx $nx --ny $ny --iters 4)" >>"$tsv"
  echo -e "strong\tadvection\t$np\t$adv_cells cells\t$(best_ms "$np" "$adv" --cells $adv_cells --iters 4)" >>"$tsv"
  echo -e "strong\tpressure\t$np\t${prs_side}x${prs_side}\t$(best_ms "$np" "$prs" --nx $prs_side --ny $prs_side --iters 4)" >>"$tsv"
done

python3 - "$tsv" "$root/bench/mpi_scaling.md" "$root/README.md" "$(nproc --all)" "$repeats" \
  "$(cut -d" " -f1-3 /proc/loadavg)" <<'PY'
import re, sys, datetime
tsv, out, readme, cores, repeats, load = sys.argv[1:7]
rows = [l.rstrip("\n").split("\t") for l in open(tsv) if l.strip()]
t = {(k, p, int(n)): (g, float(ms)) for k, p, n, g, ms in rows}
names = {"advection": "advection_inverse_mpi (100 upwind steps, full tape)",
         "pressure": "pressure_optimization_mpi (2 CG + BoomerAMG solves to 1e-10)"}
lines = [f"Measured with `scripts/mpi_scaling.sh` on {cores} cores shared with other work "
         f"({datetime.date.today()}, load average {load} at the end): milliseconds per gradient (forward and backward, the "
         f"slowest rank), best of {repeats} runs, 1 OpenMP thread per rank. **4 ranks on "
         f"{cores} cores are oversubscribed**: that row measures the decomposition's overhead, "
         f"not a speed-up.", ""]
for kind, title, note in (
        ("weak", "Weak scaling (grid per rank fixed)",
         "efficiency = t(1) / t(N); ideal 1"),
        ("strong", "Strong scaling (whole grid fixed)",
         "speed-up = t(1) / t(N); ideal N")):
    lines += [f"**{title}**, {note}:", "",
              "| problem | ranks | grid | ms per gradient | " +
              ("efficiency" if kind == "weak" else "speed-up") + " |",
              "|---|---|---|---|---|"]
    for p in ("advection", "pressure"):
        base = t[(kind, p, 1)][1]
        for n in (1, 2, 4):
            g, ms = t[(kind, p, n)]
            lines.append(f"| {names[p] if n == 1 else ''} | {n} | {g} | {ms:.1f} | "
                         f"{base / ms:.2f} |")
    lines.append("")
text = "\n".join(lines)
open(out, "w").write("# Distributed scaling\n\n" + text)
src = open(readme).read()
new = re.sub(r"(<!-- mpi-scaling:begin -->\n).*?(<!-- mpi-scaling:end -->)",
             lambda m: m.group(1) + text + m.group(2), src, flags=re.S)
if new == src and "<!-- mpi-scaling:begin -->" not in src:
    sys.exit("mpi_scaling: README.md has no mpi-scaling markers")
open(readme, "w").write(new)
print(text)
PY
