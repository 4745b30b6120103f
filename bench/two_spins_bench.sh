#!/usr/bin/env bash
# Chains at two spins (docs/rom.md, "Bodies at different spins"): what Floquet's roots cost. Benchmarks, not tests;
# figures go into docs/rom.md ("Bodies at different spins", "Cost").
#
#   bash bench/two_spins_bench.sh
#
# On data/scenes/spacecraft_wheel.toml (its table from the recipe, made if missing) and on the baffled-tank craft with
# the same wheel (data/scenes/spacecraft_baffled_tank.toml's table; 13 band modes): the wall time of `chain-rom
# spectrum` with the Magnus steps it settled with, as the wheel's spin comes close to the craft's (the period grows:
# 60, 10, 5.5, 5.1 rad/s against 5), a 391-point sweep of the wheel's spin, and a 150 s `run` by Magnus steps
# against the nonlinear chain's. Writes bench/results/two_spins_<date>.md.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
ROM="$ROOT/build/rom/chain-rom"
MODES="$ROOT/build/modes/cavity-modes"
[ -x "$ROM" ] || { echo "two_spins_bench: $ROM not built (bash scripts/build.sh)" >&2; exit 1; }
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
mkdir -p "$ROOT/out/tables" "$ROOT/bench/results"
OUT="$ROOT/bench/results/two_spins_$(date +%F).md"
[ -f "$ROOT/out/tables/spacecraft_side_tank.h5" ] ||
  "$MODES" ellipsoid --a 1 --b 0.8 --c 1.6 -o "$ROOT/out/tables/spacecraft_side_tank.h5" > /dev/null
[ -f "$ROOT/out/tables/baffled_tank.h5" ] ||
  "$MODES" volume "$ROOT/data/volumes/sphere_four_baffles_graded.geo" --order 2 --mesh-size 0.3 --floor 1e-2 \
    -o "$ROOT/out/tables/baffled_tank.h5" > /dev/null
sed "s#\.\./\.\./out#$ROOT/out#" "$ROOT/data/scenes/spacecraft_wheel.toml" > "$TMP/wheel.toml"
# The baffled craft with the wheel on a bearing 0.5 m above it.
sed "s#\.\./\.\./out#$ROOT/out#; s/^spin = 6.0$/next_joint = 0.5\nspin = 6.0/" "$ROOT/data/scenes/spacecraft_baffled_tank.toml" > "$TMP/baffled.toml"
printf '\n[[body]]\nmass = 20.0\nA = 0.40\nB = 0.44\nC = 0.6\ncom = 0.0\nspin = 60.0\n[[joint]]\nstiffness = 2.0e4\nfriction = 0.0\n' >> "$TMP/baffled.toml"

seconds() { local t0 t1; t0=$(date +%s.%N); "$@" > "$TMP/last.txt"; t1=$(date +%s.%N); printf '%.3f' "$(echo "$t1 - $t0" | bc)"; }
{
  echo "# Chains at two spins: cost ($(date +%F), $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), commit $(git -C "$ROOT" rev-parse --short HEAD), load $(cut -d' ' -f1 /proc/loadavg))"
  echo
  echo "| scene | wheel spin (rad/s) | roots | Magnus steps a period | settled (rad/s) | spectrum wall time (s) |"
  echo "|---|---|---|---|---|---|"
  for scene in wheel baffled; do
    for w in 60.0 10.0 5.5 5.1; do
      sed "s/^spin = 60.0$/spin = $w/" "$TMP/$scene.toml" > "$TMP/s.toml"
      t=$(seconds "$ROM" spectrum "$TMP/s.toml" --json)
      /usr/bin/python3 -c "import json,sys; d=json.load(open('$TMP/last.txt')); f=d['floquet']; print('| %s | %s | %d | %d | %.1e | %s |' % ('$scene', '$w', len(d['roots']), f['steps_per_period'], f['settled'], '$t'))"
    done
  done
  echo
  t=$(seconds "$ROM" sweep "$TMP/wheel.toml" --param body[2].spin --from 10 --to 400 --steps 391 -o "$TMP/sweep.csv")
  echo "sweep of the wheel's spin, 10 to 400 rad/s, 391 points (2 threads): $t s"
  for model in linear nonlinear; do
    cp "$TMP/wheel.toml" "$TMP/run.toml"
    printf '[initial]\ntilt = [[0.0, 0.0], [1e-6, 0.0]]\nrate = [[0.0, 0.0], [0.0, 0.0]]\n[run]\nt_end = 150.0\noutput_step = 0.002\nmodel = "%s"\n' "$model" >> "$TMP/run.toml"
    t=$(seconds "$ROM" run "$TMP/run.toml" -o "$TMP/run.h5")
    echo "run, 150 s at output steps of 2 ms, model $model: $t s ($(head -1 "$TMP/last.txt" | sed 's/.*samples, //'))"
  done
} | tee "$OUT"
