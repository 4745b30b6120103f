#!/usr/bin/env bash
# What a large Krylov response table costs, end to end: one tank of the spacecraft of data/scenes/spacecraft_nutation.toml
# (as bench/viscous_fill_study.sh), its default table (time, points, rows), then `chain-rom spectrum` with the rows that
# no root needs left out (the default) and with every row (`prune = false`): each time, the rows left out, and the
# nutation's decay both ways. Appends one CSV row to OUT/krylov_table_cost.csv and prints it (docs/rom.md, "Rows no
# root needs"; docs/viscous.md, "Where a partially filled tank's table spends its time").
#   bash bench/krylov_table_cost.sh "cone --radius 1 --height 1.5" 0.8 1e-7 [BUILD_DIR] [OUT]   (about 75 s idle)
set -euo pipefail
usage="usage: bash bench/krylov_table_cost.sh SHAPE_ARGS FILL EKMAN [BUILD_DIR] [OUT]"
if [ "${1:-}" = "--help" ] || [ "${1:-}" = "-h" ]; then
  echo "$usage"
  sed -n '2,/^set -euo/p' "$0" | grep '^#' | sed 's/^# \{0,1\}//'
  exit 0
fi
ROOT=$(cd "$(dirname "$0")/.." && pwd)
SHAPE=${1:?$usage}
FILL=${2:?$usage}
EK=${3:?$usage}
BUILD=${4:-$ROOT/build}
OUT=${5:-$ROOT/bench/results}
MODES=$BUILD/modes/cavity-modes
ROM=$BUILD/rom/chain-rom
# shellcheck source=spacecraft_tank.sh
source "$ROOT/bench/spacecraft_tank.sh"
spacecraft_tank_workdir "$EK"
sed 's/^viscosity = \(.*\)/viscosity = \1\nprune = false/' scene.toml > all_rows.toml
t=$(now)
spacecraft_tank_table "$MODES" "$SHAPE" "$FILL" "$EK" tank.h5 > table.txt 2>&1
table_s=$(since "$t")
points=$("$MODES" info tank.h5 | sed -n 's/.*Krylov space: \([0-9]*\) expansion points.*/\1/p' | head -1)
rows=$(/usr/bin/python3 -c "import h5py; print(len(h5py.File('tank.h5', 'r')['modes/lambda']))")
# The body's first root line: its decay (1/s).
nutation() { awk '/ body 1 .*decays/ {sub("i$", "", $2); print $2; exit}' "$1"; }
t=$(now)
"$ROM" spectrum scene.toml > pruned.txt
pruned_s=$(since "$t")
t=$(now)
"$ROM" spectrum all_rows.toml > all.txt
all_s=$(since "$t")
left_out=$(sed -n 's/.*, \([0-9]*\) rows\{0,1\} left out that no root needs.*/\1/p' pruned.txt | head -1)
csv=$OUT/krylov_table_cost.csv
[ -f "$csv" ] || echo "date,shape,fill,ekman,table_s,points,rows,rows_left_out,spectrum_s,spectrum_all_rows_s,decay,decay_all_rows" > "$csv"
row="$(date +%F),$SHAPE,$FILL,$EK,$table_s,$points,$rows,${left_out:-0},$pruned_s,$all_s,$(nutation pruned.txt),$(nutation all.txt)"
echo "$row" >> "$csv"
echo "$row"
