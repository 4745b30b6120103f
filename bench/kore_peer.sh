#!/usr/bin/env bash
# Kore (the spectral SLEPc code for spheres and shells, github.com/repepo/kore) against cavity-modes on Kore's own test
# case, side by side on this machine: the spin-over mode of the spherical shell (inner radius 0.35, both walls
# no-slip, Ek = 1e-3; Kore's tests/spinover). Kore: its reference eigenvalue, its run (submatrices, assemble, solve
# with its test's solver options) timed. Ours: data/sections/shell.geo with --ekman 1e-3, with the ideal survey
# (the default) and with --target 1.0 (no survey), timed; each against Kore's reference. Writes
# OUT/kore_peer_<shapes>_<date>.csv and prints it.
#   KORE_DIR=/path/to/kore bash bench/kore_peer.sh [BUILD_DIR] [OUT]
# SHAPES="shell sphere" (default shell: Kore's test; sphere: its full-sphere case, ricb = 0) and EKMANS (default
# "1e-3 1e-4") choose the cases; SHELL_SIZES / SPHERE_SIZES our mesh ladder beyond the default mesh. The errors are
# against Kore's reference eigenvalue (the shell at 1e-3) or Kore's own one-rank run; OUT/kore_peer_<shapes>_<date>.png plots
# error against run time for both codes (bench/plot_kore_peer.py). On the sphere at Ek <= 1e-5 our meshes follow the
# internal shear layers unless the row says "uniform interior" (--no-shear-layers).
# Kore is optional: without KORE_DIR (a checkout of github.com/repepo/kore) or without its Debian needs
# (python3-petsc4py-complex python3-slepc4py-complex python3-mpi4py) the script says so and runs ours alone.
set -euo pipefail
if [ "${1:-}" = "--help" ] || [ "${1:-}" = "-h" ]; then
  sed -n '2,14p' "$0" | sed 's/^# \{0,1\}//'
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
echo "ekman,code,setting,seconds,frequency,decay,frequency_error,decay_error" > "$csv.tmp"
now() { date +%s.%N; }
since() { python3 -c "import sys; print('%.2f' % (float(sys.argv[2]) - float(sys.argv[1])))" "$1" "$(now)"; }
# Kore's reference: its tests/spinover/reference.eig at Ek = 1e-3 (-decay, frequency); at other Ek its own run with
# one rank (the spectral solution, converged far below our errors) when it runs, else none.
declare -A REF_F REF_D
REF_F[1e-3]=1.005733690103750355
REF_D[1e-3]=0.1019947097016500742
row() {  # ekman code setting seconds frequency decay
  python3 -c "import sys; e, c, s, t, f, d, rf, rd = sys.argv[1:]; f, d = float(f), float(d)
err = lambda x, r: '%.2e' % (abs(x - float(r)) / float(r)) if r else ''
print('%s,%s,%s,%s,%.16g,%.16g,%s,%s' % (e, c, s, t, f, d, err(f, rf), err(d, rd)))" "$@" "${REF_F[$1]:-}" "${REF_D[$1]:-}"
}

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
  [ -n "${REF_F[$ek]:-}" ] || { REF_F[$ek]=$freq; REF_D[$ek]=$decay; }
  local N
  N=$(grep -o "N = [0-9]*" "$dir/sub.log" | head -1 | tr -d ' ')
  row "$ek" kore "$SHAPE;spectral ${N:-};np=$n${fine:+;1.5 x truncation}" "$t" "$freq" "$decay" >> "$csv.tmp"
}
ours() {  # ekman setting, then cavity-modes arguments
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
  row "$ek" cavity-modes "$SHAPE;$setting;$ndof unknowns" "$t" "$freq" "$decay" >> "$csv.tmp"
}
for SHAPE in ${SHAPES:-shell}; do
  if [ "$SHAPE" = shell ]; then
    RICB=0.35 CAVITY=(section "$ROOT/data/sections/shell.geo") SIZES=${SHELL_SIZES:-0.1 0.08}
  else
    RICB=0 CAVITY=(sphere --radius 1) SIZES=${SPHERE_SIZES:-0.125 0.0625}
  fi
  for ek in ${EKMANS:-1e-3 1e-4}; do
    unset "REF_F[$ek]" "REF_D[$ek]"
    [ "$SHAPE:$ek" != shell:1e-3 ] || { REF_F[1e-3]=1.005733690103750355; REF_D[1e-3]=0.1019947097016500742; }
    if [ "$have_kore" = 1 ]; then kore "$ek" 1; kore "$ek" 2; kore "$ek" 2 fine; fi
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
mv "$csv.tmp" "$csv"
column -s, -t < "$csv"
/usr/bin/python3 "$ROOT/bench/plot_kore_peer.py" "$csv" "${csv%.csv}.png" || echo "no plot (matplotlib?)" >&2
