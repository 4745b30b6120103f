#!/usr/bin/env bash
# cavity-modes --ekman on the command line: bad input gives one line, a non-zero exit and no file; a small good
# run writes a viscous table that info --json shows; chain-rom reads it with the fluid's viscosity (and refuses it
# with one line without one, or with one whose Ekman number is not the table's).
set -u
source "$(cd "$(dirname "$0")" && pwd)/cli_checks.sh"
BIN=$1
ROM=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
small=(--order 3 --mesh-size 0.5 --no-convergence-check)

expect_error "zero Ekman number" "outside" "$BIN" sphere --radius 1 --ekman 0 -o out.h5
expect_error "negative Ekman number" "outside" "$BIN" sphere --radius 1 --ekman -1e-3 -o out.h5
expect_error "NaN Ekman number" "outside" "$BIN" sphere --radius 1 --ekman nan -o out.h5
expect_error "Ekman number too small for this machine" "outside" "$BIN" cylinder --radius 1 --height 2 --ekman 1e-9 -o out.h5
expect_error "wall mesh too coarse for the Ekman layer" "does not resolve the Ekman layer" "$BIN" sphere --radius 1 --ekman 1e-4 --wall-size 0.1 -o out.h5
expect_error "wall size without --ekman" "applies with --ekman only" "$BIN" sphere --radius 1 --wall-size 0.01 -o out.h5
expect_error "--fields with --ekman" "not available with --ekman" "$BIN" sphere --radius 1 --ekman 1e-2 --fields -o out.h5
expect_error "order 1 with --ekman" "order >= 2" "$BIN" sphere --radius 1 --ekman 1e-2 --order 1 -o out.h5
expect_error "viscous solver failure" "did not converge" "$BIN" sphere --radius 1 --ekman 1e-2 "${small[@]}" -o out.h5 \
  -viscous_eps_max_it 1 -viscous_eps_tol 1e-30

if "$BIN" sphere --radius 1 --ekman 1e-2 --modes 1 "${small[@]}" -o visc.h5 > run.txt 2>&1 &&
   "$BIN" info visc.h5 --json > visc.json && python3 -c '
import json
j = json.load(open("visc.json"))
m = j["modes"]
assert j["ekman"] == 1e-2, j["ekman"]
assert len(m["decay"]) == len(m["E"]) == len(m["E_imag"]) == 1
assert 0 < m["decay"][0] < 1 and abs(m["lambda"][0] - 1) < 0.05, (m["lambda"], m["decay"])
print("Ek = 1e-2 sphere: lambda %.6f decay %.6f E %.6f%+.6fi" % (m["lambda"][0], m["decay"][0], m["E"][0], m["E_imag"][0]))
'; then ok "viscous sphere table and info --json"; else bad "viscous table: $(tail -2 run.txt)"; fi

# Two ideal cone targets (unconverged ideal clusters) lead to one damped mode: kept once, and said so.
if "$BIN" cone --radius 1 --height 1 --modes 4 --ekman 1e-3 --order 4 --mesh-size 0.25 --no-convergence-check \
     -o cone.h5 > cone.txt 2> cone.err && grep -q "kept once" cone.err && "$BIN" info cone.h5 --json > cone.json &&
   python3 -c '
import json
m = json.load(open("cone.json"))["modes"]
pairs = sorted(zip(m["lambda"], m["decay"]))
assert all(abs(a[0] - b[0]) + abs(a[1] - b[1]) > 1e-6 for a, b in zip(pairs, pairs[1:])), pairs
print("cone Ek = 1e-3: %d distinct damped modes from 4 ideal targets" % len(pairs))
'; then ok "a damped mode reached from two targets is kept once"; else bad "cone repeat: $(tail -2 cone.err)"; fi

# cavity-modes response: R(sigma) by forced solves, CSV.
expect_error "response without --ekman" "needs --ekman" "$BIN" response sphere --radius 1 --sigma 0.5:1.5:3 -o out.h5
expect_error "response without --sigma" "needs --sigma" "$BIN" response sphere --radius 1 --ekman 1e-2 -o out.h5
expect_error "--sigma on a table command" "belong to 'cavity-modes response" "$BIN" sphere --radius 1 --ekman 1e-2 --sigma 0:1:3 -o out.h5
expect_error "malformed --sigma" "is not FROM:TO:N" "$BIN" response sphere --radius 1 --ekman 1e-2 --sigma 1:0.5:3 -o out.h5
if "$BIN" response sphere --radius 1 --ekman 1e-2 "${small[@]}" --sigma 0.5:1.5:11 --sigma-imag 0.2 -o resp.csv > resp.txt 2>&1 &&
   [ ! -e resp.csv.tmp* ] && python3 -c '
import csv, math
rows = [r for r in csv.reader(l for l in open("resp.csv") if not l.startswith("#"))]
assert rows[0] == ["sigma_re", "sigma_im", "R_re", "R_im"], rows[0]
vals = [[float(x) for x in r] for r in rows[1:]]
assert len(vals) == 11 and all(math.isfinite(x) for r in vals for x in r)
peak = max(vals, key=lambda r: math.hypot(r[2], r[3]))
print("response: |R| peaks at sigma = %.2f%+.2fi (the damped spin-over mode is near 1)" % (peak[0], peak[1]))
assert abs(peak[0] - 1) <= 0.15
'; then ok "response CSV"; else bad "response: $(tail -2 resp.txt)"; fi

# Distributed: the same table with mpirun -n 1 and -n 2 (PETSc's distributed matrices, parallel MUMPS). At the
# default eigensolver tolerance (1e-10) two runs, serial or not, agree to about 2e-10; on the coarse P3 mesh
# above, whose null pivots MUMPS must detect, a run under full load differed by 2e-10 even at tolerance 1e-13.
# So: a P4 mesh, tolerance 1e-13, one OpenMP thread (MUMPS's own threads round differently under load).
if command -v mpirun > /dev/null; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1 OMP_NUM_THREADS=1
  tight=(--order 4 --mesh-size 0.25 --no-convergence-check -viscous_eps_tol 1e-13)
  if mpirun -n 1 "$BIN" sphere --radius 1 --ekman 1e-3 --modes 1 "${tight[@]}" -o mpi1.h5 > mpi1.txt 2>&1 &&
     mpirun -n 2 "$BIN" sphere --radius 1 --ekman 1e-3 --modes 1 "${tight[@]}" -o mpi2.h5 > mpi2.txt 2>&1 &&
     [ ! -e mpi2.h5.tmp* ] && /usr/bin/python3 -c '
import h5py
a, b = h5py.File("mpi1.h5")["modes"], h5py.File("mpi2.h5")["modes"]
for name, re, im in (("lambda + i decay", "lambda", "decay"), ("E + i E_imag", "E", "E_imag")):
    x, y = complex(a[re][0], a[im][0]), complex(b[re][0], b[im][0])
    d = abs(x - y) / abs(x)
    print("%s: -n 1 %.15g%+.15gi, -n 2 %.15g%+.15gi, relative difference %.1e" % (name, x.real, x.imag, y.real, y.imag, d))
    assert d < 1e-10, name
'; then ok "mpirun -n 1 and -n 2 give the same table"; else bad "mpirun: $(tail -3 mpi2.txt)"; fi
else
  ok "mpirun not installed: distributed check skipped"
fi

# chain-rom with the viscous table (docs/rom.md, "Viscous tanks"): Ek = nu/(spin scale^2) must be the table's.
scene() {  # the cavity's extra lines
  cat > scene.toml <<SCENE
[system]
kind = "fixed"
gravity = 9.81
[[body]]
mass = 2.0
A = 0.05
C = 0.08
com = 0.05
spin = 200.0
[body.cavity]
table = "visc.h5"
density = 1000.0
scale = 0.04
center = 0.05
$1
[initial]
tilt = [[0.01, 0.0]]
[run]
t_end = 0.2
output_step = 0.001
SCENE
}
scene ""
expect_error "chain-rom: a viscous table needs the viscosity" "give the fluid's viscosity" "$ROM" spectrum scene.toml
scene "viscosity = 3.0e-3"   # Ek = 3e-3/(200 * 0.04^2) = 9.4e-3, the table's is 1e-2
expect_error "chain-rom: viscosity inconsistent with the table's Ek" "must agree" "$ROM" spectrum scene.toml
scene "viscosity = -3.2e-3"
expect_error "chain-rom: negative viscosity" "must be > 0" "$ROM" spectrum scene.toml
scene "viscosity = 0"
expect_error "chain-rom: zero viscosity" "must be > 0" "$ROM" spectrum scene.toml
"$BIN" sphere --radius 1 "${small[@]}" -o ideal.h5 > /dev/null 2>&1
sed -i 's/visc.h5/ideal.h5/' scene.toml && sed -i 's/^viscosity = 0$/viscosity = 3.2e-3/' scene.toml
expect_error "chain-rom: viscosity with an ideal table" "ideal-fluid table" "$ROM" spectrum scene.toml
scene "viscosity = 3.2e-3"   # Ek = 1e-2
if "$ROM" spectrum scene.toml --json > spec.json && "$ROM" run scene.toml -o out.h5 > run.txt && python3 -c '
import json
j = json.load(open("spec.json"))
assert j["stable"] and j["growth"] < 0 and j["root_agreement"] < 1e-8 and j["newton_failed"] == 0, j
print("viscous top: slowest decay %.4f 1/s, Newton on det Phi agrees to %.1e" % (-j["growth"], j["root_agreement"]))
' && grep -q "not computed with viscous tanks" run.txt && [ -s out.h5 ]; then
  ok "chain-rom spectrum and run with the viscous table"
else
  bad "chain-rom with the viscous table: $(cat spec.json run.txt 2>/dev/null | tail -3)"
fi
finish
