#!/usr/bin/python3
"""Draws a chain-rom frequency response (CSV from `chain-rom response ... -o OUT.csv`) as a Bode plot (PNG).

    /usr/bin/python3 scripts/plot_response.py RESPONSE.csv -o OUT.png [--title TEXT]

Top: each body's tilt per unit moment |u_k| (rad per N m, log scale) against the moment's frequency sigma (rad/s);
bottom: its phase (degrees). A chain without axial symmetry adds each body's mirror tilt |A-| at -sigma - 2 spin
(dashed, the columns mirror_abs_k), and at two spins the root mean square of the tilt at every other frequency
(dotted, sideband_rms_k). The resonances (real parts of the chain's roots, the CSV's "# resonance" lines) are
marked by vertical lines: grey for decaying or neutral roots, red for growing ones. `chain-rom response --png` runs
this script. Uses Debian's python3-matplotlib and python3-numpy.
"""
import os
import sys

import plotting


def read(path, np):
    resonances = []
    with open(path) as f:
        for line in f:
            if line.startswith("# resonance"):
                parts = line.split()
                resonances.append((float(parts[2]), float(parts[4])))
            elif not line.startswith("#"):
                header = line.strip().split(",")
                break
        else:
            raise ValueError("no header")
    bodies = sum(1 for h in header if h.startswith("abs_"))
    if header[0] != "sigma" or bodies == 0 or any(f"phase_deg_{k}" not in header for k in range(1, bodies + 1)):
        raise ValueError("not a chain-rom response CSV (header sigma,abs_1,phase_deg_1,...)")
    data = np.genfromtxt(path, delimiter=",", comments="#", skip_header=0, names=None, ndmin=2)
    data = data[~np.isnan(data[:, 0])]  # the header line reads as nan
    if data.size == 0 or data.shape[1] != len(header):
        raise ValueError("no rows, or rows do not match the header")
    return header, data, resonances


def main() -> int:
    args = plotting.parse_args(__doc__, "response")
    plt, np = plotting.pyplot("plot_response")
    if plt is None:
        return 2
    try:
        header, data, resonances = read(args.csv, np)
    except (OSError, ValueError) as e:
        print(f"plot_response: error: {args.csv}: {e}", file=sys.stderr)
        return 1
    sigma = data[:, 0]
    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(8, 6), dpi=110)
    column = {h: i for i, h in enumerate(header)}
    for k in range(1, sum(1 for h in header if h.startswith("abs_")) + 1):
        line, = top.semilogy(sigma, data[:, column[f"abs_{k}"]], lw=1.2, label=f"body {k}")
        phase = data[:, column[f"phase_deg_{k}"]]
        # A real negative tilt (a conservative chain) sits at ±180° by the sign of a rounding-sized imaginary part.
        bottom.plot(sigma, np.where(phase <= -179.999, 180.0, phase), lw=1.0, color=line.get_color())
        if f"mirror_abs_{k}" in column:
            top.semilogy(sigma, data[:, column[f"mirror_abs_{k}"]], lw=0.9, ls="--", color=line.get_color(),
                         label=f"body {k}, mirror |A-|")
        if f"sideband_rms_{k}" in column:
            top.semilogy(sigma, data[:, column[f"sideband_rms_{k}"]], lw=0.9, ls=":", color=line.get_color(),
                         label=f"body {k}, sidebands (rms)")
    for s, growth in resonances:
        for ax in (top, bottom):
            ax.axvline(s, color="tab:red" if growth > 0 else "0.6", lw=0.7, ls="--", zorder=0)
    top.set_ylabel("|u| per unit moment (rad/(N m))")
    top.legend(loc="best", fontsize=8)
    top.grid(alpha=0.3, which="both")
    bottom.set_ylabel("phase (degrees)")
    bottom.set_xlabel("σ of the moment F e^{iσt} (rad/s)")
    bottom.set_ylim(-180, 180)
    bottom.grid(alpha=0.3)
    growing = sum(1 for _, g in resonances if g > 0)
    top.set_title((args.title or os.path.basename(args.csv)) +
                  f": {len(resonances)} resonances marked" + (f", {growing} growing (red)" if growing else ""))
    fig.tight_layout()
    return plotting.save(fig, args.png, "plot_response")


if __name__ == "__main__":
    sys.exit(main())
