#!/usr/bin/env bash
# One tank of the spacecraft of data/scenes/spacecraft_nutation.toml (800 kg, A = 400, C = 520 kg m^2, 60 rpm; the
# tank's scale 0.4 m, its centre 0.3 m above the centre of mass) with any built-in shape, fill and Ekman number, the
# way a user runs it: the default response table, chain-rom spectrum, chain-rom confirm with its defaults (the mesh
# study), and a reference: confirm on P4 then P5 with a quarter of the table's interior size. Appends one CSV row per
# run to OUT/viscous_fill_study.csv (shape, fill, Ek, each decay rate with its bar, the times) and prints them:
# docs/trust.md's viscous rows come from it.
#   bash bench/viscous_fill_study.sh "sphere --radius 1" 0.6 9.05192e-7 [BUILD_DIR] [OUT]
#   (the 60 %-full sphere: about 8 minutes idle on 2 cores, 11 GB at most; smaller liquids need finer references)
# REFERENCE_DIVISOR (default 4): the reference's interior size is the table's over it; 3 where the quarter's P4 mesh
# does not fit in memory (the annular tank at 30 %: 1.9 million real unknowns, refused up front). Run it alone: a
# level that fits beside another job's tables may not.
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
SHAPE=${1:?usage: viscous_fill_study.sh SHAPE_ARGS FILL EKMAN [BUILD_DIR] [OUT]}
FILL=${2:?fill}
EK=${3:?Ekman number}
BUILD=${4:-$ROOT/build}
OUT=${5:-$ROOT/bench/results}
MODES=$BUILD/modes/cavity-modes
ROM=$BUILD/rom/chain-rom
# shellcheck source=spacecraft_tank.sh
source "$ROOT/bench/spacecraft_tank.sh"
spacecraft_tank_workdir "$EK"
t=$(now)
spacecraft_tank_table "$MODES" "$SHAPE" "$FILL" "$EK" tank.h5 > table.txt 2>&1
table_s=$(since "$t")
h=$("$MODES" info tank.h5 | sed -n '1s/.*h = \([0-9.e-]*\),.*/\1/p')
# The body's root (the nutation), not the verdict's slowest: a fluid root can decay more slowly than it.
spectrum=$("$ROM" spectrum scene.toml | awk '/ body 1 .*decays/ {sub("i$", "", $2); print $2; exit}')
# The body root's decay, its bar and whether converged, from confirm --json.
decay() {
  python3 -c 'import json, sys
try:
    r = [x for x in json.load(open(sys.argv[1]))["roots"] if x["owner"].startswith("body")][0]
    print("%.8g,%.3g,%s" % (-r["growth"], r["growth_error"], "converged" if r["mesh_converged"] else "NOT CONVERGED"))
except Exception as e:
    print("nan,nan,failed")' "$1"
}
t=$(now)
"$ROM" confirm scene.toml --json --cavity-modes "$MODES" > confirm.txt 2> confirm.log || true
confirm_s=$(since "$t")
t=$(now)
fine=$(python3 -c "print($h / ${REFERENCE_DIVISOR:-4})")
"$ROM" confirm scene.toml --json --order 4 --mesh-size "$fine" --refine-by order --cavity-modes "$MODES" > reference.txt \
  2> reference.log || true
reference_s=$(since "$t")
csv=$OUT/viscous_fill_study.csv
[ -f "$csv" ] || echo "date,shape,fill,ekman,table_h,table_s,spectrum_decay,confirm_decay,confirm_bar,confirm_flag,confirm_s,reference_h,reference_decay,reference_bar,reference_flag,reference_s" > "$csv"
row="$(date +%F),$SHAPE,$FILL,$EK,$h,$table_s,$spectrum,$(decay confirm.txt),$confirm_s,$fine,$(decay reference.txt),$reference_s"
echo "$row" >> "$csv"
echo "$row"
# A failed confirm says why (the work folder goes with the script).
for f in confirm reference; do
  case "$(decay $f.txt)" in
    *failed) echo "$f gave no body root with a bar: $(head -c 600 $f.txt) $(tail -3 $f.log)" >&2 ;;
  esac
done
