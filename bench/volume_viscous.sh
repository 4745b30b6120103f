#!/usr/bin/env bash
# The viscous fluid in 3-D (docs/volume.md §7): the triaxial ellipsoid 1 : 0.8 : 0.6's damped spin-over mode
# (`cavity-modes ellipsoid --ekman`) at Ek = 1e-2 and 1e-3 on several tetrahedral meshes, serial and on two ranks,
# against its boundary-layer limit λ0 + λ1 Ek^{1/2}. λ1 is computed here again, independently of the C++ code: the
# closed-form uniform-vorticity mode's wall velocity in Greenspan's Ekman-layer formula (docs/viscous.md §4), by a
# midpoint rule on the ellipsoid's surface. Writes bench/results/volume_viscous_<date>.csv and .png.
# Usage: bash bench/volume_viscous.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
BIN=$BUILD/modes/cavity-modes
[ -x "$BIN" ] || { echo "bench/volume_viscous.sh: build first ($BIN missing)" >&2; exit 1; }
source scripts/blas-core.sh
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
out=bench/results/volume_viscous_$(date +%F)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "ekman,order,mesh_size,wall_size,ranks,unknowns,seconds,max_rss_kb,lambda,decay" > "$out.csv"
# Ekman number, order, interior size, wall size, ranks
for run in "1e-2 3 0.25 0.08 1" "1e-2 4 0.3 0.06 1" "1e-3 3 0.25 0.05 1" "1e-3 3 0.25 0.035 1" "1e-3 3 0.25 0.025 1" \
           "1e-3 4 0.3 0.06 1" "1e-3 4 0.3 0.045 1" "1e-3 4 0.3 0.06 2"; do
  set -- $run
  launch=()
  [ "$5" != 1 ] && launch=(mpirun -n "$5")
  /usr/bin/time -f "%e %M" -o "$work/time.txt" "${launch[@]}" "$BIN" ellipsoid --a 1 --b 0.8 --c 0.6 --ekman "$1" \
    --order "$2" --mesh-size "$3" --wall-size "$4" > "$work/log.txt" 2>&1
  read -r secs rss < "$work/time.txt"
  unknowns=$(grep -o '[0-9]* unknowns' "$work/log.txt" | head -1 | cut -d' ' -f1)
  read -r _ lam decay _ < <(tail -1 "$work/log.txt")
  echo "$1,$2,$3,$4,$5,$unknowns,$secs,$rss,$lam,$decay" | tee -a "$out.csv"
done
/usr/bin/python3 - "$out.csv" "$out.png" <<'PY'
import csv, sys
import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

a, b, c = 1.0, 0.8, 0.6
# The spin-over mode (docs/volume.md §3): K ω̇ = −2 D [D⁻¹ẑ]× ω, V = D (ω × D⁻¹ r).
D, Di = np.diag([a, b, c]), np.diag([1 / a, 1 / b, 1 / c])
K = np.diag([(b*b + c*c) / (b*c), (a*a + c*c) / (a*c), (a*a + b*b) / (a*b)])
cross = lambda u: np.array([[0, -u[2], u[1]], [u[2], 0, -u[0]], [-u[1], u[0], 0]])
mu, W = np.linalg.eig(-2 * np.linalg.inv(K) @ D @ cross(Di @ np.array([0, 0, 1.0])))
k = int(np.argmax(mu.imag))
lam0, L = mu[k].imag, D @ cross(W[:, k]) @ Di
norm2 = np.trace(L.conj().T @ L @ ((4 * np.pi * a * b * c / 15) * D @ D)).real
# λ1 = (i/‖V‖²) ∮ ½ (q+ |U+|² + q− |U−|²) dS, q± = (i(λ0 ± 2 ẑ·n))^{1/2}, n inward, U± = U·e1 ± i U·e2, e1 × e2 = n.
def limit(n):
    t = (np.arange(n) + 0.5) * np.pi / n
    f = (np.arange(2 * n) + 0.5) * np.pi / n
    T, F = np.meshgrid(t, f, indexing="ij")
    X = np.stack([a * np.sin(T) * np.cos(F), b * np.sin(T) * np.sin(F), c * np.cos(T)], -1)
    N = np.stack([b * c * np.sin(T)**2 * np.cos(F), a * c * np.sin(T)**2 * np.sin(F), a * b * np.sin(T) * np.cos(T)], -1)
    dS = np.linalg.norm(N, axis=-1) * (np.pi / n)**2
    n_in = -N / np.linalg.norm(N, axis=-1)[..., None]
    e1 = np.cross(n_in, [0.3, 0.5, 0.7]); e1 /= np.linalg.norm(e1, axis=-1)[..., None]
    e2 = np.cross(n_in, e1)
    U = X @ L.T
    u1, u2 = (U * e1).sum(-1), (U * e2).sum(-1)
    cz = n_in[..., 2]
    qp, qm = np.sqrt(1j * (lam0 + 2 * cz)), np.sqrt(1j * (lam0 - 2 * cz))
    return 1j * (0.5 * (qp * abs(u1 + 1j * u2)**2 + qm * abs(u1 - 1j * u2)**2) * dS).sum() / norm2
l1, l2 = limit(1000), limit(2000)
print(f"lambda0 = {lam0:.9f}; boundary-layer limit lambda1 = {l2.real:.6f}{l2.imag:+.6f}i "
      f"(midpoint rule, 2000 x 4000 points; {abs(l1 - l2) / abs(l2):.1e} from 1000 x 2000)")
rows = list(csv.DictReader(open(sys.argv[1])))
fig, ax = plt.subplots(figsize=(6.4, 4.4))
for ek, mark in (("1e-2", "o"), ("1e-3", "s")):
    sel = [r for r in rows if r["ekman"] == ek]
    e = float(ek)
    coef = [float(r["decay"]) / e**0.5 for r in sel]
    ax.semilogx([float(r["seconds"]) for r in sel], coef, mark, label=f"Ek = {ek}: decay / Ek^1/2")
    for r, y in zip(sel, coef):
        ax.annotate(f"P{r['order']} w{r['wall_size']}" + (f" ×{r['ranks']}" if r["ranks"] != "1" else ""),
                    (float(r["seconds"]), y), fontsize=7, xytext=(3, 3), textcoords="offset points")
    for r in sel:
        print(f"Ek {ek} P{r['order']} w{r['wall_size']} ranks {r['ranks']}: (lambda - lambda0)/Ek^1/2 = "
              f"{(float(r['lambda']) - lam0) / e**0.5:.5f}{float(r['decay']) / e**0.5:+.5f}i, "
              f"{r['seconds']} s, {float(r['max_rss_kb']) / 1e6:.2f} GB")
ax.axhline(l2.imag, color="k", lw=0.8, label=f"boundary-layer limit Im λ1 = {l2.imag:.4f}")
ax.set_xlabel("run time of cavity-modes ellipsoid --ekman (s, 2-core machine)")
ax.set_ylabel("decay rate / Ek^1/2")
ax.set_title("3-D triaxial ellipsoid 1 : 0.8 : 0.6, damped spin-over mode")
ax.grid(True, which="both", alpha=0.3)
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=120)
PY
