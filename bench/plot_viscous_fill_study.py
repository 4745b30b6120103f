#!/usr/bin/env python3
"""The viscous fill study's rows (bench/results/viscous_fill_study.csv, from bench/viscous_fill_study.sh) as one plot:
for each tank, fill and Ekman number with a reference, the relative distance of `spectrum`'s decay (the table) and of
`confirm`'s (with its bar) from the reference, against the 2 % the verdict uses. The latest row of each case is taken;
rows whose confirm or reference gave no decay are left out.

    python3 bench/plot_viscous_fill_study.py [CSV] [PNG]   (default docs/figures/viscous_fill_study.png)
"""
import csv
import math
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
src = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "bench/results/viscous_fill_study.csv")
dst = sys.argv[2] if len(sys.argv) > 2 else os.path.join(root, "docs/figures/viscous_fill_study.png")


def number(text):
    try:
        v = float(text)
        return v if math.isfinite(v) else None
    except ValueError:
        return None


# The 80 %-full cylinder's row predates the script's reading of the body's root: its spectrum column is the verdict's
# slowest root, a fluid one (docs/trust.md), so it is not drawn; the full capsule's is the first of three body roots
# near the nutation, not the one confirm follows (docs/trust.md, "Sections at Ek = 1e-6").
NO_TABLE_VALUE = {("cylinder", 0.8, 1e-6), ("section capsule.geo", 1.0, 1e-6)}
latest = {}
for r in csv.DictReader(open(src)):
    ref, conf = number(r["reference_decay"]), number(r["confirm_decay"])
    if ref is None or conf is None:
        continue
    shape = r["shape"].split()[0] + (" ring" if "--inner-radius" in r["shape"] else "")
    if shape == "section":  # the section's file name
        shape += " " + os.path.basename(r["shape"].split()[1])
    key = (shape, float(r["fill"]), float(r["ekman"]))
    latest[key] = dict(r, ref=ref, conf=conf, bar=number(r["confirm_bar"]) or 0, spec=number(r["spectrum_decay"]),
                       flag=r["confirm_flag"])
cases = sorted(latest, key=lambda k: (k[2], k[0], -k[1]), reverse=True)
fig, ax = plt.subplots(figsize=(max(11, 0.26 * len(cases)), 5.2))  # room for every label
for i, k in enumerate(cases):
    c = latest[k]
    d = abs(c["conf"] - c["ref"]) / c["ref"]
    ax.errorbar(i, max(d, 1e-6), yerr=[[0], [c["bar"] / c["ref"]]], fmt="o", color="C0" if c["flag"] == "converged" else "C3",
                capsize=3, label="confirm (bar up), converged" if i == 0 else None)
    if c["spec"] and k not in NO_TABLE_VALUE:
        ax.plot(i, max(abs(c["spec"] - c["ref"]) / c["ref"], 1e-6), "x", color="C1",
                label="spectrum (the table)" if i == 0 else None)
ax.plot([], [], "o", color="C3", label="confirm, NOT CONVERGED")
ax.axhline(0.02, color="k", ls="--", lw=0.8, label="2 %: the verdict's tolerance")
ax.set_yscale("log")
ax.set_xticks(range(len(cases)))
ax.set_xticklabels(["%s %g%%, Ek %g" % (s, 100 * f, e) for s, f, e in cases], rotation=90, fontsize=7)
ax.set_ylabel("|decay - reference| / reference")
ax.set_title("Nutation decay of the spacecraft's tank against a finer reference (default commands)")
ax.legend(fontsize=8, loc="lower right", ncol=2)
fig.tight_layout()
os.makedirs(os.path.dirname(dst), exist_ok=True)
fig.savefig(dst, dpi=110)
print("%d cases -> %s" % (len(cases), dst))
