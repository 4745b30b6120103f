#!/usr/bin/env bash
# cavity-modes shell (docs/spherical.md) on the command line: Kore's test shell at Ek = 1e-3 to Kore's reference
# eigenvalue, written as a CSV; the same under mpirun -n 2; the convergence verdict said plainly; bad input gives one
# line, a non-zero exit and no file.
set -u
source "$(cd "$(dirname "$0")" && pwd)/cli_checks.sh"
BIN=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

no_csv() {  # name, then expect_error's arguments: also no out.csv left behind
  local name=$1
  expect_error "$@"
  if [ -e out.csv ] || ls out.csv.tmp* > /dev/null 2>&1; then bad "$name: left out.csv behind"; rm -f out.csv*; fi
}
no_csv "zero Ekman number" "--ekman must be a positive number" "$BIN" shell --ekman 0 -o out.csv
no_csv "NaN Ekman number" "--ekman must be a positive number" "$BIN" shell --ekman nan -o out.csv
no_csv "inner radius 1" "--inner-radius must be in" "$BIN" shell --ekman 1e-3 --inner-radius 1 -o out.csv
no_csv "unknown symmetry" "--symmetry must be antisymmetric or symmetric" "$BIN" shell --ekman 1e-3 --symmetry odd -o out.csv
no_csv "no modes" "--modes must be in 1..50" "$BIN" shell --ekman 1e-3 --modes 0 -o out.csv
no_csv "resolution out of range" "--resolution must be in" "$BIN" shell --ekman 1e-3 --resolution 100 -o out.csv
no_csv "too few Chebyshev coefficients" "at least 8 Chebyshev coefficients" "$BIN" shell --ekman 1e-3 --radial 4 -o out.csv
no_csv "truncation beyond memory" "beyond 60 % of this machine" "$BIN" shell --ekman 1e-10 -o out.csv
no_csv "missing output folder" "does not exist" "$BIN" shell --ekman 1e-3 -o nowhere/out.csv
no_csv "response of a shell" "shell: damped modes only" "$BIN" response shell --ekman 1e-3 -o out.csv
no_csv "solver failure" "did not converge" "$BIN" shell --ekman 1e-3 -o out.csv -viscous_eps_max_it 1 -viscous_eps_tol 1e-30
no_h5() {  # name, then expect_error's arguments: also no out.h5 left behind
  local name=$1
  expect_error "$@"
  if [ -e out.h5 ] || ls out.h5.tmp* > /dev/null 2>&1; then bad "$name: left out.h5 behind"; rm -f out.h5*; fi
}
no_h5 "response of another m" "the tilt forces only the m = 1" "$BIN" shell --ekman 1e-3 --m 2 --sigma 0.5 -o out.h5
no_h5 "too short a window" "at least 9 frequencies" "$BIN" shell --ekman 1e-3 --sigma 0:1:5 -o out.h5
no_h5 "complex window" "needs real frequencies" "$BIN" shell --ekman 1e-3 --sigma 0:1:11 --sigma-imag 0.1 -o out.h5
no_h5 "malformed frequency" "sigma" "$BIN" shell --ekman 1e-3 --sigma 0.5+xi -o out.h5
no_h5 "mesh level out of range" "--mesh-level must be in 0..4" "$BIN" shell --ekman 1e-3 --mesh-level 9 --sigma 0.5 -o out.h5
no_h5 "unreachable fit" "errs by" "$BIN" shell --ekman 1e-3 --sigma -1:2:9 --max-fit-error 1e-16 -o out.h5

# R(sigma) printed, with its change against 0.8 times the truncation; the served session answers the same numbers.
if "$BIN" shell --ekman 1e-3 --sigma 0.5,1.02+0.01i > R.txt 2>&1 && grep -q "R(sigma) by spectral forced solves" R.txt &&
   ! grep -q "NOT CONVERGED" R.txt; then
  ok "R(sigma) printed ($(sed -n 3p R.txt | tr -s ' '))"
else
  bad "R(sigma): $(cat R.txt)"
fi
if printf '0.5\nnot-a-number\n1.02+0.01i\n' | "$BIN" shell --ekman 1e-3 --serve > served.txt 2> served.err &&
   grep -q "^ready: viscous fluid, Ekman number 0.001, spectral forced solves in the sphere" served.txt &&
   [ "$(grep -c '^error: ' served.txt)" = 1 ] && [ "$(grep -c '^[-0-9]' served.txt)" = 2 ] &&
   python3 - R.txt served.txt <<'PY'
import sys
printed = [l.split() for l in open(sys.argv[1]) if l.startswith("  ") and not l.startswith("  sigma")]
served = [l.split() for l in open(sys.argv[2]) if l[:1] in "-0123456789"]
for p, s in zip(printed, served):
    re, im = float(p[2]), float(p[3].rstrip("i"))
    sre, sim = float(s[0]), float(s[1])
    assert abs(re - sre) + abs(im - sim) <= 1e-12 * (abs(sre) + abs(sim)), (p, s)
PY
then
  ok "served R is the printed R, and a bad line gets one error line"
else
  bad "served: $(cat served.txt served.err)"
fi

# Kore's own test case (its tests/spinover/reference.eig): the shell r_i = 0.35 at Ek = 1e-3.
check_kore() {  # csv, what
  python3 - "$1" "$2" <<'PY'
import csv, sys
rows = list(csv.DictReader(l for l in open(sys.argv[1]) if not l.startswith("#")))
r = rows[0]
f, d = float(r["lambda"]), float(r["decay"])
ef, ed = abs(f - 1.005733690103750355) / 1.005733690103750355, abs(d - 0.1019947097016500742) / 0.1019947097016500742
print("%s: lambda %.15f decay %.15f: against Kore's reference %.1e, %.1e; converged %s" % (sys.argv[2], f, d, ef, ed, r["converged"]))
sys.exit(0 if ef < 1e-12 and ed < 1e-12 and r["converged"] == "yes" else 1)
PY
}
if "$BIN" shell --inner-radius 0.35 --ekman 1e-3 -o kore.csv > kore.txt 2>&1 && check_kore kore.csv serial; then
  ok "Kore's shell at Ek = 1e-3"
else
  bad "Kore's shell: $(tail -3 kore.txt)"
fi
if command -v mpirun > /dev/null; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1
  if mpirun -n 2 "$BIN" shell --inner-radius 0.35 --ekman 1e-3 -o kore2.csv > kore2.txt 2>&1 &&
     check_kore kore2.csv "mpirun -n 2"; then
    ok "Kore's shell under mpirun -n 2"
  else
    bad "mpirun -n 2: $(tail -3 kore2.txt)"
  fi
fi
# A tolerance no truncation meets: the verdict says so in words, and the CSV says no.
if "$BIN" shell --ekman 1e-3 --convergence-tolerance 1e-17 -o strict.csv > strict.txt 2>&1 &&
   grep -q "^NOT CONVERGED: 1 mode(s)" strict.txt && grep -q ",no$" strict.csv; then
  ok "an unmet tolerance is said plainly"
else
  bad "unmet tolerance: $(cat strict.txt)"
fi
finish
