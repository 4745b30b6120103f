#!/usr/bin/env bash
# The spacecraft of data/scenes/spacecraft_nutation.toml (a 60 %-full sphere at Ek = 9.05e-7) the way a user runs it:
# the default response table (timed), chain-rom spectrum with it, chain-rom confirm with its defaults (the mesh study
# on the table's mesh and its halving, timed), and the reference: confirm on P4 then P5 with h 0.0145 (timed). Prints
# each decay rate and time and writes OUT/spacecraft_nutation_<date>.txt; docs/rom.md, "Mesh error of confirmed
# roots", records a run (2026-11-29: table 170 s, confirm 76.5 s, reference about 200 s; 2.9790e-4 +- 2.1e-7 against
# 2.9726e-4 +- 1.4e-7 1/s).
#   bash bench/spacecraft_nutation.sh [BUILD_DIR] [OUT]        (about 8 minutes idle on 2 cores, 11 GB at most)
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=${1:-$ROOT/build}
OUT=${2:-$ROOT/bench/results}
MODES=$BUILD/modes/cavity-modes
ROM=$BUILD/rom/chain-rom
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$OUT"
log=$OUT/spacecraft_nutation_$(date +%F).txt
sed 's#"../../out/tables/sphere_fill0.6_hydrazine.h5"#"fill.h5"#' "$ROOT/data/scenes/spacecraft_nutation.toml" > "$work/scene.toml"
cd "$work"
now() { date +%s.%N; }
since() { python3 -c "print(round($(now) - $1, 1))"; }
{
  t=$(now)
  "$MODES" response sphere --radius 1 --fill 0.6 --ekman 9.05192e-7 --sigma -2.5:2:181 -o fill.h5 > table.txt 2>&1
  echo "default response table: $(since "$t") s, $("$MODES" info fill.h5 | grep -o '[0-9]* Ritz pairs' | head -1) (two rows each)"
  echo "spectrum: $("$ROM" spectrum scene.toml | grep '^stable')"
  t=$(now)
  "$ROM" confirm scene.toml --cavity-modes "$MODES" > confirm.txt
  echo "confirm (defaults): $(since "$t") s: $(grep '^ *body 1 .*decay' confirm.txt)"
  t=$(now)
  "$ROM" confirm scene.toml --order 4 --mesh-size 0.0145 --refine-by order --cavity-modes "$MODES" > reference.txt
  echo "reference (P4, P5 on h 0.0145): $(since "$t") s: $(grep '^ *body 1 .*decay' reference.txt)"
} | tee "$log"
