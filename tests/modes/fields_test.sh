#!/usr/bin/env bash
# cavity-modes --fields: the XDMF companion parses and names datasets that exist with the shapes it states,
# the stored fields pass the physics checks of check_fields.py (sphere closed form, ∫ energy = N² = 1,
# a from the nodal field), and the table and its companion are written and removed together.
set -u
source "$(cd "$(dirname "$0")" && pwd)/cli_checks.sh"
BIN=$1
CHECK="/usr/bin/python3 $(cd "$(dirname "$0")" && pwd)/check_fields.py"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

run_checks() {  # name, check_fields arguments...
  local name=$1
  shift
  if $CHECK "$@" > check.txt 2>&1; then
    ok "$name: $(grep -c '^ok:' check.txt) checks"
  else
    bad "$name"
  fi
  grep -E "sphere:|2 pi int|nodal field|re-solved|volume" check.txt | sed 's/^/    /'
  grep -E "FAILED|Error|Traceback" check.txt | sed 's/^/    /'
}

# Sphere, order 4 on a coarse mesh (h = R/2): one mode, p = -z r (docs/physics.md §2). The output goes to a
# subfolder and the checks run from elsewhere: the companion must name the table relative to itself.
mkdir sub
if "$BIN" sphere --radius 1 --order 4 --mesh-size 0.5 --fields -o sub/s.h5 > run.txt 2>&1 \
   && [ -f sub/s.h5 ] && [ -f sub/s.xdmf ]; then
  ok "sphere table and its XDMF companion written"
  grep -q '>s.h5:/fields/mesh/points<' sub/s.xdmf && ok "companion names the table by its relative name" \
    || bad "companion does not name s.h5: $(grep points sub/s.xdmf)"
  ls sub | grep -q tmp && bad "temporary files left: $(ls sub)" || ok "no temporary file left"
  run_checks "sphere fields" sub/s.h5 --sphere 1 --tol-integral 5e-3 --tol-a 5e-3 --tol-closed 5e-3
else
  bad "sphere --fields: $(tail -1 run.txt)"
fi

# Cylinder 2h/a = 2, three modes with different radial structure.
if "$BIN" cylinder --radius 1 --height 2 --order 4 --mesh-size 0.25 --modes 3 --no-convergence-check --fields \
     -o c.h5 > run.txt 2>&1; then
  run_checks "cylinder fields" c.h5
else
  bad "cylinder --fields: $(tail -1 run.txt)"
fi

# Optional: ParaView's own readers (Debian's paraview + python3-paraview; not in install-deps.sh, ~0.5 GB) must
# read every point, sub-triangle and array that the table holds.
if command -v pvpython > /dev/null && [ -f c.xdmf ]; then
  want=$(/usr/bin/python3 -c 'import h5py; f = h5py.File("c.h5", "r")
print("points %d cells %d" % (len(f["fields/mesh/points"]), len(f["fields/mesh/cells"])), 3 * len(f["modes/E"]))')
  if pvpython --force-offscreen-rendering "$(cd "$(dirname "$0")" && pwd)/paraview_read.py" c.xdmf > pv.txt 2> pv_err.txt; then
    read -r label_p np label_c nc narrays <<< "$want"
    readers=$(grep -c "points $np cells $nc arrays" pv.txt)
    arrays_ok=$(grep -o "'mode[0-9]* [a-zA-Z_]*'" pv.txt | sort -u | wc -l)
    [ "$readers" -eq 3 ] && [ "$arrays_ok" -eq "$narrays" ] \
      && ok "ParaView's XDMF readers read $np points, $nc cells, $narrays arrays (3 readers)" \
      || bad "ParaView read something else than $want: $(cut -c1-200 pv.txt)"
  else
    bad "ParaView could not read c.xdmf: $(tail -2 pv.txt pv_err.txt)"
  fi
else
  echo "skipped: ParaView check (no pvpython)"
fi

# Rewriting a table without --fields removes its stale companion, and the table has no /fields.
if [ -f sub/s.h5 ] && "$BIN" sphere --radius 1 --order 2 --mesh-size 0.5 -o sub/s.h5 > run.txt 2>&1; then
  [ ! -e sub/s.xdmf ] && ok "stale companion removed" || bad "stale companion left behind"
  /usr/bin/python3 -c 'import h5py, sys; sys.exit("fields" in h5py.File("sub/s.h5", "r"))' \
    && ok "no /fields without --fields" || bad "/fields written without --fields"
fi
echo '<Xdmf/>' > sub/s.xdmf  # not ours: must survive a rewrite
"$BIN" sphere --radius 1 --order 2 --mesh-size 0.5 -o sub/s.h5 > run.txt 2>&1
[ -f sub/s.xdmf ] && ok "a user's own s.xdmf is left alone" || bad "a user's own s.xdmf was removed"

# Failures leave neither the table nor its companion.
no_companion() {  # name
  if ls out.xdmf* > /dev/null 2>&1; then bad "$1: companion left behind"; else ok "$1: no companion"; fi
}
expect_error "table named .xdmf" "must not end in .xdmf" "$BIN" sphere --radius 1 --order 2 --fields -o out.xdmf
no_companion "table named .xdmf"
expect_error "solver failure with --fields" "eigensolver" "$BIN" sphere --radius 1 --order 3 --fields -o out.h5 \
  -pep_max_it 1 -pep_tol 1e-30
no_companion "solver failure with --fields"
expect_error "unwritable output with --fields" "cannot create" "$BIN" sphere --radius 1 --order 2 --fields \
  -o /nonexistent-dir/out.h5

finish
