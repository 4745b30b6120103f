#!/usr/bin/env python3
"""Error against run time of the nonlinear chain's integrator (docs/rom.md, "Nonlinear chain"; docs/benchmarks.md):
a scene (default data/scenes/nonlinear_chain.toml: three spinning bodies released at 17 degrees) run for 10 s by
`chain-rom run` with [run] model = "nonlinear" at tolerances 1e-4 ... 1e-12; the error is the largest difference of
the tilts u_k over the run from a reference at tolerance 1e-14 (1e-13 with --fast-reference), the time is chain-rom's
own integration time (best of three). A linear scene is turned nonlinear (its `method` dropped), and --tilt sets a
common initial tilt.

  /usr/bin/python3 bench/nonlinear_work_precision.py [--bin build/rom/chain-rom] [--scene S] [--tilt 0.3]
      [--tolerances 1e-8,1e-10] [--name STEM] [-o PNG]

Writes bench/results/<STEM>_<date>.csv (default STEM nonlinear_work_precision) and the PNG (default
bench/results/<STEM>.png)."""
import argparse, os, re, subprocess, sys, tempfile

import h5py
import numpy as np

from results_csv import write_results

TOLERANCES = [1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12]


def run(binary, scene_text, tol, folder):
    scene = os.path.join(folder, "scene_%g.toml" % tol)
    out = os.path.join(folder, "out_%g.h5" % tol)
    with open(scene, "w") as f:
        f.write(re.sub(r"(?m)^tolerance = .*$", "tolerance = %r" % tol, scene_text))
    best = None
    for _ in range(3):
        p = subprocess.run([binary, "run", scene, "-o", out], capture_output=True, text=True)
        if p.returncode:
            sys.exit(p.stderr.strip())
        seconds = float(re.search(r"rejected\), ([0-9.e+-]+) s", p.stdout).group(1))
        steps = int(re.search(r", (\d+) steps", p.stdout).group(1))
        best = seconds if best is None else min(best, seconds)
    with h5py.File(out) as f:
        u = f["u_re"][()] + 1j * f["u_im"][()]
    return u, best, steps


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--bin", default="build/rom/chain-rom")
    ap.add_argument("--scene", default="data/scenes/nonlinear_chain.toml")
    ap.add_argument("--tilt", type=float, default=None)
    ap.add_argument("--tolerances", default=",".join("%g" % t for t in TOLERANCES))
    ap.add_argument("--fast-reference", action="store_true")
    ap.add_argument("--name", default="nonlinear_work_precision")
    ap.add_argument("-o", dest="png", default=None)
    args = ap.parse_args()
    png = args.png or "bench/results/%s.png" % args.name
    text = open(args.scene).read()
    folder = os.path.dirname(os.path.abspath(args.scene))
    text = re.sub(r'(?m)^table = "([^"]+)"', lambda m: 'table = "%s"' % os.path.join(folder, m.group(1)), text)
    text = re.sub(r"(?m)^method = .*\n", "", text)
    text = re.sub(r"(?m)^t_end = .*$", "t_end = 10.0", text)
    text = re.sub(r"(?m)^output_step = .*$", "output_step = 0.01", text)
    if not re.search(r"(?m)^model = ", text):
        text = text.replace("[run]\n", "[run]\nmodel = \"nonlinear\"\n")
    if not re.search(r"(?m)^tolerance = ", text):
        text = text.replace("[run]\n", "[run]\ntolerance = 1e-10\n")
    if args.tilt is not None:
        n = len(re.findall(r"(?m)^\[\[body\]\]", text))
        text = re.sub(r"(?m)^tilt = .*$", "tilt = [%s]" % ", ".join(["[%r, 0.0]" % args.tilt] * n), text)
    with tempfile.TemporaryDirectory() as d:
        reference, ref_seconds, ref_steps = run(args.bin, text, 1e-13 if args.fast_reference else 1e-14, d)
        rows = []
        for tol in [float(x) for x in args.tolerances.split(",")]:
            u, seconds, steps = run(args.bin, text, tol, d)
            err = float(np.max(np.abs(u - reference)))
            rows.append({"tolerance": tol, "steps": steps, "seconds": seconds, "max_tilt_error_rad": err})
            print("tolerance %.0e: %7d steps, %.4f s, max |u - u_ref| = %.2e rad" % (tol, steps, seconds, err))
    print("reference: %d steps, %.3f s" % (ref_steps, ref_seconds))
    write_results(args.name, rows)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4.2), constrained_layout=True)
    ax.loglog([r["seconds"] for r in rows], [r["max_tilt_error_rad"] for r in rows], "o-")
    for r in rows:
        ax.annotate("%.0e" % r["tolerance"], (r["seconds"], r["max_tilt_error_rad"]), fontsize=7,
                    textcoords="offset points", xytext=(4, 2))
    ax.set_xlabel("integration time (s, 2-core machine)")
    ax.set_ylabel("max |u - u_ref| over 10 s (rad)")
    ax.set_title("nonlinear chain, RKMK4 with step doubling and extrapolation\n(%s, 10 s)" % args.scene, fontsize=9)
    ax.grid(True, which="both", lw=0.3)
    fig.savefig(png, dpi=130)
    print("wrote", png)


if __name__ == "__main__":
    main()
