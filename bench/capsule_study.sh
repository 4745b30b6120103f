#!/usr/bin/env bash
# The capsule study of docs/trust.md: data/sections/capsule.geo at order 6 and --mesh-size 0.25, 0.125, 0.0625
# (tables, `cavity-modes compare` of consecutive pairs, exact band weights by spectral-window). About 1 h on the
# 2-core machine (the finest table 25 min, its three spectral-window bands 17 min). Results into OUT
# (default bench/results/capsule_<date>).
#   bash bench/capsule_study.sh [BUILD_DIR] [OUT]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
out=${2:-$root/bench/results/capsule_$(date +%F)}
mkdir -p "$out"
geo=$root/data/sections/capsule.geo
for h in 0.25 0.125 0.0625; do
  "$build/modes/cavity-modes" section "$geo" --mesh-size $h -o "$out/cap_$h.h5" > "$out/table_h$h.txt"
  "$build/modes/spectral-window" section "$geo" --mesh-size $h --window 0.4,0.5 --window 0.1,0.2 \
    --window=-0.5,-0.4 > "$out/spectral_window_h$h.json"
done
(cd "$out" && "$build/modes/cavity-modes" compare cap_0.125.h5 cap_0.25.h5 --tolerance 1e-3 > compare_0.125_0.25.txt)
(cd "$out" && "$build/modes/cavity-modes" compare cap_0.0625.h5 cap_0.125.h5 --tolerance 1e-3 > compare_0.0625_0.125.txt)
rm -f "$out"/cap_*.h5
echo "capsule study written to $out"
