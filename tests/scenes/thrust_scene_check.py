#!/usr/bin/env python3
"""A uniform time-varying field end to end (data/scenes/gyro_under_thrust.toml): a gimballed rotor with a water-filled
spherical tank aboard a stage during its burn — the thrust's acceleration a uniform field -20 e_z, the engine's lateral
shaking a harmonic one (docs/rom.md, "A uniform force field").

1. chain-rom spectrum: a filled sphere acts through its mass only, so the roots are Lagrange's top's under the thrust's
   "gravity", A' s^2 + C w s + a f = 0 (A' = A + m_f d^2, a = m c + m_f d), and Maievski's threshold
   w_c = 2 sqrt(A' a f)/C separates stable (the scene's 60 rad/s) from unstable (30 rad/s).
2. The field is gravity by another name: the scene with gravity = 20 and no field has the same roots.
3. chain-rom run: the burn with the engine's shaking, the linear run against the nonlinear chain (its own validity
   check) below 1e-3.

Usage: thrust_scene_check.py CAVITY_MODES CHAIN_ROM SCENE WORKDIR
"""
import json, math, os, re, subprocess, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from partial_fill_table import table_from_recipe, value  # noqa: E402

modes_bin, rom_bin, scene, work = sys.argv[1:5]
text, _, table = table_from_recipe(modes_bin, scene, work)
text = re.sub(r'^table = ".*"$', f'table = "{table}"', text, flags=re.M)
failed = 0


def fail(message):
    global failed
    print("FAILED: " + message)
    failed += 1


def roots(scene_text, name):
    path = os.path.join(work, name)
    open(path, "w").write(scene_text)
    out = subprocess.run([rom_bin, "spectrum", path, "--json", "--all"], capture_output=True, text=True)
    if out.returncode not in (0, 1):
        fail(f"chain-rom spectrum {name}: {out.stderr.strip()}")
        return None, []
    sp = json.loads(out.stdout)
    r = [complex(x[0], x[1]) for x in sp["roots"]]
    radius = max(abs(x) for x in r)
    return sp, sorted((x for x in r if abs(x) > 1e-9 * radius), key=lambda z: (z.real, z.imag))


mass, A, C, com = value(text, "mass"), value(text, "A"), value(text, "C"), value(text, "com")
rho, L, d = value(text, "density"), value(text, "scale"), value(text, "center")
thrust = -float(re.search(r"^space = \[0\.0, 0\.0, ([-0-9.e]+)\]", text, re.M).group(1))
m_f = rho * 4 / 3 * math.pi * L**3
A1, a = A + m_f * d * d, mass * com + m_f * d
w_c = 2 * math.sqrt(A1 * a * thrust) / C
print(f"Maievski's threshold under the thrust's {thrust:g} m/s^2: {w_c:.4f} rad/s")
for spin in (value(text, "spin"), 30.0):
    body = re.sub(r"^spin = .*$", f"spin = {spin!r}", text, flags=re.M)
    sp, got = roots(body, f"thrust_{spin:g}.toml")
    if sp is None:
        continue
    Cw, af = C * spin, a * thrust
    disc = complex(Cw * Cw - 4 * A1 * af) ** 0.5
    exact = sorted([(-Cw + disc) / (2 * A1), (-Cw - disc) / (2 * A1)], key=lambda z: (z.real, z.imag))
    err = (max(min(abs(p - q) for p in got) for q in exact) / max(abs(q) for q in exact) if len(got) == 2
           else float("inf"))
    print(f"spin {spin:g} rad/s: chain-rom {'stable' if sp['stable'] else 'unstable'}, roots "
          f"{', '.join(f'{z.real:.10f}{z.imag:+.10f}i' for z in got)}; Lagrange's top under the thrust to {err:.1e}")
    if not err < 1e-10:
        fail("the roots are not Lagrange's top's under the thrust")
    if sp["stable"] != (spin > w_c):
        fail(f"the verdict at {spin:g} rad/s is not Maievski's")
    if spin == value(text, "spin"):
        as_gravity = re.sub(r"^gravity = .*$", f"gravity = {thrust!r}", text, flags=re.M)
        as_gravity = re.sub(r"^\[field\]\n(.*\n)*?\n", "", as_gravity, flags=re.M)
        _, g_roots = roots(as_gravity, "thrust_as_gravity.toml")
        gap = (max(min(abs(p - q) for p in g_roots) for q in got) / max(abs(q) for q in got) if len(g_roots) == 2
               else 1.0)
        print(f"the same rotor under gravity {thrust:g} m/s^2 and no field: roots equal to {gap:.1e}")
        if not gap < 1e-13:
            fail("the uniform field is not gravity by another name")
path = os.path.join(work, "burn.toml")
open(path, "w").write(text)
out = subprocess.run([rom_bin, "run", path, "-o", os.path.join(work, "burn.h5")], capture_output=True, text=True)
m = re.search(r"validity: the nonlinear chain differs by ([0-9.e+-]+) relative", out.stdout)
print(f"the burn with the engine's shaking (chain-rom run): {m.group(0) if m else out.stderr.strip()}")
if not (out.returncode == 0 and m and float(m.group(1)) < 1e-3):
    fail("the burn's linear run is not the nonlinear chain's at this amplitude")
sys.exit(1 if failed else 0)
