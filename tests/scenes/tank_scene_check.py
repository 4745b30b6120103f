#!/usr/bin/env python3
"""A scene with 3-D ellipsoid tanks end to end (data/scenes/spacecraft_triaxial_tank.toml, spacecraft_two_tanks.toml).

  tank_scene_check.py CAVITY_MODES CHAIN_ROM ROM_ELLIPSOID_TABLE SCENE DIR VERDICT

The scene's recipe (cavity-modes ellipsoid at its default order and mesh) makes the tanks' table; chain-rom spectrum
--json gives the chain without axial symmetry's roots and verdict; the same scene with the ellipsoid's closed-form table
(rom-ellipsoid-table: Poincare's and Hough's uniform-vorticity mode) must give the verdict VERDICT (stable or
unstable) both times, an unstable chain's growth rate to 1e-3, and every closed-form root within 1e-3 of the spectral
radius of a root of the recipe's chain (the mesh's discrete copies of a mode are extra roots beside it)."""
import json, os, re, shlex, subprocess, sys

modes, rom, closed_form, scene, out, verdict = sys.argv[1:7]
os.makedirs(out, exist_ok=True)
os.chdir(out)
text = open(scene).read()
name, args = re.search(r"^# recipe: ([^:]+): (.*)$", text, re.M).groups()
subprocess.run([modes] + shlex.split(args) + ["-o", name], check=True, stdout=subprocess.DEVNULL)
axes = [float(re.search(r"--%s (\S+)" % k, args).group(1)) for k in "abc"]
subprocess.run([closed_form] + ["%.17g" % x for x in axes] + ["0", "closed.h5"], check=True)
open("mesh.toml", "w").write(text.replace('"../../out/tables/%s"' % name, '"%s"' % name))
open("closed.toml", "w").write(text.replace('"../../out/tables/%s"' % name, '"closed.h5"'))


def spectrum(f):
    return json.loads(subprocess.run([rom, "spectrum", f, "--json"], capture_output=True, text=True, check=True).stdout)


m, c = spectrum("mesh.toml"), spectrum("closed.toml")
assert m["model"] == "general" and c["model"] == "general", m["model"]
mr, cr = ([complex(*r) for r in d["roots"]] for d in (m, c))
scale = max(abs(r) for r in cr)
gap = max(min(abs(r - s) for s in mr) for r in cr) / scale
print("%s: stable %s (closed form %s), growth %.6g 1/s (closed form %.6g), every closed-form root within %.1e of the "
      "spectral radius" % (os.path.basename(scene), m["stable"], c["stable"], m["growth"], c["growth"], gap))
assert m["stable"] == c["stable"] == (verdict == "stable"), (m["stable"], c["stable"])
if verdict == "unstable":
    assert abs(m["growth"] / c["growth"] - 1) < 1e-3, (m["growth"], c["growth"])
assert gap < 1e-3, gap
