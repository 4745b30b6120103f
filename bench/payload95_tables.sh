#!/usr/bin/env bash
# The projectile's payload filled to 95 % (data/scenes/projectile_payload95.toml, Ek = 1.33e-6, a free surface around
# the burster tube): the nutation's growth rate three ways, each timed with its peak memory — (1) the scene's recipe,
# a 3-row damped-mode table, and chain-rom spectrum with it; (2) the Krylov response table with the free surface
# (cavity-modes response --fill, the recipe's mesh, window -1.5:2:141, --max-fit-error 1e-4) and spectrum with it;
# (3) chain-rom confirm with the liquid's own response (R, R_fg, R_gg by forced solves). Writes
# OUT/payload95_tables_<date>.csv (method, seconds, peak GB, root, growth) and prints it; docs/benchmarks.md,
# "Partially filled tanks: response tables", records a run.
#   bash bench/payload95_tables.sh [BUILD_DIR] [OUT]      (about 22 minutes and 7 GB on 2 cores)
set -euo pipefail
if [ "${1:-}" = "--help" ] || [ "${1:-}" = "-h" ]; then
  sed -n '2,9p' "$0" | sed 's/^# \{0,1\}//'
  exit 0
fi
ROOT=$(cd "$(dirname "$0")/.." && pwd)
source "$ROOT/scripts/blas-core.sh"
BUILD=${1:-$ROOT/build}
OUT=${2:-$ROOT/bench/results}
MODES=$BUILD/modes/cavity-modes
ROM=$BUILD/rom/chain-rom
SCENE=$ROOT/data/scenes/projectile_payload95.toml
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$OUT"
csv=$OUT/payload95_tables_$(date +%F).csv
recipe=$(sed -n 's/^# recipe: [^:]*: \(.*\)$/\1/p' "$SCENE")
read -r -a args <<< "$recipe"
timed() {  # LOG COMMAND...: runs it under /usr/bin/time -v, its stdout into LOG; prints "seconds peak_GB"
  local log=$1; shift
  /usr/bin/time -v "$@" > "$log" 2> "$log.time"
  python3 - "$log.time" <<'PY'
import re, sys
t = open(sys.argv[1]).read()
h, m, s = (["0"] + re.search(r"Elapsed \(wall clock\) time \(h:mm:ss or m:ss\): (\S+)", t).group(1).split(":"))[-3:]
gb = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", t).group(1)) / 1e6
print("%.1f %.2f" % (3600 * float(h) + 60 * float(m) + float(s), gb))
PY
}
scene_with() {  # TABLE: the scene pointed at it
  sed "s#^table = .*#table = \"$1\"#" "$SCENE" > "$work/scene.toml"
  echo "$work/scene.toml"
}
root_of() {  # the growing body root of `spectrum --json` (or of confirm's)
  python3 -c "import json, sys; d = json.load(open(sys.argv[1])); r = d['roots']
r = [complex(*x['confirmed']) for x in r] if isinstance(r[0], dict) else [complex(*x) for x in r]
z = min(r, key=lambda z: z.imag); print('%.6f,%.6f,%.6f' % (z.real, z.imag, -z.imag))" "$1"
}
echo "method,seconds,peak_GB,sigma_re,sigma_im,growth" > "$csv.tmp"
read -r s gb <<< "$(timed "$work/modal.log" "$MODES" "${args[@]}" -o "$work/modal.h5")"
"$ROM" spectrum "$(scene_with "$work/modal.h5")" --json > "$work/modal.json" || true
echo "damped-mode table (recipe),$s,$gb,$(root_of "$work/modal.json")" >> "$csv.tmp"
read -r s gb <<< "$(timed "$work/krylov.log" "$MODES" response cylinder --radius 1 --height 4 --inner-radius 0.2 \
  --fill 0.95 --ekman 1.3333333e-6 --sigma -1.5:2:141 --max-fit-error 1e-4 -o "$work/krylov.h5")"
"$ROM" spectrum "$(scene_with "$work/krylov.h5")" --json > "$work/krylov.json" || true
echo "Krylov response table,$s,$gb,$(root_of "$work/krylov.json")" >> "$csv.tmp"
read -r s gb <<< "$(timed "$work/confirm.json" "$ROM" confirm "$(scene_with "$work/krylov.h5")" --json || true)"
echo "confirm (forced solves),$s,$gb,$(root_of "$work/confirm.json")" >> "$csv.tmp"
mv "$csv.tmp" "$csv"
cat "$csv"
