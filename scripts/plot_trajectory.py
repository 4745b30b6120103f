#!/usr/bin/python3
"""Draws a chain-rom time history (HDF5 from `chain-rom run ... -o OUT.h5`) as a PNG.

    /usr/bin/python3 scripts/plot_trajectory.py HISTORY.h5 -o OUT.png [--title TEXT]

Left: the path of each body's axis in the tilt plane (alpha_k, beta_k), from u_k = beta_k - i alpha_k
(Krylov angles), in degrees. Right, top: tilt magnitude |u_k|(t). Right, bottom: relative drift of the
quadratic integral H(t) (docs/rom.md, "Energy"). Uses Debian's python3-h5py/python3-matplotlib.
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import h5py  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("history", help="HDF5 written by chain-rom run")
    ap.add_argument("-o", "--output", dest="png", required=True, help="PNG to write")
    ap.add_argument("--title", default=None, help="figure title (default: the history's file name)")
    args = ap.parse_args()

    try:
        with h5py.File(args.history, "r") as f:
            if f.attrs.get("format", b"") not in (b"chain-rom-history", "chain-rom-history"):
                raise ValueError("not a chain-rom history (attribute format != chain-rom-history)")
            t = f["t"][()]
            u = f["u_re"][()] + 1j * f["u_im"][()]
            energy = f["energy"][()] if "energy" in f else None
            # With viscous tanks: the frozen chain's energy budget (docs/rom.md, "Energy budget").
            budget = {k: f[k][()] for k in ("frozen_energy", "fluid_work") if k in f}
            # The nonlinear model's history (docs/rom.md, "Nonlinear chain"): attitudes and spins as well.
            quat = f["quaternion"][()] if "quaternion" in f else None
            spin = f["spin"][()] if "spin" in f else None
            method = f.attrs.get("method", b"")
            method = method.decode() if isinstance(method, bytes) else str(method)
    except (OSError, KeyError, ValueError) as e:
        print(f"plot_trajectory: error: {args.history}: {e}", file=sys.stderr)
        return 1

    n = u.shape[1]
    nonlinear = quat is not None and spin is not None
    if nonlinear:
        # Body axis n = R e3 from the quaternion (w, x, y, z), drawn in the equal-area (Lambert) projection seen from
        # above, which keeps large angles honest: radius 2 sin(theta/2), theta the tilt from the vertical.
        q = quat.reshape(len(t), n, 4)
        w, x, y, z = q[..., 0], q[..., 1], q[..., 2], q[..., 3]
        nx, ny, nz = 2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)
        theta = np.arccos(np.clip(nz, -1, 1))
        scale = np.where(theta > 1e-12, 2 * np.sin(theta / 2) / np.maximum(np.hypot(nx, ny), 1e-300), 1.0)
        px, py = np.degrees(nx * scale), np.degrees(ny * scale)
        tilt_deg = np.degrees(theta)
    else:
        px, py = np.degrees(-u.imag), np.degrees(u.real)  # alpha_k, beta_k
        tilt_deg = np.degrees(np.abs(u))

    fig = plt.figure(figsize=(12, 7.5 if nonlinear else 5.5), constrained_layout=True)
    rows = 3 if nonlinear else 2
    gs = fig.add_gridspec(rows, 2, width_ratios=[1.0, 1.4])
    ax_path = fig.add_subplot(gs[:, 0])
    ax_tilt = fig.add_subplot(gs[0, 1])
    ax_spin = fig.add_subplot(gs[1, 1], sharex=ax_tilt) if nonlinear else None
    ax_energy = fig.add_subplot(gs[rows - 1, 1], sharex=ax_tilt)

    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for k in range(n):
        c = colors[k % len(colors)]
        ax_path.plot(px[:, k], py[:, k], lw=0.6, color=c, label=f"body {k + 1}")
        ax_path.plot(px[0, k], py[0, k], "o", color=c, ms=5)
        ax_tilt.plot(t, tilt_deg[:, k], lw=0.6, color=c, label=f"body {k + 1}")
        if nonlinear:
            ax_spin.plot(t, spin[:, k] - spin[0, k], lw=0.6, color=c, label=f"body {k + 1}")
    ax_path.plot([], [], "ko", ms=5, label="t = 0")
    if nonlinear:
        ax_path.set_xlabel(r"$n_x$, equal-area (deg at small tilt)")
        ax_path.set_ylabel(r"$n_y$, equal-area (deg at small tilt)")
        ax_path.set_title("body axes seen from above (Lambert projection)")
        ax_tilt.set_ylabel("tilt from the vertical (deg)")
        ax_spin.set_ylabel(r"spin $-$ spin(0) (rad/s)")
        ax_spin.set_title(r"spins $\Omega_k\cdot n_k$")
        ax_spin.grid(True, lw=0.3)
        plt.setp(ax_spin.get_xticklabels(), visible=False)
    else:
        ax_path.set_xlabel(r"$\alpha_k$ (deg)")
        ax_path.set_ylabel(r"$\beta_k$ (deg)")
        ax_path.set_title(r"axis paths, $u_k = \beta_k - i\alpha_k$")
        ax_tilt.set_ylabel(r"$|u_k|$ (deg)")
    ax_path.set_aspect("equal", adjustable="datalim")
    ax_path.grid(True, lw=0.3)
    ax_path.legend(loc="best", fontsize=8)

    ax_tilt.set_title("tilt magnitude")
    ax_tilt.grid(True, lw=0.3)
    ax_tilt.legend(loc="upper right", fontsize=8)
    plt.setp(ax_tilt.get_xticklabels(), visible=False)

    if energy is not None and np.all(np.isfinite(energy)) and energy[0] != 0:
        ax_energy.plot(t, (energy - energy[0]) / abs(energy[0]), lw=0.6, color="k")
        ax_energy.set_ylabel(r"$(H - H_0)/|H_0|$")
        ax_energy.ticklabel_format(axis="y", style="sci", scilimits=(-3, 3))
        title_energy = "energy change (friction, moments)" if nonlinear else "quadratic integral drift"
    elif len(budget) == 2:
        hb = budget["frozen_energy"]
        ax_energy.plot(t, hb - hb[0], lw=0.8, color="k", label=r"$H_b - H_b(0)$ (fluid frozen)")
        ax_energy.plot(t, -budget["fluid_work"], lw=0.8, ls="--", color="tab:blue",
                       label=r"$-W$: work given by the fluid")
        ax_energy.set_ylabel("J")
        ax_energy.ticklabel_format(axis="y", style="sci", scilimits=(-3, 3))
        ax_energy.legend(loc="best", fontsize=8)
        title_energy = "energy budget with viscous tanks"
    else:
        ax_energy.text(0.5, 0.5, "energy not available", ha="center", va="center",
                       transform=ax_energy.transAxes)
        title_energy = "quadratic integral drift"
    ax_energy.set_xlabel("t (s)")
    ax_energy.set_title(title_energy)
    ax_energy.grid(True, lw=0.3)

    title = args.title or os.path.basename(args.history)
    fig.suptitle(f"{title}  ({n} bodies, {len(t)} samples, {method})", fontsize=10)

    tmp = args.png + ".tmp.png"
    try:
        fig.savefig(tmp, dpi=130)
        os.replace(tmp, args.png)
    except OSError as e:
        if os.path.exists(tmp):
            os.remove(tmp)
        print(f"plot_trajectory: error: {args.png}: {e}", file=sys.stderr)
        return 1
    print(f"plot_trajectory: wrote {args.png}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
