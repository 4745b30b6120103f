#!/usr/bin/python3
"""The spacecraft with partially filled tanks off its axis (data/scenes/spacecraft_fill_tanks.toml, two tanks, and
spacecraft_four_fill_tanks.toml, four) end to end: each scene's tables from its recipes at a low order (P3), chain-rom
spectrum --json on it (the free chain, its base recoiling with the liquid: docs/volume.md §8, "The free chain"):
1. the two-tank craft's nutation on a second mesh (P4, h 0.6) within 3e-3 of the first (measured 2026-12-07 on six
   meshes from P3 to P5: 2.09605 to 2.09846 rad/s);
2. the free chain's reduction check (X only through tau, pi conserved) to 1e-12;
3. the verdict stable, and NOT CONVERGED said for the tanks' unsettled rows;
4. the craft's mirror symmetry about the tanks' plane through its centre of mass decouples the tilts from the base's
   translation, so the free chain's tilt roots are the fixed chain's (to 1e-9 of the nutation); with the tanks 0.1 m
   above the craft's centre of mass they are not (its joint O then moves: by more than 1e-5);
and with the liquid viscous (spacecraft_fill_tanks_viscous.toml, boundary-layer tables: docs/volume.md section 9):
5. stable, the nutation decays, and the recipes' --exact-at is the root's (remade there, it moves by < 1e-6; measured
   2026-12-08 at P3 h 0.3: the nutation 2.112642 + 1.2560e-4i rad/s, moved 3.2e-10).
usage: fill_tanks_scene_check.py CAVITY_MODES CHAIN_ROM SCENES_DIR WORKDIR
"""
import json, os, re, shlex, shutil, subprocess, sys

modes_bin, rom_bin, scenes, work = sys.argv[1:5]
shutil.rmtree(work, ignore_errors=True)  # the tables made by this build, not an earlier run's
os.makedirs(work)
os.chdir(work)
failures = []

def run(*args):
    p = subprocess.run(list(args), capture_output=True, text=True)
    if p.returncode != 0: sys.exit("failed: " + " ".join(args) + "\n" + p.stderr[-2000:])
    return p.stdout

def scene_with_tables(name, extra, tag, edit=lambda s: s, kind=None, recipe=lambda s: s):
    """The scene pointed at its recipes' tables made with `extra` options (once per tag), as <name>_<tag>.toml;
    `recipe` edits the scene's text before its recipes are read."""
    text = recipe(open(os.path.join(scenes, name + ".toml")).read())
    for table, args in re.findall(r"^# recipe: ([^:]+): (.*)$", text, re.M):
        made = "%s_%s" % (tag, table)
        if not os.path.exists(made): run(modes_bin, *shlex.split(args), *extra, "-o", made)
        text = text.replace('"../../out/tables/%s"' % table, '"%s"' % made)
    text = edit(text)
    if kind: text = text.replace('kind = "free"', 'kind = "%s"' % kind)
    out = "%s_%s%s.toml" % (name, tag, "_" + kind if kind else "")
    open(out, "w").write(text)
    return out

def spectrum(path):
    return json.loads(run(rom_bin, "spectrum", path, "--json"))

def nutation(sp):
    tilts = [r[0] for r in sp["roots"] if 0.5 < r[0] < 4]
    if len(tilts) != 1: sys.exit("expected one nutation root in (0.5, 4) rad/s, got %s" % tilts)
    return tilts[0]

low, second = ["--order", "3"], ["--order", "4", "--mesh-size", "0.6"]
for name in ("spacecraft_fill_tanks", "spacecraft_four_fill_tanks"):
    sp = spectrum(scene_with_tables(name, low, "p3"))
    nut = nutation(sp)
    print("%s: stable %s, nutation %.6f rad/s (turning frame), reduction check %.1e, %d tanks NOT CONVERGED"
          % (name, sp["stable"], nut, sp.get("recoil_residual", 1), len(sp["not_converged"])))
    if not sp["stable"]: failures.append(name + ": not stable")
    if not sp.get("recoil_residual", 1) < 1e-12: failures.append(name + ": reduction check %s" % sp.get("recoil_residual"))
    if not sp["not_converged"]: failures.append(name + ": no NOT CONVERGED note for the unsettled rows")
    if name != "spacecraft_fill_tanks": continue
    other = nutation(spectrum(scene_with_tables(name, second, "p4")))
    print("  on a second mesh (P4, h 0.6): %.6f, %.1e apart" % (other, abs(other / nut - 1)))
    if not abs(other / nut - 1) < 3e-3: failures.append("the two meshes' nutations %.1e apart" % abs(other / nut - 1))
    fixed = nutation(spectrum(scene_with_tables(name, low, "p3", kind="fixed")))
    raise_tanks = lambda s: s.replace("origin = 0.0", "origin = 0.1")
    up_free = nutation(spectrum(scene_with_tables(name, low, "p3", raise_tanks)))
    up_fixed = nutation(spectrum(scene_with_tables(name, low, "p3", raise_tanks, kind="fixed")))
    print("  free against fixed: %.1e with the tanks on the centre of mass's plane, %.1e with them 0.1 m above it"
          % (abs(fixed / nut - 1), abs(up_fixed / up_free - 1)))
    if not abs(fixed / nut - 1) < 1e-9: failures.append("free and fixed differ by %.1e on the plane" % abs(fixed / nut - 1))
    if not abs(up_fixed / up_free - 1) > 1e-5: failures.append("free and fixed agree off the plane")

# The viscous craft (spacecraft_fill_tanks_viscous.toml): boundary-layer tables exact at the nutation's tank frequency.
def viscous_nutation(sp, near):
    slow = [complex(*r) for r in sp["roots"] if 0.5 < r[0] < 4 and abs(r[1]) < 1e-2]
    return min(slow, key=lambda r: abs(r - near))

name = "spacecraft_fill_tanks_viscous"
p3 = lambda text: text.replace("--order 4 --mesh-size 0.3", "--mesh-size 0.3")  # the recipes' mesh at P3 (`low`)
sp = spectrum(scene_with_tables(name, low, "p3", recipe=p3))
root = viscous_nutation(sp, 2.1127)
print("%s: stable %s, nutation %.6f%+.4ei" % (name, sp["stable"], root.real, root.imag))
if not sp["stable"]: failures.append(name + ": not stable")
if not 0 < root.imag: failures.append(name + ": the nutation does not decay")
# 5. Remade exact at the root found, the table moves it by less than 1e-6: the recipes' --exact-at is the root's.
s = -root.conjugate() / 6.2832
exact = lambda text: re.sub(r"--exact-at=\S+", "--exact-at=%.12g%+.12gi" % (s.real, s.imag), p3(text))
again = viscous_nutation(spectrum(scene_with_tables(name, low, "again", recipe=exact)), root)
print("  remade at the root: moved %.1e" % (abs(again / root - 1)))
if not abs(again / root - 1) < 1e-6: failures.append("the recipes' exact frequency is not the root's")
print("FAILED: " + "; ".join(failures) if failures else "passed")
sys.exit(1 if failures else 0)
