#!/usr/bin/env bash
# 3-D cavities: error against run time of `cavity-modes ellipsoid` (the triaxial ellipsoid a, b, c = 1, 0.8, 0.6,
# upright) for orders and wall sizes, against the uniform-vorticity closed form (docs/volume.md §3, §4).
# Writes bench/results/volume_ellipsoid_<date>.csv and .png. Usage: bash bench/volume_ellipsoid.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
BIN=$BUILD/modes/cavity-modes
[ -x "$BIN" ] || { echo "bench/volume_ellipsoid.sh: build first ($BIN missing)" >&2; exit 1; }
source scripts/blas-core.sh
out=bench/results/volume_ellipsoid_$(date +%F)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "order,mesh_size,wall_size,ndof,seconds,max_rss_kb,lambda,lambda_rel_error,H_rel_error" > "$out.csv"
# order, interior size, wall size (0: uniform)
for run in "2 0.3 0" "3 0.3 0" "4 0.3 0" "4 0.2 0" "4 0.5 0.15" "6 0.5 0.2" "6 0.5 0.15" "6 0.5 0.1"; do
  set -- $run
  args=(ellipsoid --a 1 --b 0.8 --c 0.6 --order "$1" --mesh-size "$2" -o "$work/t.h5")
  [ "$3" != 0 ] && args+=(--wall-size "$3")
  /usr/bin/time -f "%e %M" -o "$work/time.txt" "$BIN" "${args[@]}" > "$work/log.txt" 2>&1
  read -r secs rss < "$work/time.txt"
  "$BIN" info "$work/t.h5" --json > "$work/t.json"
  /usr/bin/python3 - "$work/t.json" "$1" "$2" "$3" "$secs" "$rss" >> "$out.csv" <<'PY'
import json, math, sys
d = json.load(open(sys.argv[1]))
a, b, c = 1.0, 0.8, 0.6
m = 4 * math.pi * a * b * c / 3
lam = 2 * a * b / math.sqrt((a * a + c * c) * (b * b + c * c))
Hxx, Hyy = 0.4 * m * b * b * c * c / (b * b + c * c), 0.4 * m * a * a * c * c / (a * a + c * c)
modes, v = d["modes"], d["cavity_3d"]
# The cluster: the rows within 1e-3 of the exact λ (a 3-D mesh splits the mode among discrete copies; docs/volume.md §3).
rows = [k for k in range(len(modes["E"])) if abs(modes["lambda"][k] - lam) < 1e-3 * lam]
hxx = sum(v["coupling_re"][9 * k] for k in rows)
hyy = sum(v["coupling_re"][9 * k + 4] for k in rows)
err_H = max(abs(hxx - Hxx), abs(hyy - Hyy)) / (Hxx + Hyy)
l = sum(modes["lambda"][k] * modes["E"][k] for k in rows) / sum(modes["E"][k] for k in rows)
print(f"{sys.argv[2]},{sys.argv[3]},{sys.argv[4]},{d['ndof']},{sys.argv[5]},{sys.argv[6]},{l:.15f},"
      f"{abs(l - lam) / lam:.3e},{err_H:.3e}")
PY
  tail -1 "$out.csv"
done
/usr/bin/python3 - "$out.csv" "$out.png" <<'PY'
import csv, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
rows = list(csv.DictReader(open(sys.argv[1])))
fig, ax = plt.subplots(figsize=(6.4, 4.4))
for key, mark, name in (("lambda_rel_error", "o", "spin-over λ"), ("H_rel_error", "s", "coupling H_xx, H_yy (its rows within 1e-3)")):
    ax.loglog([float(r["seconds"]) for r in rows], [float(r[key]) for r in rows], mark, label=name)
for r in rows:
    ax.annotate(f"P{r['order']} h{r['mesh_size']}" + (f" w{r['wall_size']}" if r["wall_size"] != "0" else ""),
                (float(r["seconds"]), float(r["lambda_rel_error"])), fontsize=7, xytext=(3, 3), textcoords="offset points")
ax.set_xlabel("run time of cavity-modes ellipsoid (s, 2-core machine)")
ax.set_ylabel("relative error against the closed form")
ax.set_title("3-D triaxial ellipsoid 1 : 0.8 : 0.6, spin-over mode")
ax.grid(True, which="both", alpha=0.3)
ax.legend()
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=120)
PY
echo "wrote $out.csv and $out.png"
