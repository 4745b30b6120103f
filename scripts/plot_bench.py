#!/usr/bin/python3
"""Draws a chain-rom benchmark (CSV from `chain-rom bench SCENE -o OUT.csv`) as a PNG.

    /usr/bin/python3 scripts/plot_bench.py BENCH.csv -o OUT.png [--title TEXT]

Left: work-precision, the relative error of the state at t_end against wall time, one line per
integrator (gauss over its step sweep, rk45 over its tolerance sweep, exact as one point; the long
double reference's own error as a horizontal line). Middle and right: the error of the roots owned by
the bodies against the number of kept modes of one cavity, with (solid) and without (dashed) static
correction, at the scene's spins and at zero spin (Zhukovsky's case); errors of exactly 0 are drawn at
the bottom edge. `chain-rom bench --png` runs this script. Uses Debian's
python3-matplotlib and python3-numpy.
"""
import argparse
import csv
import math
import os
import sys

import plotting

COLUMNS = ["part", "method", "parameter", "value", "steps", "body", "static_correction", "spin_factor",
           "coverage", "wall_seconds", "cpu_seconds", "error"]
FLOOR = 1e-17  # where exact zeros are drawn on the log axes


def num(s):
    return float(s) if s not in ("", None) else math.nan


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("csv", help="CSV written by chain-rom bench")
    ap.add_argument("-o", "--output", dest="png", required=True, help="PNG to write")
    ap.add_argument("--title", default=None, help="figure title (default: the CSV's file name)")
    args = ap.parse_args()
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError as e:
        print(f"plot_bench: error: {e} (apt-get install python3-matplotlib)", file=sys.stderr)
        return 2
    try:
        with open(args.csv, newline="") as f:
            reader = csv.DictReader(f)
            if reader.fieldnames != COLUMNS:
                raise ValueError("not a chain-rom bench CSV (header must be " + ",".join(COLUMNS) + ")")
            rows = list(reader)
        if not rows:
            raise ValueError("no rows")
    except (OSError, ValueError) as e:
        print(f"plot_bench: error: {args.csv}: {e}", file=sys.stderr)
        return 1

    work = [r for r in rows if r["part"] == "work"]
    roots = [r for r in rows if r["part"] == "roots"]
    fig, (ax1, ax2, ax3) = plt.subplots(1, 3, figsize=(17, 5.4), dpi=100)

    colours = {"exact": "black", "gauss": "tab:blue", "rk45": "tab:orange", "magnus": "tab:purple"}
    for method in ("gauss", "rk45", "exact", "magnus"):
        pts = [(num(r["wall_seconds"]), max(num(r["error"]), FLOOR), r) for r in work if r["method"] == method]
        if not pts:
            continue
        x, y = [p[0] for p in pts], [p[1] for p in pts]
        ax1.plot(x, y, "o-" if method != "exact" else "s", color=colours[method], ms=5 if method != "exact" else 8,
                 label={"exact": "exact (double)", "gauss": "gauss: step sweep",
                        "rk45": "rk45: tolerance sweep", "magnus": "magnus (two spins): step sweep"}[method])
        for xi, yi, r in pts:
            if method == "rk45":
                ax1.annotate(f"{num(r['value']):.0e}", (xi, yi), fontsize=6, xytext=(3, 3), textcoords="offset points")
            elif method in ("gauss", "magnus"):
                ax1.annotate(f"h={num(r['value']):.1e}", (xi, yi), fontsize=6, xytext=(3, -9),
                             textcoords="offset points")
    ref = [r for r in work if r["method"] == "reference" and r["parameter"] in ("method_difference", "magnus_difference")]
    if ref:
        ax1.axhline(max(num(ref[0]["error"]), FLOOR), color="tab:green", ls=":", lw=1.2,
                    label="reference: long double eig vs expm" if ref[0]["parameter"] == "method_difference"
                    else "reference: Magnus, 4 vs 2 times the steps")
    ax1.set_xscale("log")
    ax1.set_yscale("log")
    ax1.set_xlabel("wall time (s, best of repeated runs)")
    ax1.set_ylabel("relative error of the state at t_end")
    ax1.set_title("work-precision")
    ax1.grid(alpha=0.3, which="both")
    ax1.legend(loc="best", fontsize=8)

    bodies = sorted({int(r["body"]) for r in roots})
    palette = ["tab:blue", "tab:red", "tab:purple", "tab:brown", "tab:olive", "tab:cyan"]
    for ax, factor, what in ((ax2, "1", "at the scene's spins"), (ax3, "0", "at zero spin (Zhukovsky)")):
        drawn = False
        for i, b in enumerate(bodies):
            for corr, style in (("1", "o-"), ("0", "s--")):
                pts = sorted((num(r["value"]), max(num(r["error"]), FLOOR), num(r["coverage"])) for r in roots
                             if int(r["body"]) == b and r["spin_factor"] == factor and r["static_correction"] == corr)
                if not pts:
                    continue
                drawn = True
                ax.plot([p[0] for p in pts], [p[1] for p in pts], style, color=palette[i % len(palette)], ms=4,
                        lw=1.2, label=f"body {b}, " + ("static correction" if corr == "1" else "no correction"))
                if corr == "0":
                    for x, y, c in pts:
                        ax.annotate(f"{c:.2f}", (x, y), fontsize=6, xytext=(2, 4), textcoords="offset points",
                                    color=palette[i % len(palette)])
        if drawn:
            ax.set_xscale("log", base=2)
            ax.set_yscale("log")
            ax.axhline(FLOOR, color="0.6", lw=0.8)
            ax.text(0.01, 0.02, "exactly 0 drawn at 1e-17; labels: coverage", transform=ax.transAxes, fontsize=7,
                    color="0.4")
            ax.legend(loc="center left", fontsize=7)
        else:
            # The chain without axial symmetry benches its roots at the scene's spin only (docs/rom.md, "Benchmark").
            why = ("not computed (no row at zero spin)" if factor == "0" and any(r["spin_factor"] == "1" for r in roots)
                   else "no cavity with more than one coupling mode")
            ax.text(0.5, 0.5, why, ha="center", transform=ax.transAxes)
        ax.set_xlabel("modes kept (of one cavity; the others keep all)")
        ax.set_ylabel("largest relative error of the body roots")
        ax.set_title("body roots " + what, fontsize=10)
        ax.grid(alpha=0.3, which="both")

    fig.suptitle(args.title or os.path.basename(args.csv))
    fig.tight_layout()
    return plotting.save(fig, args.png, "plot_bench")


if __name__ == "__main__":
    sys.exit(main())
