#!/usr/bin/env python3
"""The example with a viscous 3-D tank end to end (data/scenes/spacecraft_viscous_tank.toml; docs/volume.md §7).

  viscous_tank_scene_check.py CAVITY_MODES CHAIN_ROM ROM_ELLIPSOID_TABLE SCENE DIR

The scene's recipe (cavity-modes ellipsoid --ekman 1e-3 -o) makes the tank's viscous 3-D table on a mesh coarser than
its own (--mesh-size 0.5 --wall-size 0.12: 41 s, where the recipe's mesh takes 62 s idle and 7 GB; the recipe's own
mesh and finer ones are bench/volume_viscous_chain.sh's), and the same recipe on a coarser mesh still (--mesh-size 0.6
--wall-size 0.15, 25 s) a second; chain-rom spectrum --json runs the scene on each. No closed form exists for the
viscous chain, so the checks are a convergence check and the Ekman number's trend: both chains unstable with growth
rates within 1 % of each other (measured 2026-11-29: 0.466739 and 0.467720 1/s; the recipe's mesh 0.466613), and the
growth ordered as the Ekman number falls towards the ideal liquid's limit — the same scene at Ek = 1e-2 (viscosity ten
times larger, its table on the coarser mesh) grows more slowly than at 1e-3, and that more slowly than the ideal
liquid's chain (the ellipsoid's closed-form table, rom-ellipsoid-table; measured 0.153, 0.467, 0.665 1/s)."""
import json, os, re, shlex, subprocess, sys

modes, rom, closed_form, scene, out = sys.argv[1:6]
os.makedirs(out, exist_ok=True)
os.chdir(out)
text = open(scene).read()
name, args = re.search(r"^# recipe: ([^:]+): (.*)$", text, re.M).groups()
args = shlex.split(args)
nu = float(re.search(r"^viscosity = (\S+)$", text, re.M).group(1))


def spectrum(table, viscosity):
    scene_text = text.replace('"../../out/tables/%s"' % name, '"%s"' % table)
    if viscosity is None:
        scene_text = re.sub(r"^viscosity = .*\n", "", scene_text, flags=re.M)
    else:
        scene_text = re.sub(r"^viscosity = .*$", "viscosity = %.17g" % viscosity, scene_text, flags=re.M)
    toml = table.replace(".h5", ".toml")
    open(toml, "w").write(scene_text)
    d = json.loads(subprocess.run([rom, "spectrum", toml, "--json"], capture_output=True, text=True, check=True).stdout)
    assert d["model"] == "general", d["model"]
    return d


def make(file, extra, replace=None):
    a = list(args)
    if replace:
        a[a.index(replace[0]) + 1] = replace[1]
    subprocess.run([modes] + a + extra + ["-o", file], check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return file


# The recipe on the test's mesh, without its own check against a mesh 1.5 times as coarse: the coarser table below is
# this test's check.
test_mesh = ["--mesh-size", "0.5", "--wall-size", "0.12", "--no-convergence-check"]
coarser_mesh = ["--mesh-size", "0.6", "--wall-size", "0.15", "--no-convergence-check"]
recipe = spectrum(make(name, test_mesh), nu)
coarse = spectrum(make("coarse.h5", coarser_mesh), nu)
thick = spectrum(make("ek1e-2.h5", coarser_mesh, ("--ekman", "1e-2")), 10 * nu)
axes = [float(re.search(r"--%s (\S+)" % k, " ".join(args)).group(1)) for k in "abc"]
subprocess.run([closed_form] + ["%.17g" % x for x in axes] + ["0", "ideal.h5"], check=True)
ideal = spectrum("ideal.h5", None)
print("%s: growth %.6g 1/s (the recipe on h 0.5), %.6g (h 0.6: %.1e apart); Ek = 1e-2: %.6g, ideal liquid: %.6g"
      % (os.path.basename(scene), recipe["growth"], coarse["growth"], abs(coarse["growth"] / recipe["growth"] - 1),
         thick["growth"], ideal["growth"]))
assert not recipe["stable"] and not coarse["stable"] and not ideal["stable"], "the verdicts changed"
assert abs(coarse["growth"] / recipe["growth"] - 1) < 1e-2, (recipe["growth"], coarse["growth"])
assert thick["growth"] < recipe["growth"] < ideal["growth"], (thick["growth"], recipe["growth"], ideal["growth"])
