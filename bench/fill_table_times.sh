#!/usr/bin/env bash
# The time a user waits for a partially filled tank's viscous response table made with the defaults, and for
# chain-rom's spectrum with it: each built-in shape at each fill, `cavity-modes response SHAPE --fill F --ekman EK
# --sigma -2.5:2:181` (the recipe of docs/trust.md's rows) and `chain-rom spectrum` on the spacecraft of
# data/scenes/spacecraft_nutation.toml with that table. One CSV row per table to OUT/fill_table_times_<date>.csv:
# shape, fill, Ek, unknowns, expansion points, rows, the table's seconds and peak memory, the spectrum's seconds and the
# nutation's decay. The decay's mesh error is bench/viscous_fill_study.sh's (docs/trust.md); this is the cost.
#   bash bench/fill_table_times.sh [BUILD_DIR] [OUT]      (about 15 minutes idle on 2 cores; run it alone)
# SHAPES (one per line) and FILLS, EKMAN override the defaults below.
set -euo pipefail
if [ "${1:-}" = "--help" ] || [ "${1:-}" = "-h" ]; then
  sed -n '2,9p' "$0" | sed 's/^# \{0,1\}//'
  exit 0
fi
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=$(cd "${1:-$ROOT/build}" && pwd)
OUT=${2:-$ROOT/bench/results}
EK=${EKMAN:-1e-6}
FILLS=${FILLS:-"0.5 0.8"}
SHAPES=${SHAPES:-"sphere --radius 1
spheroid --a 1 --c 0.666667
cone --radius 1 --height 1.5
cylinder --radius 1 --height 2
cylinder --radius 1 --height 2 --inner-radius 0.3"}
mkdir -p "$OUT"
OUT=$(cd "$OUT" && pwd)
csv=$OUT/fill_table_times_$(date +%F).csv
[ -f "$csv" ] || echo "shape,fill,ekman,unknowns,points,rows,table_s,table_peak_gb,spectrum_s,nutation_decay" > "$csv"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
# shellcheck source=spacecraft_tank.sh
source "$ROOT/bench/spacecraft_tank.sh"
spacecraft_tank_scene "$EK" tank.h5 > scene.toml
while IFS= read -r shape_line; do
  read -r -a shape <<< "$shape_line"
  for fill in $FILLS; do
    echo "fill_table_times: $shape_line --fill $fill --ekman $EK ..." >&2
    /usr/bin/time -f "%e %M" -o table.time "$BUILD/modes/cavity-modes" response "${shape[@]}" --fill "$fill" \
      --ekman "$EK" --sigma -2.5:2:181 -o tank.h5 > table.txt 2>&1
    read -r table_s peak_kb < table.time
    unknowns=$(sed -n 's/.*Taylor-Hood P[0-9]\/P[0-9], \([0-9]*\) real unknowns.*/\1/p' table.txt)
    points=$(sed -n 's/^solver: .* \([0-9]*\) expansion points.*/\1/p' table.txt)
    rows=$(grep -c '^ *[0-9]\+ \+-\?[0-9]' table.txt || true)
    /usr/bin/time -f "%e" -o spectrum.time "$BUILD/rom/chain-rom" spectrum scene.toml > spectrum.txt 2>&1
    spectrum_s=$(cat spectrum.time)
    decay=$(awk '/ body 1 .*decays/ {sub("i$", "", $2); print $2; exit}' spectrum.txt)
    row="$shape_line,$fill,$EK,$unknowns,$points,$rows,$table_s,$(python3 -c "print(round($peak_kb / 1048576, 2))"),$spectrum_s,$decay"
    echo "$row" | tee -a "$csv"
  done
done <<< "$SHAPES"
