#!/usr/bin/env python3
"""The nutation decay of spacecraft with boundary-layer tables (docs/volume.md section 9), measured against the viscous
solver where it can be: cavity-modes ellipsoid ... --boundary-layer tables remade exact at the nutation root (value
and slope) until it settles, then chain-rom spectrum's root.

  python3 bench/boundary_layer_spacecraft.py [BUILD_DIR] [OUT_DIR]     (about 25 minutes on one core on 2026-12-08, before --ideal-table)
  PART="four" or PART="sweep" for the four-tank craft or the two-tank craft's fill sweep (0.2 to 0.95)

1. On the spin axis, against the converged meridian viscous decays of docs/trust.md (the spacecraft of
   data/scenes/spacecraft_nutation.toml with one spherical tank of radius 0.4 m, 0.3 m above the centre of mass):
   60 % full at Ek = 9.05192e-7 (2.9726e-4 1/s, P4/P5 on h 0.0145) and 50 % full at Ek = 1e-6 (3.92675e-4 1/s).
2. The two-tank craft of data/scenes/spacecraft_fill_tanks.toml (two half-full spheres of radius 0.3 m at +-0.6 m,
   hydrazine, 60 rpm: Ek = 1.60924e-6) on three meshes of the ideal liquid.
Writes OUT_DIR/boundary_layer_spacecraft.csv and prints the rows."""
import json
import os
import re
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BUILD = os.path.abspath(sys.argv[1]) if len(sys.argv) > 1 else os.path.join(ROOT, "build")
OUT = os.path.abspath(sys.argv[2]) if len(sys.argv) > 2 else os.path.join(ROOT, "bench", "results")
MODES = os.path.join(BUILD, "modes", "cavity-modes")
ROM = os.path.join(BUILD, "rom", "chain-rom")
SPIN = 6.2832


def run(args):
    subprocess.run(args, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)


def roots(scene):
    out = subprocess.run([ROM, "spectrum", scene, "--json"], check=True, capture_output=True, text=True).stdout
    return [complex(a, b) for a, b in json.loads(out)["roots"]]


def nutation(scene, near):
    """The weakly damped root nearest the previous one (the nutation, followed from the ideal chain's)."""
    slow = [r for r in roots(scene) if abs(r.imag) < 0.01 * abs(r.real)]
    return min(slow, key=lambda r: abs(r - near))


def settle(scene, tables, start):
    """Remakes every (table, shape args) exact at the root's tank frequency until the root moves by < 1e-9."""
    root, rounds = start, 0
    while rounds < 6:
        s = root / SPIN
        for path, args in tables:
            run([MODES, "ellipsoid"] + args + ["--boundary-layer", "--sigma", "0:2:3",
                                               "--exact-at=%.12g%+.12gi" % (s.real, s.imag), "-o", path])
        new = nutation(scene, root)
        rounds += 1
        if abs(new - root) < 1e-9 * abs(root):
            return new, rounds
        root = new
    return root, rounds


def scene_text(template, replace):
    text = open(os.path.join(ROOT, "data", "scenes", template)).read()
    for a, b in replace:
        text = re.sub(a, b, text, flags=re.M)
    return text


def on_axis(work, fill, ek, reference, mesh):
    ideal = os.path.join(work, "ideal.h5")
    run([MODES, "ellipsoid", "--a", "1", "--b", "1", "--c", "1", "--fill", str(fill)] + mesh + ["-o", ideal])
    base = [(r'"../../out/tables/sphere_fill0.6_hydrazine.h5"', '"%s"' % ideal), (r"^viscosity = .*\n", "")]
    open(os.path.join(work, "ideal.toml"), "w").write(scene_text("spacecraft_nutation.toml", base))
    start = nutation(os.path.join(work, "ideal.toml"), complex(-1.53, 0))
    table = os.path.join(work, "bl.h5")
    nu = ek * SPIN * 0.16
    open(os.path.join(work, "bl.toml"), "w").write(scene_text("spacecraft_nutation.toml", [
        (r'"../../out/tables/sphere_fill0.6_hydrazine.h5"', '"%s"' % table), (r"^viscosity = .*", "viscosity = %r" % nu)]))
    args = ["--a", "1", "--b", "1", "--c", "1", "--fill", str(fill), "--ekman", repr(ek), "--ideal-table", ideal] + mesh
    t = time.time()
    root, rounds = settle(os.path.join(work, "bl.toml"), [(table, args)], start)
    return root, rounds, time.time() - t


def craft(work, template, directions, mesh, fill=0.5, guess=-2.1):
    """The craft of `template` with its tanks (one per direction, 0.6 m off the axis) at `fill`: the ideal rows'
    nutation, then the boundary-layer tables' settled root."""
    tables = []
    replace = [(r"^viscosity = .*\n", "")]
    for d in directions:
        ideal = os.path.join(work, "ideal_%s.h5" % d)
        run([MODES, "ellipsoid", "--a", "1", "--b", "1", "--c", "1", "--fill", str(fill), "--axis-distance", "2",
             "--axis-direction", d] + mesh + ["-o", ideal])
        replace.append((r'"../../out/tables/fill_tank_%s.h5"' % d, '"%s"' % ideal))
    open(os.path.join(work, "ideal.toml"), "w").write(scene_text(template, replace))
    start = nutation(os.path.join(work, "ideal.toml"), complex(guess, 0))
    replace = []
    for d in directions:
        table = os.path.join(work, "bl_%s.h5" % d)
        replace.append((r'"../../out/tables/fill_tank_%s.h5"' % d, '"%s"\nviscosity = 9.1e-7' % table))
        tables.append((table, ["--a", "1", "--b", "1", "--c", "1", "--fill", str(fill), "--axis-distance", "2",
                               "--axis-direction", d, "--ekman", "1.60924e-6",
                               "--ideal-table", os.path.join(work, "ideal_%s.h5" % d)] + mesh))
    open(os.path.join(work, "bl.toml"), "w").write(scene_text(template, replace))
    t = time.time()
    root, rounds = settle(os.path.join(work, "bl.toml"), tables, start)
    return start, root, rounds, time.time() - t


def main():
    part = os.environ.get("PART", "axis two")
    os.makedirs(OUT, exist_ok=True)
    rows = ["case,mesh,ekman,ideal_root,nutation_re,decay,reference_decay,relative,rounds,seconds"]
    meshes = [["--order", "3", "--mesh-size", "0.3"], ["--order", "3", "--mesh-size", "0.2"],
              ["--order", "4", "--mesh-size", "0.3"]]
    with tempfile.TemporaryDirectory() as work:
        for fill, ek, ref in ((0.6, 9.05192e-7, 2.9726e-4), (0.5, 1e-6, 3.92675e-4)) if "axis" in part else ():
            for mesh in meshes:
                root, rounds, sec = on_axis(work, fill, ek, ref, mesh)
                rows.append("on-axis sphere %g,%s,%g,,%.9f,%.6e,%.6e,%+.4f,%d,%.1f" % (
                    fill, " ".join(mesh), ek, root.real, root.imag, ref, root.imag / ref - 1, rounds, sec))
                print(rows[-1], flush=True)
        crafts = []
        if "two" in part:
            crafts += [("two tanks 0.5 at +-0.6 m", "spacecraft_fill_tanks.toml", ("0", "180"), mesh, 0.5) for mesh in meshes]
        if "four" in part:
            crafts.append(("four tanks 0.5 at 0.6 m", "spacecraft_four_fill_tanks.toml", ("0", "90", "180", "270"),
                           meshes[2], 0.5))
        if "sweep" in part:  # the two-tank craft's fill, on P3 h 0.3
            crafts += [("two tanks %g at +-0.6 m" % f, "spacecraft_fill_tanks.toml", ("0", "180"), meshes[0], f)
                       for f in (0.2, 0.35, 0.5, 0.65, 0.8, 0.95)]
        for name, template, directions, mesh, fill in crafts:
            guess = -2.34 if len(directions) == 4 else -2.1
            start, root, rounds, sec = craft(work, template, directions, mesh, fill, guess)
            rows.append("%s,%s,1.60924e-6,%.6f,%.9f,%.6e,,,%d,%.1f" % (
                name, " ".join(mesh), start.real, root.real, root.imag, rounds, sec))
            print(rows[-1], flush=True)
    name = "boundary_layer_spacecraft.csv" if part == "axis two" else "boundary_layer_spacecraft_%s.csv" % part.replace(" ", "_")
    with open(os.path.join(OUT, name), "w") as f:
        f.write("\n".join(rows) + "\n")
    if "sweep" in part:
        plot_sweep(rows[1:], os.path.join(OUT, "boundary_layer_fill_sweep.png"))


def plot_sweep(rows, path):
    """The two-tank craft's nutation decay and frequency against the fill (matplotlib, where installed)."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("no matplotlib: no plot")
        return
    fills = [float(r.split(",")[0].split()[2]) for r in rows]
    decay = [float(r.split(",")[5]) for r in rows]
    freq = [-float(r.split(",")[4]) for r in rows]
    fig, ax = plt.subplots(2, 1, figsize=(6, 6), sharex=True)
    ax[0].plot(fills, [1e4 * d for d in decay], "o-")
    ax[0].set_ylabel("nutation decay (1e-4 1/s)")
    ax[0].set_title("two tanks 0.6 m off the axis, hydrazine, 60 rpm", fontsize=10)
    ax[1].plot(fills, freq, "o-")
    ax[1].set_ylabel("nutation (rad/s, turning frame)")
    ax[1].set_xlabel("fill of each tank")
    fig.tight_layout()
    fig.savefig(path, dpi=90)


if __name__ == "__main__":
    main()
