#!/usr/bin/env bash
# Kore (the spectral SLEPc code for spheres and shells, github.com/repepo/kore) against cavity-modes on Kore's own test
# case, side by side on this machine: the spin-over mode of the spherical shell (inner radius 0.35, both walls
# no-slip; Kore's tests/spinover) and of the full sphere. Kore: its run (submatrices, assemble, solve with its test's
# solver options) on 1 and 2 ranks and with 1.5 times its truncations, timed. Ours: `cavity-modes shell` (the spectral
# method, docs/spherical.md) as a user runs it, without its check and at other truncations, and the finite elements
# (data/sections/shell.geo or the sphere, --ekman) with the survey, --target 1.0 and finer meshes, timed.
#   KORE_DIR=/path/to/kore bash bench/kore_peer.sh [BUILD_DIR] [OUT]
# SHAPES="shell sphere" (default shell) and EKMANS (default "1e-3 1e-4") choose the cases; SHELL_SIZES /
# SPHERE_SIZES our mesh ladder beyond the default mesh; FE=0 leaves the finite elements out; RANKS=2 runs Kore's
# fine run and ours under mpirun -n 2. Every error is against one reference per case: Kore's published eigenvalue
# (its tests/spinover/reference.eig, the shell at 1e-3), else Kore's run at 1.5 times its truncations, else (no Kore)
# ours at 1.5 times our default truncation — the CSV's reference column names it. Writes
# OUT/kore_peer_<shapes>_<date>.csv and a PNG of error against run time for both codes (bench/plot_kore_peer.py).
# On the sphere at Ek <= 1e-5 our meshes follow the internal shear layers unless the row says "uniform interior".
# Kore is optional: without KORE_DIR (a checkout of github.com/repepo/kore) or without its Debian needs
# (python3-petsc4py-complex python3-slepc4py-complex python3-mpi4py) the script says so and runs ours alone.
set -euo pipefail
if [ "${1:-}" = "--help" ] || [ "${1:-}" = "-h" ]; then
  sed -n '2,17p' "$0" | sed 's/^# \{0,1\}//'
  exit 0
fi
ROOT=$(cd "$(dirname "$0")/.." && pwd)
source "$ROOT/scripts/blas-core.sh"
BUILD=${1:-$ROOT/build}
OUT=${2:-$ROOT/bench/results}
MODES=$BUILD/modes/cavity-modes
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$OUT"
# Named by the shapes and the date; a second run the same day gets -2, -3, ... rather than overwrite the first.
stem=$OUT/kore_peer_$(echo "${SHAPES:-shell}" | tr ' ' '_')_$(date +%F)
csv=$stem.csv
for k in 2 3 4 5 6 7 8 9; do [ -e "$csv" ] || break; csv=$stem-$k.csv; done
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1
echo "ekman,code,setting,seconds,frequency,decay" > "$work/raw.csv"
now() { date +%s.%N; }
since() { python3 -c "import sys; print('%.2f' % (float(sys.argv[2]) - float(sys.argv[1])))" "$1" "$(now)"; }
row() {  # ekman code setting seconds frequency decay: a raw row (the errors are computed at the end)
  echo "$1,$2,$3,$4,$5,$6" >> "$work/raw.csv"
}
ranks=${RANKS:-1}
parallel=()
[ "$ranks" = 1 ] || parallel=(mpirun -n "$ranks")

# Kore, when present: Debian's complex PETSc/SLEPc builds are chosen by PETSC_DIR and SLEPC_DIR (README.Debian of
# python3-petsc4py-complex), and Kore's scripts run with Debian's Python (numpy, scipy).
PY=/usr/bin/python3
export PETSC_DIR=${PETSC_DIR:-$(ls -d /usr/lib/petscdir/petsc3*/x86_64-linux-gnu-complex 2> /dev/null | head -1)}
export SLEPC_DIR=${SLEPC_DIR:-$(ls -d /usr/lib/slepcdir/slepc3*/x86_64-linux-gnu-complex 2> /dev/null | head -1)}
have_kore=0
if [ -n "${KORE_DIR:-}" ] && [ -f "$KORE_DIR/bin/solve.py" ] &&
   "$PY" -c "import petsc4py, slepc4py, mpi4py, scipy; from petsc4py import PETSc; assert PETSc.ScalarType().dtype.kind == 'c'" 2> /dev/null; then
  have_kore=1
else
  echo "Kore not run: set KORE_DIR to a checkout of github.com/repepo/kore and install python3-petsc4py-complex" \
       "python3-slepc4py-complex python3-mpi4py python3-petsc4py python3-slepc4py (its reference eigenvalue at" \
       "Ek = 1e-3 is used alone)" >&2
fi
kore() {  # ekman ranks [fine: 1.5 times Kore's radial and angular truncations, to measure its own error]
  local ek=$1 n=$2 fine=${3:-} dir=$work/kore
  rm -rf "$dir" && mkdir -p "$dir" && cp -r "$KORE_DIR/bin" "$dir/bin"
  local truncation="s/^N = Ncheb(Ek)/N = Ncheb(Ek)/"
  [ -z "$fine" ] || truncation="s/^N = Ncheb(Ek)/N = Ncheb(Ek) * 3 \/\/ 4 * 2/"
  sed -e "s/^Ek = .*/Ek = $ek/" -e "s/^ricb = .*/ricb = $RICB/" -e "$truncation" \
    "$KORE_DIR/tests/spinover/params.spinover" > "$dir/bin/parameters.py"
  local t0 t
  t0=$(now)
  (cd "$dir" && "$PY" ./bin/submatrices.py "$n" > sub.log 2>&1 && mpiexec -n "$n" "$PY" ./bin/assemble.py > asm.log 2>&1 &&
    mpiexec -n "$n" "$PY" ./bin/solve.py -st_type sinvert > solve.log 2>&1) ||
    { echo "Kore failed (Ek $ek, n = $n): $(tail -2 "$dir/solve.log" 2> /dev/null)" >&2; return; }
  t=$(since "$t0")
  read -r decay freq < <("$PY" -c "import numpy as np; d = np.atleast_2d(np.loadtxt('$dir/eigenvalues0.dat'))
i = np.argmax(d[:, 0]); print('%.17g %.17g' % (-d[i, 0], d[i, 1]))")
  local N
  N=$(grep -o "N = [0-9]*" "$dir/sub.log" | head -1 | tr -d ' ')
  row "$ek" kore "$SHAPE;spectral ${N:-};np=$n${fine:+;1.5 x truncation}" "$t" "$freq" "$decay"
}
ours() {  # ekman setting, then cavity-modes arguments: the finite elements
  local ek=$1 setting=$2
  shift 2
  local t0 t
  t0=$(now)
  env -u PETSC_DIR -u SLEPC_DIR "$MODES" "${CAVITY[@]}" --ekman "$ek" --no-convergence-check \
    "$@" -o "$work/ours.h5" > "$work/ours.txt" 2>&1 || { tail -2 "$work/ours.txt" >&2; return; }
  t=$(since "$t0")
  read -r freq decay ndof < <(/usr/bin/python3 -c "import h5py, numpy as np
f = h5py.File('$work/ours.h5'); m = f['modes']; i = int(np.argmin(np.abs(m['lambda'][:] - 1)))
print(repr(m['lambda'][i]), repr(m['decay'][i]), f.attrs['ndof'])")
  row "$ek" cavity-modes "$SHAPE;$setting;$ndof unknowns" "$t" "$freq" "$decay"
}
spectral() {  # ekman setting ranks, then `cavity-modes shell` arguments: our spectral method (docs/spherical.md)
  local ek=$1 setting=$2 n=$3
  shift 3
  local t0 t run=()
  [ "$n" = 1 ] || run=(mpirun -n "$n")
  t0=$(now)
  env -u PETSC_DIR -u SLEPC_DIR "${run[@]}" "$MODES" shell --inner-radius "$RICB" --ekman "$ek" "$@" \
    -o "$work/shell.csv" > "$work/shell.txt" 2>&1 || { tail -2 "$work/shell.txt" >&2; return; }
  t=$(since "$t0")
  read -r freq decay < <(/usr/bin/python3 -c "import csv
r = next(csv.DictReader(l for l in open('$work/shell.csv') if not l.startswith('#'))); print(r['lambda'], r['decay'])")
  local size
  size=$(grep -o "[0-9]* unknowns" "$work/shell.txt" | head -1)
  row "$ek" cavity-modes "$SHAPE;spectral $setting;np=$n;$size" "$t" "$freq" "$decay"
}
for SHAPE in ${SHAPES:-shell}; do
  if [ "$SHAPE" = shell ]; then
    RICB=0.35 CAVITY=(section "$ROOT/data/sections/shell.geo") SIZES=${SHELL_SIZES:-0.1 0.08}
  else
    RICB=0 CAVITY=(sphere --radius 1) SIZES=${SPHERE_SIZES:-0.125 0.0625}
  fi
  for ek in ${EKMANS:-1e-3 1e-4}; do
    if [ "$have_kore" = 1 ]; then kore "$ek" 1; kore "$ek" 2; kore "$ek" "$ranks" fine; fi
    spectral "$ek" "default with its check" 1
    spectral "$ek" "default" 1 --no-convergence-check
    for r in 0.8 1.5; do spectral "$ek" "resolution $r" 1 --no-convergence-check --resolution "$r"; done
    [ "$ranks" = 1 ] || spectral "$ek" "default" "$ranks" --no-convergence-check
    [ "${FE:-1}" != 0 ] || continue
    ours "$ek" "P6 default mesh;ideal survey" --modes 1
    ours "$ek" "P6 default mesh;--target 1.0" --target 1.0
    # The sphere at Ek <= 1e-5: the default mesh follows the internal shear layers (docs/viscous.md); the uniform
    # interior for comparison.
    [ "$SHAPE" != sphere ] || ours "$ek" "P6 default mesh uniform interior;--target 1.0" --target 1.0 --no-shear-layers
    for h in $SIZES; do ours "$ek" "P6 h $h;--target 1.0" --target 1.0 --mesh-size "$h"; done
    # The near-wall zone (docs/viscous.md, "Near-wall zone"): elements of Ek^(1/3) just outside the wall layers.
    # NEAR_WALL=0 leaves it out (at Ek = 1e-7 its mesh would not fit in this machine's memory).
    near=$(python3 -c "print('%.3g' % ($ek ** (1 / 3)))")
    [ "${NEAR_WALL:-1}" = 0 ] || ours "$ek" "P6 default mesh + near-wall $near;--target 1.0" --target 1.0 --near-wall-size "$near"
  done
done
# The errors, each case against one reference: Kore's published eigenvalue for its test (the shell at 1e-3, its
# tests/spinover/reference.eig), else Kore's 1.5-times run, else ours at 1.5 times our truncation.
/usr/bin/python3 - "$work/raw.csv" "$csv.tmp" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
published = {("shell", "1e-3"): (1.005733690103750355, 0.1019947097016500742)}
def reference(shape, ek):
    if (shape, ek) in published:
        return published[(shape, ek)], "Kore's tests/spinover/reference.eig"
    for code, mark, name in (("kore", "1.5 x truncation", "Kore at 1.5 x its truncation"),
                             ("cavity-modes", "spectral resolution 1.5", "cavity-modes shell --resolution 1.5")):
        for r in rows:
            if r["code"] == code and r["ekman"] == ek and r["setting"].split(";")[0] == shape and mark in r["setting"]:
                return (float(r["frequency"]), float(r["decay"])), name
    return None, ""
with open(sys.argv[2], "w") as out:
    out.write("ekman,code,setting,seconds,frequency,decay,frequency_error,decay_error,reference\n")
    for r in rows:
        ref, name = reference(r["setting"].split(";")[0], r["ekman"])
        f, d = float(r["frequency"]), float(r["decay"])
        err = lambda x, y: "%.2e" % (abs(x - y) / abs(y)) if ref else ""
        out.write("%s,%s,%s,%s,%.16g,%.16g,%s,%s,%s\n" % (r["ekman"], r["code"], r["setting"], r["seconds"], f, d,
                  err(f, ref[0]) if ref else "", err(d, ref[1]) if ref else "", name))
PY
mv "$csv.tmp" "$csv"
column -s, -t < "$csv"
/usr/bin/python3 "$ROOT/bench/plot_kore_peer.py" "$csv" "${csv%.csv}.png" || echo "no plot (matplotlib?)" >&2
