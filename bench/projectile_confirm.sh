#!/usr/bin/env bash
# The projectile with a liquid payload (data/scenes/projectile_liquid.toml) at real Ekman numbers: its response-fit
# table by the scene's recipe (timed), spectrum with the fit, chain-rom confirm (the roots with the liquid's own
# response, timed), the sweep over spin 3000 -> 800 rad/s by forced solves (timed, with its PNG), and the test's
# checks with Krylov tables at four spins (tests/scenes/confirm_scene_check.py; 577 s idle when the suite ran them,
# 2026-11-26). Writes
# OUT/projectile_* and prints the times; docs/benchmarks.md, "Viscous chain at real Ekman numbers", records a run.
#   bash bench/projectile_confirm.sh [BUILD_DIR] [OUT]        (about 20 minutes idle on 2 cores)
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
source "$ROOT/scripts/blas-core.sh"
BUILD=${1:-$ROOT/build}
OUT=${2:-$ROOT/bench/results}
MODES=$BUILD/modes/cavity-modes
ROM=$BUILD/rom/chain-rom
SCENE=$ROOT/data/scenes/projectile_liquid.toml
day=$(date +%F)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$OUT"
recipe=$(sed -n 's/^# recipe: \([^:]*\): \(.*\)$/\1|\2/p' "$SCENE")
name=${recipe%%|*}
read -r -a args <<< "${recipe#*|}"
seconds() { python3 -c "import time; print(round(time.time() - $1, 2))"; }
start=$(python3 -c 'import time; print(time.time())')
"$MODES" "${args[@]}" -o "$work/$name" > "$work/table.txt" 2> "$work/table.err"
echo "table ($name, recipe): $(seconds "$start") s"
sed "s#\"../../out/tables/$name\"#\"$work/$name\"#" "$SCENE" > "$work/scene.toml"
"$ROM" spectrum "$work/scene.toml" > "$OUT/projectile_spectrum_fit_$day.txt"
start=$(python3 -c 'import time; print(time.time())')
"$ROM" confirm "$work/scene.toml" --cavity-modes "$MODES" > "$OUT/projectile_confirm_$day.txt"
echo "confirm: $(seconds "$start") s"
grep -E '^  |with the confirmed' "$OUT/projectile_confirm_$day.txt"
start=$(python3 -c 'import time; print(time.time())')
"$ROM" sweep "$work/scene.toml" --param 'body[1].spin' --from 3000 --to 800 --steps 12 --cavity-modes "$MODES" \
  -o "$OUT/projectile_spin_sweep_$day.csv" --png "$OUT/projectile_spin_sweep_$day.png" 2> "$OUT/projectile_spin_sweep_$day.log"
echo "spin sweep, 12 points: $(seconds "$start") s"
cat "$OUT/projectile_spin_sweep_$day.csv"
# The test's checks (tests/scenes/confirm_scene_check.py) with the recipe's Krylov tables at four spins, where the
# suite takes one (3000 rad/s) to keep its test short.
start=$(python3 -c 'import time; print(time.time())')
python3 "$ROOT/tests/scenes/confirm_scene_check.py" "$MODES" "$ROM" "$SCENE" "$work/check" 800,1500,2000,3000 |
  grep -E "rad/s|Krylov tables"
echo "Krylov tables at four spins against confirm: $(seconds "$start") s"
