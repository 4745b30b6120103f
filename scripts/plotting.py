"""What chain-rom's plot scripts share: their command line, Debian's matplotlib, and a PNG written atomically."""
import argparse
import os
import sys


def parse_args(doc, what):
    """CSV -o PNG [--title TEXT]; `what` names the chain-rom command that writes the CSV."""
    ap = argparse.ArgumentParser(description=doc.splitlines()[0])
    ap.add_argument("csv", help=f"CSV written by chain-rom {what}")
    ap.add_argument("-o", "--output", dest="png", required=True, help="PNG to write")
    ap.add_argument("--title", default=None, help="figure title (default: the CSV's file name)")
    return ap.parse_args()


def pyplot(prog):
    """matplotlib.pyplot with the Agg backend and numpy, or None after a one-line error naming the packages."""
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        import numpy as np
    except ImportError as e:
        print(f"{prog}: error: {e} (apt-get install python3-matplotlib python3-numpy)", file=sys.stderr)
        return None, None
    return plt, np


def save(fig, png, prog):
    """Writes the figure under a temporary name and renames it: a PNG is whole or absent. Returns the exit code."""
    tmp = png + f".tmp-{os.getpid()}.png"
    try:
        fig.savefig(tmp)
        os.replace(tmp, png)
    except OSError as e:
        if os.path.exists(tmp):
            os.remove(tmp)
        print(f"{prog}: error: {png}: {e}", file=sys.stderr)
        return 1
    return 0
