#!/usr/bin/env python3
"""Plots bench/viscous_bench.py's CSV: decay/Ek^(1/2) against Ek with the boundary-layer limits, and the error of
lambda against run time at Ek = 1e-4.

  /usr/bin/python3 bench/plot_viscous.py bench/results/viscous_2026-11-24.csv -o bench/results/viscous.png"""
import argparse, csv, math
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

LIMIT_DECAY = {"sphere": 2.6204722, "cylinder": 1.447087}  # Im lambda1, tests/modes/test_viscous.cpp


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("csv")
    ap.add_argument("-o", "--output", required=True)
    a = ap.parse_args()
    rows = list(csv.DictReader(open(a.csv)))
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
    for shape, colour in (("sphere", "C0"), ("cylinder", "C1")):
        sweep = [r for r in rows if r["kind"] == "Ek sweep" and r["shape"] == shape]
        ek = [float(r["ek"]) for r in sweep]
        left.semilogx(ek, [float(r["decay"]) / math.sqrt(float(r["ek"])) for r in sweep], "o-", color=colour,
                      label=f"{shape}: full solver (default mesh)")
        left.axhline(LIMIT_DECAY[shape], color=colour, ls="--", label=f"{shape}: boundary-layer limit")
        ladder = [r for r in rows if r["kind"] == "refinement" and r["shape"] == shape and float(r["err"] or 0) > 0]
        right.loglog([float(r["wall"]) for r in ladder], [float(r["err"]) for r in ladder], "o-", color=colour,
                     label=shape)
        for r in ladder:
            right.annotate(r["args"].replace("--order ", "P").replace(" --mesh-size ", ", h ") or "default",
                           (float(r["wall"]), float(r["err"])), fontsize=7, xytext=(4, 4), textcoords="offset points")
    left.set_xlabel("Ekman number")
    left.set_ylabel("decay / Ek^(1/2)")
    left.set_title("damped dominant mode against Greenspan's limit")
    left.legend(fontsize=7)
    right.set_xlabel("wall time of the run [s]")
    right.set_ylabel("relative error of lambda + i decay")
    right.set_title("Ek = 1e-4: error against run time (vs. finest mesh)")
    right.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(a.output, dpi=120)
    print(f"wrote {a.output}")


if __name__ == "__main__":
    main()
