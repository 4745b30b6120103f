#!/usr/bin/env python3
"""Error against run time: the rational fit of R(s) against the Galerkin response table (docs/viscous.md, "Response
fit" and "Galerkin response table"), both made by cavity-modes from the same forced solves on the same mesh.

  /usr/bin/python3 bench/galerkin_response_bench.py [--bin build/modes/cavity-modes] [--shape sphere|cylinder]

For N = 11, 21, 41, 81 samples of s in [-1.5, 2] at Ek = 1e-3 (default mesh, P6) each table's own error between its
samples (the fit: max |fit - R| on the held-out odd samples; the Galerkin table: on forced solves at every midpoint),
both over max|R|, an independent error at 7 points that neither saw (forced solves here), the number of poles or
Ritz pairs, whether the table is passive on [-3, 4], and the wall time. Both are made with --max-fit-error 1, so
that they report their error instead of refining (the fit) or failing (the Galerkin table). Writes bench/results/galerkin_response_bench_<date>.csv."""
import argparse, os, subprocess, tempfile, time

import h5py
import numpy as np

from results_csv import write_results

PROBES = [-1.37, -0.61, 0.23, 0.88, 1.02, 1.33, 1.87]
SHAPES = {"sphere": ["sphere", "--radius", "1"], "cylinder": ["cylinder", "--radius", "1", "--height", "2"]}


def table_response(path, s):
    f = h5py.File(path, "r")
    lam = f["modes/lambda"][:] + 1j * f["modes/decay"][:]
    E = f["modes/E"][:] + 1j * f["modes/E_imag"][:]
    return np.array([np.sum(E / (x - lam)) for x in s]), len(lam), f.attrs["fit_error"]


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--bin", default="build/modes/cavity-modes")
    p.add_argument("--shape", default="sphere", choices=sorted(SHAPES))
    args = p.parse_args()
    shape = SHAPES[args.shape]
    rows = []
    with tempfile.TemporaryDirectory() as d:
        probe = os.path.join(d, "probe.csv")
        subprocess.run([args.bin, "response", *shape, "--ekman", "1e-3", "--sigma", ",".join(map(str, PROBES)),
                        "-o", probe], check=True, capture_output=True)
        data = np.loadtxt(probe, delimiter=",", comments="#", skiprows=3)
        R = data[:, 2] + 1j * data[:, 3]
        for n in (11, 21, 41, 81):
            for kind in ("fit", "galerkin"):
                out = os.path.join(d, "%s_%d.h5" % (kind, n))
                cmd = [args.bin, "response", *shape, "--ekman", "1e-3", "--sigma", "-1.5:2:%d" % n, "-o", out]
                cmd += ["--max-fit-error", "1"] + (["--galerkin"] if kind == "galerkin" else ["--fit"])
                t0 = time.time()
                subprocess.run(cmd, check=True, capture_output=True)
                seconds = time.time() - t0
                Rt, count, own = table_response(out, PROBES)
                grid = np.linspace(-3, 4, 7001)
                Rg, _, _ = table_response(out, grid)
                rows.append({"shape": args.shape, "samples": n, "table": kind, "poles": count, "own_error": own,
                             "probe_error": float(np.max(np.abs(Rt - R)) / np.max(np.abs(R))),
                             "min_im_R_over_max": float(np.min(Rg.imag) / np.max(np.abs(Rg))),
                             "wall_seconds": round(seconds, 1)})
                print(rows[-1], flush=True)
    out = write_results("galerkin_response_bench_" + args.shape, rows)
    plot(rows, out.replace(".csv", ".png"))


def plot(rows, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4))
    for kind, label in (("fit", "rational fit (AAA)"), ("galerkin", "Galerkin response table")):
        r = [x for x in rows if x["table"] == kind]
        ax.loglog([x["wall_seconds"] for x in r], [x["probe_error"] for x in r], "o-", label=label)
        for x in r:
            ax.annotate("N=%d" % x["samples"], (x["wall_seconds"], x["probe_error"]), fontsize=7)
    ax.set_xlabel("wall time (s, 2 cores' machine, serial)")
    ax.set_ylabel("max |R_table - R| / max |R| at 7 unseen points")
    ax.set_title("%s, Ek = 1e-3: response tables, error against run time" % rows[0]["shape"])
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(png, dpi=120)
    print("wrote", png)


if __name__ == "__main__":
    main()
