#!/usr/bin/env bash
# A partially filled tank moved off the craft's spin axis (docs/volume.md §8): the spheroid c/a = 0.8 filled to 0.7
# at axis distances D, its ideal modes by `cavity-modes ellipsoid --fill --axis-distance` (P4, h 0.35). Writes
# OUT/off_axis_fill_study.csv: each distance's b, its heaviest rows' weight-weighted λ and summed E (H_xx + H_yy) in
# the cluster about the on-axis mode, and the run's time. The cluster's λ must move as D² (the mirror D → −D is the
# same tank) and tend to the meridian solver's 1.23023573 as D → 0.
#   bash bench/off_axis_fill_study.sh [BUILD_DIR] [OUT] [DISTANCES...]   (the default five distances: about 6 min idle)
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=$(cd "${1:-$ROOT/build}" && pwd)
OUT=${2:-$ROOT/bench/results}
shift $(( $# > 2 ? 2 : $# ))
DISTANCES=("$@")
[ ${#DISTANCES[@]} -gt 0 ] || DISTANCES=(0 0.01 0.03 0.1 0.3)
mkdir -p "$OUT"
OUT=$(cd "$OUT" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
csv=$OUT/off_axis_fill_study.csv
[ -f "$csv" ] || echo "date,distance,b,lambda_cluster,E_cluster,rows_in_cluster,seconds" > "$csv"
for d in "${DISTANCES[@]}"; do
  start=$(date +%s.%N)
  "$BUILD/modes/cavity-modes" ellipsoid --a 1 --b 1 --c 0.8 --fill 0.7 --axis-distance "$d" --order 4 --mesh-size 0.35 \
    > run.txt 2> log.txt
  seconds=$(python3 -c "import time; print(round(time.time() - $start, 1))")
  # The cluster: rows within 0.05 of the on-axis mode (the heavy mode splits over discrete neighbours off the axis).
  python3 - "$d" "$seconds" "$csv" <<'PY'
import re, sys, datetime
d, seconds, csv = sys.argv[1], sys.argv[2], sys.argv[3]
text = open("run.txt").read()
b = re.search(r"free surface b = ([0-9.eE+-]+)", text).group(1)
rows = [l.split() for l in text.splitlines() if re.match(r"^ +[0-9]+\.[0-9]+ ", l)]
near = [(float(r[0]), float(r[1])) for r in rows if abs(float(r[0]) - 1.2302) < 0.05]
E = sum(e for _, e in near)
lam = sum(l * e for l, e in near) / E
line = f"{datetime.date.today()},{d},{b},{lam:.9f},{E:.6f},{len(near)},{seconds}"
open(csv, "a").write(line + "\n")
print(line)
PY
done
