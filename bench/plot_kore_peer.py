#!/usr/bin/env python3
"""Error against run time of the spin-over mode's decay, Kore and cavity-modes side by side (bench/kore_peer.sh's CSV):
one panel per cavity, one colour per Ekman number, circles for Kore, diamonds for cavity-modes' spectral method
(`cavity-modes shell`), squares for its finite elements. A run that is its own reference (the CSV's reference column)
has no error and is marked, open, at the panel's floor.

Usage: plot_kore_peer.py CSV PNG
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

rows = list(csv.DictReader(open(sys.argv[1])))
shapes = sorted({r["setting"].split(";")[0] for r in rows})
ekmans = sorted({r["ekman"] for r in rows}, key=float, reverse=True)
colours = dict(zip(ekmans, plt.rcParams["axes.prop_cycle"].by_key()["color"]))
fig, axes = plt.subplots(1, len(shapes), figsize=(6 * len(shapes), 4.5), squeeze=False)
for ax, shape in zip(axes[0], shapes):
    floor = 1e-16
    for r in rows:
        if r["setting"].split(";")[0] != shape:
            continue
        err = float(r["decay_error"]) if r["decay_error"] else 0.0
        spectral = r["code"] != "kore" and "spectral" in r["setting"]
        marker = "o" if r["code"] == "kore" else "D" if spectral else "s"
        name = "cavity-modes shell" if spectral else "cavity-modes FE" if r["code"] != "kore" else "Kore"
        ax.loglog(float(r["seconds"]), max(err, floor), marker, color=colours[r["ekman"]], mfc="none" if err == 0 else None,
                  label=f"{name}, Ek {r['ekman']}")
    handles, labels = ax.get_legend_handles_labels()
    unique = dict(zip(labels, handles))
    ax.legend(unique.values(), unique.keys(), fontsize=7)
    ax.set_xlabel("run time (s, whole process, this machine)")
    ax.set_ylabel("relative error of the spin-over decay")
    ax.set_title(f"{shape}: Kore (circles), cavity-modes shell (diamonds), its finite elements (squares)", fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=120)
print(f"wrote {sys.argv[2]}")
