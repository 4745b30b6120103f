#!/usr/bin/env bash
# The spacecraft of data/scenes/spacecraft_nutation.toml with its spherical tank completely full, at several Ekman
# numbers: the nutation's decay by the spectral method (docs/spherical.md §5: `cavity-modes shell --sigma ... -o
# FILE.h5`, chain-rom spectrum, then chain-rom confirm with the served spectral solves and its truncation study) as the
# reference, and the finite elements' default commands (the default Krylov table, spectrum, confirm with its mesh
# study) measured against it. One CSV row per Ekman number in OUT/spectral_sphere_reference.csv; docs/trust.md's
# sphere rows come from it. Serial, as the default commands run. About 9 minutes for the three defaults.
#   bash bench/spectral_sphere_reference.sh [BUILD_DIR] [OUT] [EKMAN ...]
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=$(cd "${1:-$ROOT/build}" && pwd)
mkdir -p "${2:-$ROOT/bench/results}"
OUT=$(cd "${2:-$ROOT/bench/results}" && pwd)
shift $(( $# > 2 ? 2 : $# )) || true
EKS=("$@")
[ ${#EKS[@]} -gt 0 ] || EKS=(1e-4 1e-5 1e-6)
MODES=$BUILD/modes/cavity-modes
ROM=$BUILD/rom/chain-rom
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$OUT"
cd "$work"
# shellcheck source=spacecraft_tank.sh
source "$ROOT/bench/spacecraft_tank.sh"
scene() { spacecraft_tank_scene "$2" "$1"; }  # TABLE EK: the spacecraft with that table at EK
body_decay() { "$ROM" spectrum "$1" | awk '/ body 1 .*decays/ {sub("i$", "", $2); print $2; exit}'; }
confirmed() {  # confirm --json output: decay,bar,flag of the body's root
  python3 -c 'import json, sys
try:
    r = [x for x in json.load(open(sys.argv[1]))["roots"] if x["owner"].startswith("body")][0]
    print("%.10g,%.3g,%s" % (-r["growth"], r["growth_error"], "converged" if r["mesh_converged"] else "NOT CONVERGED"))
except Exception as e:
    print("nan,nan,failed")' "$1"
}
csv=$OUT/spectral_sphere_reference.csv
[ -f "$csv" ] || echo "date,ekman,spectral_table_s,spectral_table_decay,spectral_confirm_decay,spectral_bar,spectral_flag,spectral_confirm_s,fe_table_s,fe_table_decay,fe_confirm_decay,fe_bar,fe_flag,fe_confirm_s,fe_table_error,fe_confirm_error,bar_covers" > "$csv"
for ek in "${EKS[@]}"; do
  echo "== Ek $ek ($(date +%T))"
  scene spectral.h5 "$ek" > spectral.toml
  scene fe.h5 "$ek" > fe.toml
  t=$(now); "$MODES" shell --ekman "$ek" --sigma -2.5:2:181 -o spectral.h5 > spectral.txt 2>&1; st=$(since "$t")
  t=$(now); "$ROM" confirm spectral.toml --json --cavity-modes "$MODES" > sc.json 2> sc.log || true; sc=$(since "$t")
  t=$(now); "$MODES" response sphere --radius 1 --ekman "$ek" --sigma -2.5:2:181 -o fe.h5 > fe.txt 2>&1; ft=$(since "$t")
  t=$(now); "$ROM" confirm fe.toml --json --cavity-modes "$MODES" > fc.json 2> fc.log || true; fc=$(since "$t")
  s_row=$(confirmed sc.json); f_row=$(confirmed fc.json)
  row="$(date +%F),$ek,$st,$(body_decay spectral.toml),$s_row,$sc,$ft,$(body_decay fe.toml),$f_row,$fc"
  row=$(python3 -c 'import sys
r = sys.argv[1].split(",")
ref, tab, conf, bar = float(r[4]), float(r[9]), float(r[10]), float(r[11])
print("%s,%.3g,%.3g,%s" % (sys.argv[1], abs(tab - ref) / ref, abs(conf - ref) / ref, "yes" if abs(conf - ref) <= bar else "no"))' "$row")
  echo "$row" >> "$csv"
  echo "$row"
done
