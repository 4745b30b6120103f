#!/usr/bin/env python3
"""Galerkin tanks against modal tanks against the full response (docs/rom.md, "Galerkin tanks").

One heavy top (m = 3 kg, A = 0.066, C = 0.05 kg m^2, spin 100 rad/s) with a water-like cylinder tank (radius 4 cm,
height 8 cm, Ek = 1e-3): its two body roots with the tank entering as
  * the response fit (cavity-modes response: every mode, to the fit's error) - the reference,
  * the Galerkin response table (cavity-modes response --galerkin: the projection on the forced solutions at the
    same samples), modal and Galerkin reduction (one model: its E are the Galerkin residues),
  * k damped modes, modal (residues E_c) or Galerkin (residues of the Hermitian projection), k = 1 ... 10,
    with and without the static correction,
and the energy balance of a `run` with the Galerkin tank.

  /usr/bin/python3 bench/galerkin_tanks.py [--bin build/modes/cavity-modes] [--rom build/rom/chain-rom]
                                           [--tables DIR (reuse cylinder_modes.h5, cylinder_fit.h5 and
                                                          cylinder_galerkin.h5 there)]

Writes bench/results/galerkin_tanks_<date>.csv and prints a markdown table."""
import argparse, json, os, subprocess, tempfile

from results_csv import write_results

SCENE = """[system]
kind = "fixed"
gravity = 9.81
[[body]]
mass = 3.0
A = 0.066
C = 0.05
com = 0.12
spin = 100.0
[body.cavity]
table = "{table}"
viscosity = 1.6e-4
density = 1000.0
scale = 0.04
center = 0.15
{extra}
[initial]
tilt = [[0.02, 0.0]]
rate = [[0.0, 0.0]]
[run]
t_end = 5.0
output_step = {step}
method = "exact"
"""


def tables(args, d):
    modes, fit = os.path.join(d, "cylinder_modes.h5"), os.path.join(d, "cylinder_fit.h5")
    galerkin = os.path.join(d, "cylinder_galerkin.h5")
    if not os.path.exists(modes):
        subprocess.run([args.bin, "cylinder", "--radius", "1", "--height", "2", "--coverage", "0.97", "--ekman", "1e-3",
                        "--no-convergence-check", "-o", modes], check=True, capture_output=True)
    if not os.path.exists(fit):
        subprocess.run([args.bin, "response", "cylinder", "--radius", "1", "--height", "2", "--ekman", "1e-3",
                        "--sigma", "-1.5:2:141", "--fit", "-o", fit], check=True, capture_output=True)
    if not os.path.exists(galerkin):
        subprocess.run([args.bin, "response", "cylinder", "--radius", "1", "--height", "2", "--ekman", "1e-3",
                        "--sigma", "-1.5:2:141", "--galerkin", "-o", galerkin], check=True, capture_output=True)
    return modes, fit, galerkin


def body_roots(args, d, table, extra):
    scene = os.path.join(d, "scene.toml")
    open(scene, "w").write(SCENE.format(table=table, extra=extra, step=0.001))
    out = subprocess.run([args.rom, "spectrum", scene, "--json"], check=True, capture_output=True, text=True).stdout
    roots = [complex(a, b) for a, b in json.loads(out)["roots"] if abs(b) < 1.0]  # the fluid's roots decay fast
    return sorted(roots, key=lambda z: z.real)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--bin", default="build/modes/cavity-modes")
    p.add_argument("--rom", default="build/rom/chain-rom")
    p.add_argument("--tables")
    args = p.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        d = args.tables or tmp
        modes, fit, galerkin = tables(args, d)
        ref = body_roots(args, d, fit, "static_correction = true")
        rows = [{"tank": "response fit", "modes": "", "static_correction": 1, "nutation_re": ref[0].real,
                 "nutation_growth": -ref[0].imag, "precession_re": ref[1].real, "precession_decay": ref[1].imag}]
        for red in ("modal", "galerkin"):
            r = body_roots(args, d, galerkin, 'reduction = "%s"\nstatic_correction = true' % red)
            rows.append({"tank": "Galerkin response table, " + red, "modes": "", "static_correction": 1,
                         "nutation_re": r[0].real, "nutation_growth": -r[0].imag, "precession_re": r[1].real,
                         "precession_decay": r[1].imag})
        for sc in (1, 0):
            for k in (1, 2, 3, 4, 6, 8, 10):
                for red in ("modal", "galerkin"):
                    extra = 'modes = %d\nreduction = "%s"\n%s' % (k, red, "static_correction = true" if sc else "")
                    r = body_roots(args, d, modes, extra)
                    rows.append({"tank": red, "modes": k, "static_correction": sc, "nutation_re": r[0].real,
                                 "nutation_growth": -r[0].imag, "precession_re": r[1].real,
                                 "precession_decay": r[1].imag})
        # The energy balance of runs with Galerkin tanks (ten damped modes; the response table), two output steps.
        for table, extra in ((modes, "modes = 10\n"), (galerkin, "")):
            for step in (0.001, 0.0005):
                scene = os.path.join(d, "scene.toml")
                open(scene, "w").write(SCENE.format(table=table, step=step, extra=extra +
                                                    'reduction = "galerkin"\nstatic_correction = true'))
                out = subprocess.run([args.rom, "run", scene, "-o", os.path.join(d, "run.h5")], capture_output=True,
                                     text=True).stdout
                print("%s, step %g: %s" % (os.path.basename(table), step,
                                           [l for l in out.splitlines() if "Galerkin tanks" in l][0]))
    write_results("galerkin_tanks", rows)
    print("| tank | modes | static corr. | nutation Re σ | growth (1/s) | precession decay (1/s) |")
    print("|---|---|---|---|---|---|")
    for r in rows:
        print("| %s | %s | %s | %.5f | %.6f | %.3e |" % (r["tank"], r["modes"], r["static_correction"], r["nutation_re"],
                                                     r["nutation_growth"], r["precession_decay"]))


if __name__ == "__main__":
    main()
