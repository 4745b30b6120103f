#!/usr/bin/env bash
# The 3-D viscous response table (docs/volume.md §7, "The response table"; docs/benchmarks.md, "Viscous 3-D"): error
# against run time, and what the whole response changes in a chain.
#  A. The spheroid a = 1, c = 0.5 at Ek = 1e-2 on one P3 mesh (h 0.3, wall 0.08): response tables at --max-fit-error
#     1e-2 … 1e-6, each measured against forced solves on the same mesh at six frequencies it never saw (in the
#     window, beyond it, off the real axis), and the nutation of a top carrying it (A = B, 200 rad/s: the chain without
#     axial symmetry) against (26) with the meridian solver's Krylov response table (P6, --max-fit-error 1e-8) — the
#     mesh's error, which no tolerance removes; the damped-mode table (the spin-over alone) for comparison.
#  B. data/scenes/spacecraft_viscous_tank.toml (its 1 : 0.8 : 3 tank at Ek = 1e-3): its growth rate with the recipe's
#     damped-mode table and with a response table on the same mesh.
# Writes bench/results/volume_response_table_<date>.csv (part A) and .png, and prints part B. About 8 minutes and
# 7 GB at most on a 2-core machine.
# Usage: bash bench/volume_response_table.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
MODES=$BUILD/modes/cavity-modes
ROM=$BUILD/rom/chain-rom
for b in "$MODES" "$ROM"; do [ -x "$b" ] || { echo "bench/volume_response_table.sh: build first ($b missing)" >&2; exit 1; }; done
source scripts/blas-core.sh
out=bench/results/volume_response_table_$(date +%F)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mesh=(--a 1 --b 1 --c 0.5 --ekman 1e-2 --order 3 --mesh-size 0.3 --wall-size 0.08)
top() {  # table -> a top with A = B carrying it
  printf '[system]\nkind = "fixed"\ngravity = 9.81\n[[body]]\nmass = 2.0\nA = 0.05\nB = 0.05\nC = 0.08\ncom = 0.05\n'
  printf 'spin = 200.0\n[body.cavity]\ntable = "%s"\ndensity = 1000.0\nscale = 0.04\ncenter = 0.05\nviscosity = 3.2e-3\n' "$1"
}
timed() {  # log, command... -> "seconds max_rss_kb"
  local log=$1; shift
  /usr/bin/time -f "%e %M" -o "$work/time.txt" "$@" > "$log" 2>&1
  cat "$work/time.txt"
}
"$MODES" response spheroid --a 1 --c 0.5 --ekman 1e-2 --sigma 0:2.5:11 --max-fit-error 1e-8 -o "$work/ref.h5" > /dev/null 2>&1
top "$work/ref.h5" > "$work/ref.toml"
"$ROM" spectrum "$work/ref.toml" --json > "$work/ref.json"
"$MODES" ellipsoid "${mesh[@]}" --sigma 0.13,0.77,1.31+0.05i,1.9,2.3,3.3 -o "$work/forced.csv" > /dev/null 2>&1
echo "method,max_fit_error,seconds,max_rss_kb,points,vectors,poles,R_error,nutation_frequency_error,nutation_decay_error" > "$out.csv"
measure() {  # method, tolerance, seconds rss, table
  top "$5" > "$work/t.toml"
  "$ROM" spectrum "$work/t.toml" --json > "$work/t.json"
  /usr/bin/python3 - "$@" "$work" <<'PY' | tee -a "$out.csv"
import sys, json, re
import h5py, numpy as np
method, tol, secs, rss, table, work = sys.argv[1:7]
f = h5py.File(table)
lam = f["modes"]["lambda"][:] + 1j * f["modes"]["decay"][:]
H = (f["volume"]["coupling_re"][:] + 1j * f["volume"]["coupling_im"][:]).reshape(-1, 3, 3)
R_of = lambda s: np.array([sum(h / (x - l) + h.conj() / (x + np.conj(l)) for l, h in zip(lam, H)) for x in s])
v = np.genfromtxt(work + "/forced.csv", delimiter=",", names=True, skip_header=2)
ent = ["xx", "xy", "xz", "yx", "yy", "yz", "zx", "zy", "zz"]
R = np.stack([v["R_%s_re" % e] + 1j * v["R_%s_im" % e] for e in ent], axis=1).reshape(-1, 3, 3)
d = np.abs(np.diagonal(R, axis1=1, axis2=2)).max(axis=0)   # each entry against the forced solves' largest values
err = np.max(np.abs(R_of(v["sigma_re"] + 1j * v["sigma_im"]) - R) / np.sqrt(np.outer(d, d)))
g, m = (json.load(open(work + "/" + n)) for n in ("t.json", "ref.json"))
# the nutation: the least damped root near 318 rad/s in space (fluid roots near it decay thousands of times faster)
nut_g = min((complex(*r) - 200 for r in g["roots"] if -150 < r[0] < -100), key=lambda r: abs(r.imag))  # turning -> space
nut_m = min((complex(*r) for r in m["roots"] if -350 < r[0] < -300), key=lambda r: abs(r.imag))
solver = f.attrs["solver"]
solver = solver.decode() if isinstance(solver, bytes) else str(solver)
pts = re.search(r"(\d+) expansion points", solver)
vec = re.search(r"(\d+) primal", solver)
print(f"{method},{tol},{secs},{rss},{pts.group(1) if pts else ''},{vec.group(1) if vec else ''},{len(lam)},{err:.3e},"
      f"{abs(nut_g.real / nut_m.real - 1):.3e},{abs(nut_g.imag / nut_m.imag - 1):.3e}")
PY
}
for tol in 1e-2 1e-3 1e-4 1e-5 1e-6; do
  read -r secs rss < <(timed "$work/log.txt" "$MODES" ellipsoid "${mesh[@]}" --sigma 0:2.5:11 --max-fit-error "$tol" -o "$work/r.h5")
  measure response "$tol" "$secs" "$rss" "$work/r.h5"
done
read -r secs rss < <(timed "$work/log.txt" "$MODES" ellipsoid "${mesh[@]}" --no-convergence-check -o "$work/d.h5")
measure damped_modes "" "$secs" "$rss" "$work/d.h5"

echo "part B: data/scenes/spacecraft_viscous_tank.toml"
scene_on() { sed -e "s#\"../../out/tables/spacecraft_viscous_tank.h5\"#\"$1\"#" data/scenes/spacecraft_viscous_tank.toml > "$work/craft.toml"; }
growth() { "$ROM" spectrum "$work/craft.toml" --json | /usr/bin/python3 -c 'import json, sys; print(json.load(sys.stdin)["growth"])'; }
read -r secs rss < <(timed "$work/log.txt" "$MODES" ellipsoid --a 1 --b 0.8 --c 3 --ekman 1e-3 --order 3 --no-convergence-check -o "$work/cd.h5")
scene_on "$work/cd.h5"
echo "damped-mode table (the recipe's mesh): $secs s, $((rss / 1000)) MB, growth $(growth) 1/s"
read -r secs rss < <(timed "$work/log.txt" "$MODES" ellipsoid --a 1 --b 0.8 --c 3 --ekman 1e-3 --order 3 --sigma 0:2.5:11 -o "$work/cr.h5")
scene_on "$work/cr.h5"
echo "response table (the same mesh, --sigma 0:2.5:11): $secs s, $((rss / 1000)) MB, growth $(growth) 1/s; $(grep -o '[0-9]* expansion points, [0-9]* + [0-9]* basis vectors, [0-9]* poles' "$work/log.txt")"

/usr/bin/python3 - "$out.csv" "$out.png" <<'PY'
import csv, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
rows = list(csv.DictReader(open(sys.argv[1])))
resp = [r for r in rows if r["method"] == "response"]
fig, ax = plt.subplots(figsize=(6.4, 4.4))
ax.loglog([float(r["seconds"]) for r in resp], [float(r["R_error"]) for r in resp], "o-", label="R against forced solves")
ax.loglog([float(r["seconds"]) for r in resp], [float(r["nutation_decay_error"]) for r in resp], "s-",
          label="nutation decay against (26), meridian P6")
for r in resp:
    ax.annotate(f"tol {r['max_fit_error']}", (float(r["seconds"]), float(r["R_error"])), fontsize=7, xytext=(3, 3),
                textcoords="offset points")
d = [r for r in rows if r["method"] == "damped_modes"]
if d:
    ax.loglog([float(d[0]["seconds"])], [float(d[0]["nutation_decay_error"])], "k^", label="damped-mode table: nutation decay")
ax.set_xlabel("table run time (s)")
ax.set_ylabel("relative error")
ax.set_title("3-D response table, spheroid c/a = 0.5, Ek = 1e-2, P3 (25 449 unknowns)", fontsize=9)
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=120)
print("wrote", sys.argv[2])
PY
