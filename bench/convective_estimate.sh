#!/usr/bin/env bash
# How large Kononov's convective term (u·∇)u of (6), which the chain's modal liquid leaves out (docs/physics.md,
# "The convective term"), gets in a nonlinear run: the default ideal scene (data/scenes/default_ideal.toml, its three
# tanks without the static correction, whose rest carries no flow) released at tilts THETA, run by the nonlinear
# chain for 2 s. Per tank the relative flow's r.m.s. speed from the modal coordinates, rho ∫|u|² = Σ_l (E_l/2) |ζ_l|²
# (ζ = S' e^{iω0 t} N²/a, E = 2a²/N²: docs/rom.md, "Nonlinear chain"), against the Coriolis term's scale ω0 L (L the
# tank's `scale`): ε = u_rms/(ω0 L), the convective term's size against the terms kept. Writes
# OUT/convective_estimate.csv (tilt, then ε's largest value in time per tank); a few seconds after the tables.
#   bash bench/convective_estimate.sh [BUILD_DIR] [OUT] [THETA...]
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=$(cd "${1:-$ROOT/build}" && pwd)
mkdir -p "${2:-$ROOT/bench/results}"
OUT=$(cd "${2:-$ROOT/bench/results}" && pwd)
shift $(( $# > 2 ? 2 : $# )) || true
TILTS=("$@")
[ ${#TILTS[@]} -gt 0 ] || TILTS=(0.003 0.02 0.1 0.3)
MODES=$BUILD/modes/cavity-modes
ROM=$BUILD/rom/chain-rom
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
scene=$ROOT/data/scenes/default_ideal.toml
sed -n 's/^# recipe: //p' "$scene" | while IFS=: read -r name args; do
  read -r -a a <<< "$args"
  "$MODES" "${a[@]}" -o "$name" > /dev/null 2>&1
done
base() {  # the scene with its tables here, no static correction, tilt $1, no [run]
  sed "s#../../out/tables/##; s/^static_correction = true.*/static_correction = false/;
       s/^tilt = .*/tilt = [[$1, 0.0], [$1, 0.0], [$1, 0.0]]/; /^\[run\]/,\$d" "$scene"
}
{ base 0.01; printf '[run]\nt_end = 2.0\noutput_step = 0.001\nmethod = "exact"\n'; } > linear.toml
"$ROM" run linear.toml -o linear.h5 > /dev/null  # the kept modes' E and bodies (the nonlinear history has ζ only)
for th in "${TILTS[@]}"; do
  { base "$th"; printf '[run]\nt_end = 2.0\noutput_step = 0.001\nmodel = "nonlinear"\ntolerance = 1e-10\n'; } > "n$th.toml"
  "$ROM" run "n$th.toml" -o "n$th.h5" > /dev/null
done
/usr/bin/python3 - "$scene" "$OUT/convective_estimate.csv" "${TILTS[@]}" <<'PY'
import sys, tomllib, h5py, numpy as np
scene, csv, tilts = sys.argv[1], sys.argv[2], sys.argv[3:]
bodies = tomllib.load(open(scene, "rb"))["body"]
f = h5py.File("linear.h5", "r")
E, owner = f["mode_E"][:], f["mode_body"][:].astype(int)
rows = ["tilt," + ",".join("eps_tank%d" % (k + 1) for k in range(len(bodies)))]
for th in tilts:
    g = h5py.File("n%s.h5" % th, "r")
    z = g["zeta_re"][:] + 1j * g["zeta_im"][:]
    assert z.shape[1] == len(E), "the nonlinear run keeps other modes than the linear one"
    eps = []
    for k, b in enumerate(bodies):
        c = b["cavity"]
        volume = h5py.File(c["table"].split("/")[-1], "r").attrs["volume"] * c["scale"] ** 3
        sel = owner == k + 1
        rho_u2 = (np.abs(z[:, sel]) ** 2 * E[sel] / 2).sum(axis=1)
        eps.append((np.sqrt(rho_u2 / (c["density"] * volume)) / (b["spin"] * c["scale"])).max())
    rows.append(th + "," + ",".join("%.4e" % e for e in eps))
open(csv, "w").write("\n".join(rows) + "\n")
print("\n".join(rows))
PY
