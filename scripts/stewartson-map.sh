#!/usr/bin/env bash
# Stewartson's instability of a top with a partially filled cylinder as a map of the growth rate over fill and spin
# (docs/rom.md, "Partially filled tanks"): the scene data/scenes/stewartson_top.toml, a family of 45 tables (fill 0.10
# to 0.98 in steps of 0.02, cavity-modes cylinder --radius 1 --height 2 --fill F, about 2.5 s each), then one
# chain-rom sweep over the family and the spin (150..1000 rad/s, 35 values) and its PNG.
#   OUT/tables/cylinder_fill*.h5, OUT/stewartson-map.csv, OUT/stewartson-map.png   (OUT: the first argument, or out/)
# The programs must be built (bash scripts/build.sh cavity-modes chain-rom). Exits non-zero on the first failure.
set -euo pipefail
if [ "${1:-}" = "--help" ] || [ "${1:-}" = "-h" ]; then
  echo "usage: bash scripts/stewartson-map.sh [OUT]"
  sed -n '2,/^set -euo/p' "$0" | grep '^#' | sed 's/^# \{0,1\}//'
  exit 0
fi
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
OUT="$(mkdir -p "${1:-$ROOT/out}" && cd "${1:-$ROOT/out}" && pwd)"
MODES="$ROOT/build/modes/cavity-modes"
ROM="$ROOT/build/rom/chain-rom"
for bin in "$MODES" "$ROM"; do
  [ -x "$bin" ] || { echo "stewartson-map: $bin is missing: bash scripts/build.sh cavity-modes chain-rom" >&2; exit 1; }
done
source "$ROOT/scripts/blas-core.sh"
mkdir -p "$OUT/tables"
start=$SECONDS
fills=$(LC_ALL=C seq -f '%.2f' 0.10 0.02 0.98)
count=$(wc -w <<< "$fills")
i=0
for f in $fills; do
  i=$((i + 1))
  table="$OUT/tables/cylinder_fill$f.h5"
  if [ ! -f "$table" ] || [ "$table" -ot "$MODES" ]; then
    "$MODES" cylinder --radius 1 --height 2 --fill "$f" -o "$table" > /dev/null
  fi
  printf '[stewartson-map %3ds] table %d/%d (fill %s)\n' "$((SECONDS - start))" "$i" "$count" "$f"
done
# The scene's own table path is replaced by the family's (the sweep's key names a printf pattern of the fill).
scene="$OUT/stewartson_top.toml"
sed "s#^table = .*#table = \"$OUT/tables/cylinder_fill0.62.h5\"#" "$ROOT/data/scenes/stewartson_top.toml" > "$scene"
"$ROM" sweep "$scene" --param "body[1].cavity.table=$OUT/tables/cylinder_fill%.2f.h5" --from 0.10 --to 0.98 --steps "$count" \
  --param2 "body[1].spin" --from2 150 --to2 1000 --steps2 35 -o "$OUT/stewartson-map.raw.csv"
# The fill, not the file pattern, names the first column.
sed '1s/^[^,]*,/fill,/' "$OUT/stewartson-map.raw.csv" > "$OUT/stewartson-map.csv"
rm -f "$OUT/stewartson-map.raw.csv"
/usr/bin/python3 "$ROOT/scripts/plot_sweep.py" "$OUT/stewartson-map.csv" -o "$OUT/stewartson-map.png" \
  --title "Stewartson's top: growth rate over fill and spin"
printf '[stewartson-map %3ds] wrote %s and %s\n' "$((SECONDS - start))" "$OUT/stewartson-map.csv" "$OUT/stewartson-map.png"
