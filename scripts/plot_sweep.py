#!/usr/bin/python3
"""Draws a chain-rom stability map (CSV from `chain-rom sweep ... -o OUT.csv`) as a PNG.

    /usr/bin/python3 scripts/plot_sweep.py SWEEP.csv -o OUT.png [--title TEXT] [--growth]

One swept value: the distance to the threshold (rad/s) against the value: above zero the margin of an unstable
point (largest |Im sigma|), below zero, on a stable point, minus half the gap between the closest real roots of
opposite Krein signature (the CSV's `gap` column: the only roots that can meet and leave the axis). Half, because two
roots s ± g/2 that meet leave as s ± i m: the curve is continuous through a collision and reaches zero where the
verdict changes.
Two: a map over both values, the margin in colour (log scale) on the unstable points, stable points
white, the stability boundary drawn. Points the sweep could not evaluate (nan) are grey.
--growth (chains with friction or viscous tanks, where the margin column is the largest growth rate -Im sigma,
1/s, negative when every root decays; chain-rom sweep --png passes it for such scenes): the growth rate in colour
on every point, red growing, blue decaying, on a symmetric log scale, the stability boundary drawn; over one value,
the growth rate against it, with the mesh error as a bar where the CSV has a margin_error column (confirmed sweeps).
`chain-rom sweep --png` runs this script. Uses Debian's python3-matplotlib and python3-numpy.
"""
import argparse
import os
import sys

import plotting


def draw_growth(fig, ax, np, SymLogNorm, keys, data, stable, growth, error):
    """The largest growth rate (1/s; < 0: every root decays) of a dissipative chain, with its measured mesh error
    as a bar where the sweep made a mesh study."""
    if len(keys) == 1:
        x = data[:, 0]
        ax.plot(x, growth, "-", color="0.3", lw=1)
        if np.isfinite(error).any():
            ax.errorbar(x, growth, yerr=np.where(np.isfinite(error), error, 0), fmt="none", ecolor="0.4", capsize=3,
                        lw=0.8, label="mesh error (confirm's mesh study)")
        ax.plot(x[stable == 0], growth[stable == 0], "o", ms=3, color="tab:red", label="growing (unstable)")
        ax.plot(x[stable == 1], growth[stable == 1], "o", ms=3, color="tab:blue", label="decaying (stable)")
        ax.axhline(0, color="k", lw=0.8)
        ax.set_xlabel(keys[0])
        ax.set_ylabel("largest growth rate −Im σ (1/s)")
        ax.legend(loc="best")
        ax.grid(alpha=0.3)
        return
    x, y = np.unique(data[:, 0]), np.unique(data[:, 1])
    if len(x) * len(y) != len(data):
        raise SystemExit("plot_sweep: error: 2D sweep rows do not form a grid")
    G = growth.reshape(len(x), len(y)).T  # rows: first value outer, second inner
    finite = np.abs(G[np.isfinite(G)])
    ax.set_facecolor("0.75")  # nan: not evaluated
    if finite.size and finite.max() > 0:
        top = finite.max()
        linthresh = top * 1e-3
        im = ax.pcolormesh(x, y, G, cmap="RdBu_r", shading="nearest",
                           norm=SymLogNorm(linthresh=linthresh, vmin=-top, vmax=top, base=10))
        # Ticks at 0 and at the decades at least ten times the linear range's edge: matplotlib's own put ±linthresh
        # beside 0, their labels overlapping.
        decades = [10.0 ** k for k in range(int(np.ceil(np.log10(10 * linthresh))), int(np.floor(np.log10(top))) + 1)]
        ticks = sorted([-d for d in decades] + [0.0] + decades)
        fig.colorbar(im, ax=ax, ticks=ticks, label="largest growth rate −Im σ (1/s): red grows, blue decays")
    S = stable.reshape(len(x), len(y)).T
    if len(x) > 1 and len(y) > 1 and np.nanmin(S) < 1 <= np.nanmax(S):  # growth within the tolerance is stable
        ax.contour(x, y, np.nan_to_num(S, nan=0.5), levels=[0.5], colors="k", linewidths=1.2)
    ax.set_xlabel(keys[0])
    ax.set_ylabel(keys[1])
    ax.text(0.01, 0.01, "black: stability boundary (growth within the verdict's tolerance); grey: not evaluated", transform=ax.transAxes, fontsize=8, va="bottom")


def draw_distance(ax, np, keys, x, stable, margin, gap):
    """An undamped chain's distance to the threshold: +|Im σ| where unstable, −gap/2 where stable."""
    uns = stable == 0
    distance = np.where(uns, margin, -0.5 * gap)
    ax.plot(x, distance, "-", color="0.3", lw=1)
    ax.plot(x[uns], distance[uns], "o", ms=3, color="tab:red", label="unstable: largest |Im σ|")
    ax.plot(x[stable == 1], distance[stable == 1], "o", ms=3, color="tab:green",
            label="stable: −½ gap of the closest real roots of opposite Krein signature")
    ax.axhline(0, color="k", lw=0.8)
    ax.set_xlabel(keys[0])
    ax.set_ylabel("distance to the threshold (rad/s)")
    ax.legend(loc="best", fontsize=8)
    ax.grid(alpha=0.3)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("csv", help="CSV written by chain-rom sweep")
    ap.add_argument("-o", "--output", dest="png", required=True, help="PNG to write")
    ap.add_argument("--title", default=None, help="figure title (default: the CSV's file name)")
    ap.add_argument("--growth", action="store_true", help="the margin column is a growth rate (dissipative chains)")
    args = ap.parse_args()
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        from matplotlib.colors import LogNorm, SymLogNorm
        import numpy as np
    except ImportError as e:
        print(f"plot_sweep: error: {e} (apt-get install python3-matplotlib python3-numpy)", file=sys.stderr)
        return 2

    try:
        with open(args.csv) as f:
            header = f.readline().strip().split(",")
        data = np.genfromtxt(args.csv, delimiter=",", skip_header=1, ndmin=2)
        # the roots' sweeps end in gap, confirmed sweeps in their mesh study's margin_error,mesh_converged
        tail = {"gap": 4, "mesh_converged": 5}.get(header[-1], 3)
        if header[-tail:][:3] != ["stable", "margin", "nonreal"] or len(header) - tail not in (1, 2):
            raise ValueError("not a chain-rom sweep CSV (header must end in stable,margin,nonreal"
                             "[,gap | ,margin_error,mesh_converged])")
        if data.size == 0 or data.shape[1] != len(header):
            raise ValueError("no rows, or rows do not match the header")
    except (OSError, ValueError) as e:
        print(f"plot_sweep: error: {args.csv}: {e}", file=sys.stderr)
        return 1

    keys = header[:-tail]
    stable, margin = data[:, -tail], data[:, 1 - tail]
    gap = data[:, -1] if tail == 4 else np.full(len(data), np.nan)
    error = data[:, -2] if tail == 5 else np.full(len(data), np.nan)  # the growth rate's mesh error
    title = args.title or os.path.basename(args.csv)
    fig, ax = plt.subplots(figsize=(7, 5), dpi=110)
    if args.growth:
        draw_growth(fig, ax, np, SymLogNorm, keys, data, stable, margin, error)
    elif len(keys) == 1:
        draw_distance(ax, np, keys, data[:, 0], stable, margin, gap)
    else:
        x, y = np.unique(data[:, 0]), np.unique(data[:, 1])
        if len(x) * len(y) != len(data):
            print(f"plot_sweep: error: {args.csv}: 2D sweep rows do not form a grid", file=sys.stderr)
            return 1
        # rows: first value outer, second inner
        S = stable.reshape(len(x), len(y)).T
        Mg = margin.reshape(len(x), len(y)).T
        shown = np.where(S == 0, Mg, np.nan)
        ax.set_facecolor("0.75")  # nan: not evaluated
        ax.pcolormesh(x, y, np.where(S == 1, 1.0, np.nan), cmap="Greys", vmin=0, vmax=100, shading="nearest")
        pos = shown[np.isfinite(shown) & (shown > 0)]
        if pos.size:
            im = ax.pcolormesh(x, y, np.where(shown > 0, shown, np.nan), cmap="magma_r", shading="nearest",
                               norm=LogNorm(vmin=pos.min(), vmax=pos.max()))
            fig.colorbar(im, ax=ax, label="margin of unstable points: largest |Im σ| (rad/s)")
        if len(x) > 1 and len(y) > 1 and np.nanmin(S) < 1 <= np.nanmax(S):
            ax.contour(x, y, np.nan_to_num(S, nan=0.5), levels=[0.5], colors="tab:blue", linewidths=1.2)
        ax.set_xlabel(keys[0])
        ax.set_ylabel(keys[1])
        ax.text(0.01, 0.01, "white: stable; colour: unstable (margin); blue: boundary; grey: not evaluated",
                transform=ax.transAxes, fontsize=8, va="bottom")
    ax.set_title(title)
    fig.tight_layout()
    return plotting.save(fig, args.png, "plot_sweep")


if __name__ == "__main__":
    sys.exit(main())
