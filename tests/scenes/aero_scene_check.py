#!/usr/bin/python3
"""The projectile example with its aerodynamics as moments (data/scenes/projectile_aero.toml) against the same
projectile with its overturning moment stood in as gravity (data/scenes/projectile_liquid.toml), on one ideal table
of their cylinder made here (seconds; the scenes' own viscous table takes a minute): without pitch damping the two
scenes' roots must be the same to rounding (the mapping of docs/rom.md, "A projectile's aerodynamic moments"), and
with it the spectrum reports the gyroscopic stability factor C^2 w^2/(4 A' M_alpha) that the scene's header states.

    aero_scene_check.py CAVITY_MODES CHAIN_ROM SCENE_DIR WORK_DIR
"""
import json
import os
import re
import subprocess
import sys

modes_bin, rom_bin, scenes, work = sys.argv[1:5]
os.makedirs(work, exist_ok=True)
table = os.path.join(work, "cylinder_projectile_ideal.h5")
subprocess.run([modes_bin, "cylinder", "--radius", "1", "--height", "4", "--modes", "12", "-o", table], check=True,
               capture_output=True)


def local(name, edits):
    text = open(os.path.join(scenes, name)).read()
    text = re.sub(r'^table = .*$', f'table = "{table}"', text, flags=re.M)
    text = re.sub(r'^viscosity = .*\n', '', text, flags=re.M)  # the ideal table takes no viscosity
    for a, b in edits:
        text = re.sub(a, b, text, flags=re.M)
    path = os.path.join(work, name)
    open(path, "w").write(text)
    return path


def roots(scene):
    r = subprocess.run([rom_bin, "spectrum", scene, "--json"], capture_output=True, text=True, check=True)
    return sorted((complex(*z) for z in json.loads(r.stdout)["roots"]), key=lambda z: (z.real, z.imag))


gravity = roots(local("projectile_liquid.toml", []))
aero = roots(local("projectile_aero.toml", [(r"^pitch_damping = .*$", "pitch_damping = 0.0")]))
worst = max(abs(a - g) / abs(g) for a, g in zip(aero, gravity))
print(f"{len(aero)} roots: [body.aero] static_moment = 40 against gravity x com = 40 N m/rad: {worst:.1e} relative")
damped = local("projectile_aero.toml", [])
text = subprocess.run([rom_bin, "spectrum", damped], capture_output=True, text=True, check=True).stdout
sg = float(re.search(r"S_g = C\^2 w\^2/\(4 A' M\) = (\S+)\)", text).group(1))
print(f"with pitch damping: S_g = {sg:.4f} printed (the header's 'about 67')")
ok = len(aero) == len(gravity) and worst < 1e-12 and abs(sg - 67) < 0.5
print("PASS" if ok else "FAIL")
sys.exit(0 if ok else 1)
