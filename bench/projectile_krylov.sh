#!/usr/bin/env bash
# The projectile with a liquid payload (data/scenes/projectile_liquid.toml) at 800, 1500, 2000 and 3000 rad/s: at each
# spin its Krylov response table (the scene's recipe at that spin's Ekman number, under mpirun -n 2 where there is
# mpirun; timed), chain-rom spectrum with it (the table's roots) and chain-rom confirm (the roots of (22) with the
# liquid's own response by forced solves). Writes OUT/projectile_krylov_<date>.csv (one line a root: spin, Ek, table
# seconds, the table's root, the confirmed root, their distance relative to |sigma|, both growth rates; then, after
# `chain-rom confirm --refine-tables` remade the table with R exact at the confirmed roots (serially), the seconds
# that took and the refined table's nearest root's distance from the confirmed one, by a separate `spectrum`) and
# prints it;
# docs/benchmarks.md, "Krylov response tables", records a run.
#   bash bench/projectile_krylov.sh [BUILD_DIR] [OUT] [MAX_FIT_ERROR]      (about 10 minutes on 2 cores)
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
source "$ROOT/scripts/blas-core.sh"
BUILD=${1:-$ROOT/build}
OUT=${2:-$ROOT/bench/results}
TOL=${3:-}
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
if [ -n "$TOL" ]; then
  for i in "${!args[@]}"; do [ "${args[$i]}" != --max-fit-error ] || args[$((i + 1))]=$TOL; done
fi
launcher=()
if [ "$(nproc)" -gt 1 ] && command -v mpirun > /dev/null; then
  launcher=(env OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1 mpirun -n "$(nproc)")
fi
nu=$(sed -n 's/^viscosity = \([^ ]*\).*/\1/p' "$SCENE")
scale=$(sed -n 's/^scale = \([^ ]*\).*/\1/p' "$SCENE")
csv=$OUT/projectile_krylov_$day.csv
echo "spin,ekman,table_seconds,confirm_seconds,owner,table_re,table_im,confirmed_re,confirmed_im,relative_distance,table_growth,confirmed_growth,refine_seconds,refined_distance" > "$csv.tmp"
for spin in 800 1500 2000 3000; do
  ek=$(python3 -c "print('%.8g' % ($nu / ($spin * $scale ** 2)))")
  run=("${args[@]}")
  for i in "${!run[@]}"; do [ "${run[$i]}" != --ekman ] || run[$((i + 1))]=$ek; done
  t0=$(date +%s.%N)
  "${launcher[@]}" "$MODES" "${run[@]}" -o "$work/$spin.h5" > "$work/$spin.txt" 2> "$work/$spin.err" ||
    { tail -3 "$work/$spin.err" >&2; exit 1; }
  t1=$(date +%s.%N)
  sed -e "s#\"../../out/tables/$name\"#\"$work/$spin.h5\"#" -e "s/^spin = .*/spin = $spin.0/" "$SCENE" > "$work/$spin.toml"
  "$ROM" confirm "$work/$spin.toml" --json --refine-tables --cavity-modes "$MODES" > "$work/$spin.json" || true
  t2=$(date +%s.%N)
  "$ROM" spectrum "$work/$spin.toml" --json > "$work/$spin.refined.json"
  python3 - "$spin" "$ek" "$t0" "$t1" "$t2" "$work/$spin.json" "$work/$spin.refined.json" >> "$csv.tmp" <<'PY'
import json, sys
spin, ek, t0, t1, t2, path, refined = sys.argv[1:]
res = json.load(open(path))
after = [complex(*z) for z in json.load(open(refined))["roots"]]
refine = res.get("refine_seconds", float("nan"))
for r in res["roots"]:
    a, b = complex(*r["table"]), complex(*r["confirmed"])
    c = min(after, key=lambda z: abs(z - b))
    print("%s,%s,%.1f,%.1f,%s,%.12g,%.12g,%.12g,%.12g,%.3g,%.6g,%.6g,%.1f,%.3g" % (
        spin, ek, float(t1) - float(t0), float(t2) - float(t1) - refine, r["owner"].replace(",", " "), a.real, a.imag,
        b.real, b.imag, abs(a - b) / abs(b), -a.imag, -b.imag, refine, abs(c - b) / abs(b)))
PY
  grep -o "Krylov space: [0-9]* expansion points" "$work/$spin.txt" | sed "s/^/  $spin rad\/s: /" || true
done
mv "$csv.tmp" "$csv"
column -s, -t < "$csv"
