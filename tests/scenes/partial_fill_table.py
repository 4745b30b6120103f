"""A partially filled tank's table as the scene checks read it (h5py), independently of chain-rom: shared by
stewartson_scene_check.py and moving_joint_check.py."""
import os
import re
import subprocess

import h5py


def tank(path):
    """A table's datasets: each mode's lambda_c, a_c and t_c (complex for a viscous table: lambda + i decay,
    a + i a_imag, t + i t_imag), N2, and the tank's integrals K0, K1, K2, volume, A_f, C_f."""
    with h5py.File(path) as h:
        m, fs = h["modes"], h["free_surface"]
        v = "decay" in m
        out = dict(lam=m["lambda"][:] + (1j * m["decay"][:] if v else 0), N2=m["N2"][:],
                   a=m["a"][:] + (1j * m["a_imag"][:] if v else 0), t=fs["t"][:] + (1j * fs["t_imag"][:] if v else 0))
        out.update({k: float(fs.attrs[k][()]) for k in ("K0", "K1", "K2")})
        out.update({k: float(h.attrs[k][()]) for k in ("volume", "A_f", "C_f")})
    return out


def table_from_recipe(modes_bin, scene, work):
    """Makes the scene's table from its '# recipe: NAME: ARGS' line into `work`: returns the scene's text, the recipe's
    cavity-modes arguments and the table's path."""
    os.makedirs(work, exist_ok=True)
    text = open(scene).read()
    name, args = re.search(r"^# recipe: ([^:]+): (.*)$", text, re.M).groups()
    table = os.path.join(work, name)
    subprocess.run([modes_bin] + args.split() + ["-o", table], check=True, stdout=subprocess.DEVNULL)
    return text, args, table


def value(text, key):
    """The number a scene's line 'key = number' holds (the first such line)."""
    return float(re.search(rf"^{key} = ([-0-9.e]+)", text, re.M).group(1))
