#!/usr/bin/env bash
# The default response table of one tank of the spacecraft of data/scenes/spacecraft_nutation.toml (800 kg, A = 400,
# C = 520 kg m^2, 60 rpm; the tank's scale 0.4 m) made with each interior size given, and the body's nutation decay
# `chain-rom spectrum` reads from it: what the interior size costs and what it moves (docs/viscous.md, "Interior size
# of a partially filled cylinder"). Appends one CSV row per size to OUT/interior_size_study.csv and prints it; compare
# the decays with docs/trust.md's mesh-converged references (bench/viscous_fill_study.sh).
#   bash bench/interior_size_study.sh "cylinder --radius 1 --height 2" 0.5 1e-6 "0.0366 0.0732" [BUILD_DIR] [OUT]
#   (a size "default" takes the command's own; about a minute a size on 2 cores)
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
SHAPE=${1:?usage: interior_size_study.sh SHAPE_ARGS FILL EKMAN "SIZES" [BUILD_DIR] [OUT]}
FILL=${2:?fill}
EK=${3:?Ekman number}
SIZES=${4:?sizes}
BUILD=${5:-$ROOT/build}
OUT=${6:-$ROOT/bench/results}
# shellcheck source=spacecraft_tank.sh
source "$ROOT/bench/spacecraft_tank.sh"
spacecraft_tank_workdir "$EK"
csv=$OUT/interior_size_study.csv
[ -f "$csv" ] || echo "date,shape,fill,ekman,interior_h,unknowns,table_s,nutation_decay" > "$csv"
for size in $SIZES; do
  size_args=()
  [ "$size" = default ] || size_args=(--mesh-size "$size")
  start=$(date +%s.%N)
  spacecraft_tank_table "$BUILD/modes/cavity-modes" "$SHAPE" "$FILL" "$EK" tank.h5 "${size_args[@]}" > table.txt 2>&1
  seconds=$(python3 -c "print(round($(date +%s.%N) - $start, 1))")
  h=$("$BUILD/modes/cavity-modes" info tank.h5 | sed -n '1s/.*h = \([0-9.e-]*\),.*/\1/p')
  unknowns=$(grep -o '[0-9]* real unknowns' table.txt | head -1 | cut -d' ' -f1)
  # The body's root (the nutation), not the verdict's slowest: a fluid root can decay more slowly than it.
  decay=$("$BUILD/rom/chain-rom" spectrum scene.toml | awk '/ body 1 .*decays/ {sub("i$", "", $2); print $2; exit}')
  row="$(date +%F),$SHAPE,$FILL,$EK,$h,$unknowns,$seconds,$decay"
  echo "$row" >> "$csv"
  echo "$row"
done
