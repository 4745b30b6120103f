#!/usr/bin/env bash
# A viscous 3-D tank in the chain (docs/volume.md §7, "The example"; docs/benchmarks.md, "Viscous 3-D"): the growth
# rate of data/scenes/spacecraft_viscous_tank.toml (its elongated 1 : 0.8 : 3 tank at Ek = 1e-3) against the run time
# of the tank's viscous table, on P2 and P3 tetrahedral meshes (`cavity-modes ellipsoid --ekman 1e-3 ... -o`, without
# the convergence check; then `chain-rom spectrum --json`), with the ideal liquid's chain (the table without --ekman
# and the scene without its viscosity) for reference. Writes bench/results/volume_viscous_chain_<date>.csv and .png.
# About 7 minutes and 11 GB at most on a 2-core machine.
# Usage: bash bench/volume_viscous_chain.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
MODES=$BUILD/modes/cavity-modes
ROM=$BUILD/rom/chain-rom
for b in "$MODES" "$ROM"; do [ -x "$b" ] || { echo "bench/volume_viscous_chain.sh: build first ($b missing)" >&2; exit 1; }; done
source scripts/blas-core.sh
scene=data/scenes/spacecraft_viscous_tank.toml
out=bench/results/volume_viscous_chain_$(date +%F)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# The scene on a given table (its recipe's table name replaced), with or without its viscosity line.
scene_on() {  # table, keep_viscosity (1/0)
  sed -e "s#\"../../out/tables/spacecraft_viscous_tank.h5\"#\"$work/$1\"#" "$scene" |
    { if [ "$2" = 1 ]; then cat; else grep -v '^viscosity = '; fi; } > "$work/scene.toml"
}
growth() { "$ROM" spectrum "$work/scene.toml" --json | /usr/bin/python3 -c 'import json, sys; print(json.load(sys.stdin)["growth"])'; }
echo "order,mesh_size,wall_size,unknowns,seconds,max_rss_kb,growth" > "$out.csv"
# order, interior size (0: the default), wall size (0: the default 2 Ek^1/2)
for run in "2 0 0" "2 0.25 0.045" "3 0.4 0.09" "3 0.4 0.063" "3 0 0" "3 0.4 0.045" "3 0 0.045"; do
  set -- $run
  args=(ellipsoid --a 1 --b 0.8 --c 3 --ekman 1e-3 --order "$1" --no-convergence-check)
  [ "$2" != 0 ] && args+=(--mesh-size "$2")
  [ "$3" != 0 ] && args+=(--wall-size "$3")
  /usr/bin/time -f "%e %M" -o "$work/time.txt" "$MODES" "${args[@]}" -o "$work/t.h5" > "$work/log.txt" 2>&1
  read -r secs rss < "$work/time.txt"
  unknowns=$(grep -o '[0-9]* unknowns' "$work/log.txt" | head -1 | cut -d' ' -f1)
  scene_on t.h5 1
  echo "$1,$2,$3,$unknowns,$secs,$rss,$(growth)" | tee -a "$out.csv"
done
"$MODES" ellipsoid --a 1 --b 0.8 --c 3 -o "$work/ideal.h5" > /dev/null 2>&1
scene_on ideal.h5 0
ideal=$(growth)
echo "ideal liquid: growth $ideal 1/s"
/usr/bin/python3 - "$out.csv" "$out.png" "$ideal" <<'PY'
import csv, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

rows = list(csv.DictReader(open(sys.argv[1])))
p3 = [float(r["growth"]) for r in rows if r["order"] == "3"]
mean = sum(p3) / len(p3)
fig, ax = plt.subplots(figsize=(6.4, 4.4))
for order, mark in (("2", "o"), ("3", "s")):
    sel = [r for r in rows if r["order"] == order]
    ax.semilogx([float(r["seconds"]) for r in sel], [float(r["growth"]) for r in sel], mark, label=f"P{order} tables")
    for r in sel:
        ax.annotate(f"h {r['mesh_size'] if r['mesh_size'] != '0' else 'def'}, w {r['wall_size'] if r['wall_size'] != '0' else 'def'}",
                    (float(r["seconds"]), float(r["growth"])), fontsize=7, xytext=(3, 3), textcoords="offset points")
ax.axhline(mean, color="gray", lw=0.8, ls="--", label=f"mean of the P3 tables {mean:.5f}")
ax.set_xlabel("the viscous table's run time (s)")
ax.set_ylabel("the spacecraft's growth rate (1/s)")
ax.set_title(f"viscous 3-D tank at Ek = 1e-3 in the chain (ideal liquid: {float(sys.argv[3]):.4f} 1/s)", fontsize=9)
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=120)
for r in rows:
    print(f"P{r['order']} h {r['mesh_size']} wall {r['wall_size']}: {r['unknowns']} unknowns, {r['seconds']} s, "
          f"{float(r['max_rss_kb']) / 1e6:.1f} GB, growth {float(r['growth']):.6f} ({float(r['growth']) / mean - 1:+.2%} "
          f"from the P3 mean)")
print("wrote", sys.argv[2])
PY
