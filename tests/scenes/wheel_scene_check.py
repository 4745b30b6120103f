#!/usr/bin/env python3
"""The spacecraft with an unbalanced momentum wheel (data/scenes/spacecraft_wheel.toml) end to end: two spins, so the
chain's coefficients are periodic and chain-rom finds its roots by Floquet's theory (docs/rom.md, "Bodies at different
spins").

  wheel_scene_check.py CAVITY_MODES CHAIN_ROM ROM_ELLIPSOID_TABLE SCENE DIR

1. The recipe's table and the ellipsoid's closed-form table (rom-ellipsoid-table) in the scene as written (wheel at
   60 rad/s): both stable, every closed-form root within 1e-4 of the spectral radius of a root of the recipe's chain
   (the real parts compared modulo the period's frequency).
2. The wheel at 212.08 rad/s, inside a combination resonance (the craft's nutation and the wheel's fast mode 2 Omega
   apart): unstable by Floquet; the same craft with a balanced wheel (B = A) stable; and the nonlinear chain (rigid
   bodies at any angle, a separate model) released at 1e-6 rad grows at the Floquet rate to 2 %, measured on the peaks
   of its largest tilt from 100 s to 140 s.
3. A sweep of the wheel's spin over 211.8 to 213 rad/s finds the two narrow unstable bands and stable spins around them."""
import csv, json, math, os, re, shlex, subprocess, sys

import h5py
import numpy as np

modes, rom, closed_form, scene, out = sys.argv[1:6]
os.makedirs(out, exist_ok=True)
os.chdir(out)
text = open(scene).read()
name, args = re.search(r"^# recipe: ([^:]+): (.*)$", text, re.M).groups()
subprocess.run([modes] + shlex.split(args) + ["-o", name], check=True, stdout=subprocess.DEVNULL)
axes = [float(re.search(r"--%s (\S+)" % k, args).group(1)) for k in "abc"]
subprocess.run([closed_form] + ["%.17g" % x for x in axes] + ["0", "closed.h5"], check=True)
mesh_text = text.replace('"../../out/tables/%s"' % name, '"%s"' % name)
open("mesh.toml", "w").write(mesh_text)
open("closed.toml", "w").write(text.replace('"../../out/tables/%s"' % name, '"closed.h5"'))


def spectrum(f):
    return json.loads(subprocess.run([rom, "spectrum", f, "--json"], capture_output=True, text=True, check=True).stdout)


# 1. The scene as written.
m, c = spectrum("mesh.toml"), spectrum("closed.toml")
assert "floquet" in m and "floquet" in c, "the chain should be periodic"
omega = 2 * math.pi / m["floquet"]["period"]
mr, cr = ([complex(*r) for r in d["roots"]] for d in (m, c))
scale = max(abs(r) for r in cr)


def apart(a, b):
    re_ = a.real - b.real
    return math.hypot(re_ - omega * round(re_ / omega), a.imag - b.imag)


gap = max(min(apart(r, s) for s in mr) for r in cr) / scale
print("spacecraft_wheel.toml (wheel at 60 rad/s): stable %s (closed form %s), %d Floquet roots, %d Magnus steps a "
      "period, settled to %.1e rad/s; every closed-form root within %.1e of the spectral radius"
      % (m["stable"], c["stable"], len(mr), m["floquet"]["steps_per_period"], m["floquet"]["settled"], gap))
assert m["stable"] and c["stable"]
assert gap < 1e-4, gap

# 2. Inside the resonance: Floquet against the nonlinear chain.
wheel = re.compile(r"^spin = 60\.0$", re.M)
assert wheel.search(mesh_text), "the wheel's spin line"
resonant = wheel.sub("spin = 212.08", mesh_text)
open("resonant.toml", "w").write(resonant)
open("balanced.toml", "w").write(resonant.replace("B = 0.44\n", ""))
r, b = spectrum("resonant.toml"), spectrum("balanced.toml")
open("nonlinear.toml", "w").write(resonant + '[initial]\ntilt = [[0.0, 0.0], [1e-6, 0.0]]\nrate = [[0.0, 0.0], [0.0, 0.0]]\n'
                                  '[run]\nt_end = 140.0\noutput_step = 0.002\nmodel = "nonlinear"\n')
subprocess.run([rom, "run", "nonlinear.toml", "-o", "nonlinear.h5"], check=True, stdout=subprocess.DEVNULL)
with h5py.File("nonlinear.h5", "r") as h:
    t = h["t"][:]
    tilt = np.abs(h["u_re"][:] + 1j * h["u_im"][:]).max(axis=1)


def peak(t0):
    return tilt[(t >= t0) & (t < t0 + 10)].max()


measured = math.log(peak(130) / peak(100)) / 30
print("wheel at 212.08 rad/s: stable %s, Floquet growth %.6g 1/s; the nonlinear chain grows at %.6g 1/s (%.1e apart); "
      "with the wheel balanced: stable %s" % (r["stable"], r["growth"], measured, abs(measured / r["growth"] - 1), b["stable"]))
assert not r["stable"] and b["stable"]
assert abs(measured / r["growth"] - 1) < 0.02, (measured, r["growth"])

# 3. The bands.
subprocess.run([rom, "sweep", "mesh.toml", "--param", "body[2].spin", "--from", "211.8", "--to", "213", "--steps", "121",
                "-o", "bands.csv"], check=True, stdout=subprocess.DEVNULL)
rows = list(csv.DictReader(open("bands.csv")))
stable = [row["stable"] == "1" for row in rows]
changes = sum(1 for i in range(1, len(stable)) if stable[i] != stable[i - 1])
unstable = [float(row["body[2].spin"]) for row in rows if row["stable"] == "0"]
print("sweep of the wheel's spin 211.8..213 rad/s: %d unstable points, %d changes of verdict (%.2f..%.2f rad/s)"
      % (len(unstable), changes, min(unstable), max(unstable)))
assert stable[0] and stable[-1] and changes == 4, changes

# 4. The frequency response at two spins (docs/rom.md, "Frequency response at two spins"): a moment on the craft, on
# the recipe's table and on the closed form: each tilt the closed form's to 1e-4 at the frequencies 1 rad/s or more
# from every resonance (nearer, the table's 1e-7 in the roots is magnified by the peak); the unbalanced wheel's
# sidebands present; the balanced wheel's chain constant in the craft's frame (no sideband columns).
def response(f, png=False):
    subprocess.run([rom, "response", f, "--body", "1", "--freq", "-30:30:61", "-o", f + ".csv"] +
                   (["--png", f + ".png"] if png else []), check=True, capture_output=True, text=True)
    assert not png or os.path.getsize(f + ".png") > 10000, "the Bode plot with mirrors and sidebands"
    lines = open(f + ".csv").readlines()
    rows = list(csv.DictReader(line for line in lines if not line.startswith("#")))
    return [float(line.split()[2]) for line in lines if line.startswith("# resonance")], rows


_, mesh_rows = response("mesh.toml", png=True)
resonances, closed_rows = response("closed.toml")
open("balanced60.toml", "w").write(mesh_text.replace("B = 0.44\n", ""))
_, balanced_rows = response("balanced60.toml")
assert "sideband_rms_1" in mesh_rows[0] and "sideband_rms_1" not in balanced_rows[0]


def values(rows, key):
    return np.array([float(r[key]) for r in rows])


sigma = values(closed_rows, "sigma")
finite = np.isfinite(values(closed_rows, "abs_1")) & np.isfinite(values(mesh_rows, "abs_1"))
away = finite & np.array([min(abs(s - r) for r in resonances) >= 1 for s in sigma])
gap = max((np.abs(values(mesh_rows, "abs_%d" % k) / values(closed_rows, "abs_%d" % k) - 1))[away].max() for k in (1, 2))
side = values(mesh_rows, "sideband_rms_2")[finite] / values(mesh_rows, "abs_2")[finite]
print("response to a moment on the craft, 61 frequencies in -30..30 rad/s (%d at a root): the recipe's table against "
      "the closed form %.1e (relative, at the %d frequencies 1 rad/s or more from the %d resonances); the wheel's "
      "sidebands up to %.2g of its tilt" % (len(finite) - finite.sum(), gap, away.sum(), len(resonances), side.max()))
assert gap < 1e-4, gap
assert side.max() > 1e-6, side.max()
