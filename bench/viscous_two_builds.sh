#!/usr/bin/env bash
# Two builds of cavity-modes on the same viscous commands, one after the other on this machine: run time, peak memory
# and how far the tables differ (the five heaviest rows' λ + i decay and E + i E_imag, relative). For a change that
# should only make the viscous solvers faster (docs/benchmarks.md, "Complex factorisation").
#   bash bench/viscous_two_builds.sh OLD_BUILD_DIR [NEW_BUILD_DIR] [OUT]
# OLD_BUILD_DIR: a build of the earlier commit (git worktree add /tmp/old REV; cmake; make cavity-modes). Serial,
# one thread, OpenBLAS on one core (scripts/blas-core.sh). Writes OUT/viscous_two_builds_<date>.csv; about 3 minutes.
set -euo pipefail
if [ "${1:-}" = "--help" ] || [ "${1:-}" = "-h" ] || [ $# -lt 1 ]; then
  sed -n '2,7p' "$0" | sed 's/^# \{0,1\}//'
  [ $# -ge 1 ] && exit 0 || exit 2
fi
ROOT=$(cd "$(dirname "$0")/.." && pwd)
source "$ROOT/scripts/blas-core.sh"
export OMP_NUM_THREADS=1
OLD=$1/modes/cavity-modes
NEW=${2:-$ROOT/build}/modes/cavity-modes
OUT=${3:-$ROOT/bench/results}
for b in "$OLD" "$NEW"; do [ -x "$b" ] || { echo "viscous_two_builds: no executable $b" >&2; exit 1; }; done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$OUT"
csv=$OUT/viscous_two_builds_$(date +%F).csv
echo "case,unknowns,old_seconds,old_gb,new_seconds,new_gb,speedup,rows_old,rows_new,lambda_difference,E_difference" > "$csv"
case_row() {  # label, then cavity-modes arguments
  local label=$1
  shift
  for b in old new; do
    local bin=$OLD
    [ $b = new ] && bin=$NEW
    /usr/bin/time -f "%e %M" -o "$work/time.$b" "$bin" "$@" -o "$work/$b.h5" > "$work/$b.txt" 2>&1 ||
      { echo "$label: the $b build failed: $(tail -1 "$work/$b.txt")" >&2; return; }
  done
  /usr/bin/python3 - "$label" "$work" >> "$csv" <<'PY'
import h5py, sys, numpy as np
label, work = sys.argv[1:]
runs = []
for b in ("old", "new"):
    seconds, kb = open("%s/time.%s" % (work, b)).read().split()[-2:]
    f = h5py.File("%s/%s.h5" % (work, b)); m = f["modes"]
    lam = np.array(m["lambda"]) + 1j * np.array(m["decay"]); E = np.array(m["E"]) + 1j * np.array(m["E_imag"])
    runs.append((float(seconds), int(kb) / 1e6, lam, E, int(f.attrs["ndof"])))
(to, mo, lo, Eo, n), (tn, mn, ln, En, _) = runs
i, j = np.argsort(-np.abs(Eo)), np.argsort(-np.abs(En))
k = min(len(i), len(j), 5)
dl = max(abs(lo[i[:k]] - ln[j[:k]]) / abs(lo[i[:k]])); dE = max(abs(Eo[i[:k]] - En[j[:k]]) / abs(Eo[i[:k]]))
print("%s,%d,%.2f,%.2f,%.2f,%.2f,%.2f,%d,%d,%.1e,%.1e" % (label, n, to, mo, tn, mn, to / tn, len(lo), len(ln), dl, dE))
PY
}
case_row "sphere Ek 1e-4 --target 1.0" sphere --radius 1 --ekman 1e-4 --target 1.0 --no-convergence-check
case_row "sphere Ek 1e-5 --target 1.0" sphere --radius 1 --ekman 1e-5 --target 1.0 --no-convergence-check
case_row "sphere Ek 1e-6 --target 1.0" sphere --radius 1 --ekman 1e-6 --target 1.0 --no-convergence-check
case_row "sphere Ek 1e-6 default command" sphere --radius 1 --ekman 1e-6
case_row "Kore's shell Ek 1e-3 --target 1.0" section "$ROOT/data/sections/shell.geo" --ekman 1e-3 --target 1.0 --no-convergence-check
case_row "default scene's water cylinder response table" response cylinder --radius 1 --height 2 --ekman 2.0833333e-6 \
  --mesh-size 0.2 --sigma -1.5:2:141 --max-fit-error 1e-4
case_row "default scene's water spheroid response table" response spheroid --a 1 --c 0.5 --ekman 3.125e-6 \
  --mesh-size 0.15 --sigma -1.5:2:141 --max-fit-error 1e-4
column -s, -t < "$csv"
